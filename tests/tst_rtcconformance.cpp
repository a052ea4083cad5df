// SPDX-License-Identifier: MIT
// Runs every RTC Profile of the shared conformance folder (files made by OpenRTP's RTC Builder,
// its toolscommon tests and OpenRTM-aist's templates) through load → save → load, in XML and
// YAML, and compares the saved XML with the original document.
#include "constraintsyntax.h"
#include "namespaces.h"
#include "rtcxml.h"
#include "rtcyaml.h"
#include "xmlequivalence.h"

#include <QDir>
#include <QFile>
#include <QSet>
#include <QTest>

using namespace Profile;

namespace {

QString conformanceDir(const QString &sub)
{
    return (RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/")) + sub;
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

QString errorsOf(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics) {
        if (d.severity == Diagnostic::Severity::Error)
            lines << d.toString();
    }
    return lines.join(QLatin1Char('\n'));
}

/// Every element and attribute name the RTC Profile schemas (0.3 and 0.2) declare.
QSet<QString> schemaNames()
{
    QSet<QString> names;
    const QDir dir(conformanceDir(QStringLiteral("xsd")));
    for (const QString &file : dir.entryList({QStringLiteral("*RtcProfile_*.xsd")})) {
        const auto schema = parseXml(readFile(dir.filePath(file)), file, nullptr);
        if (!schema)
            continue;
        std::vector<const XmlNode *> stack {&*schema};
        while (!stack.empty()) {
            const XmlNode *node = stack.back();
            stack.pop_back();
            if (node->name == QLatin1String("element") || node->name == QLatin1String("attribute"))
                names.insert(node->attribute(QString(), QStringLiteral("name"))
                                 ? node->attribute(QString(), QStringLiteral("name"))->value
                                 : QString());
            for (const XmlNode &child : node->children)
                stack.push_back(&child);
        }
    }
    return names;
}

/// Names in `node` (recursively) that no schema declares: content the reader did not map.
QStringList unmappedNames(const XmlNode &node, const QSet<QString> &known)
{
    QStringList result;
    if (!known.contains(node.name))
        result << node.name;
    for (const XmlAttribute &a : node.attributes) {
        if (!known.contains(a.name))
            result << a.name;
    }
    for (const XmlNode &child : node.children)
        result << unmappedNames(child, known);
    return result;
}

/// Only the legacy spellings listed in formats.md (and found in the files) are forgiven.
XmlNormalization rtcQuirks()
{
    const auto rtc = [](const char *name) { return XmlNormalization::key(Ns::Rtc, name); };
    const auto ext = [](const char *name) { return XmlNormalization::key(Ns::RtcExt, name); };
    XmlNormalization n;
    n.elementRenames.insert(ext("VersionUpLog"), ext("VersionUpLogs"));
    n.attributeRenames.insert(rtc("varname"), ext("variableName"));
    n.attributeRenames.insert(ext("varname"), ext("variableName"));
    n.attributeRenames.insert(rtc("subscriprionType"), rtc("subscriptionType"));
    n.valueNormalizers.insert(ext("position"), &XmlNormalization::upperCase);
    n.valueNormalizers.insert(rtc("implemented"), &XmlNormalization::boolean);
    n.valueNormalizers.insert(rtc("matchCase"), &XmlNormalization::boolean);
    return n;
}

/// Saving writes the current format version; the source is compared as if it said so too.
void expectCurrentVersion(XmlNode &root)
{
    root.setAttribute(Ns::Rtc, QStringLiteral("version"), RtcProfile::CurrentVersion);
}

/// Reads the saved text back; the format version is the current one and is then set back
/// to the first read's, so that the rest can be compared as a whole.
std::optional<RtcProfile> reload(const std::optional<RtcProfile> &profile, const QString &version)
{
    if (profile && profile->version != RtcProfile::CurrentVersion)
        return std::nullopt;
    std::optional<RtcProfile> result = profile;
    if (result)
        result->version = version;
    return result;
}

/// The constraint trees of a profile: configurations first, then data ports.
std::vector<RtcConstraint> constraintsOf(const RtcProfile &profile)
{
    std::vector<RtcConstraint> result;
    for (const RtcConfiguration &c : profile.configurations) {
        if (c.constraint)
            result.push_back(*c.constraint);
    }
    for (const RtcDataPort &p : profile.dataPorts) {
        if (p.constraint)
            result.push_back(*p.constraint);
    }
    return result;
}

} // namespace

class TestRtcConformance : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void xmlFiles_data();
    void xmlFiles();
    void yamlFiles_data();
    void yamlFiles();
    void constraintStrings_data();
    void constraintStrings();

private:
    void addFiles(const QString &sub, const QString &pattern);
};

void TestRtcConformance::initTestCase()
{
    if (!QDir(conformanceDir(QStringLiteral("rtc"))).exists())
        QSKIP("the conformance folder (shared/conformance beside the project) is absent");
    QVERIFY(!QDir(conformanceDir(QStringLiteral("rtc"))).entryList({"*.xml"}).isEmpty());
    QVERIFY(!QDir(conformanceDir(QStringLiteral("rtc-yaml"))).entryList({"*.yaml"}).isEmpty());
}

void TestRtcConformance::addFiles(const QString &sub, const QString &pattern)
{
    QTest::addColumn<QString>("path");
    const QDir dir(conformanceDir(sub));
    for (const QString &name : dir.entryList({pattern}, QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(name)) << dir.filePath(name);
}

void TestRtcConformance::xmlFiles_data()
{
    addFiles(QStringLiteral("rtc"), QStringLiteral("*.xml"));
}

void TestRtcConformance::xmlFiles()
{
    QFETCH(QString, path);
    const QByteArray input = readFile(path);
    QVERIFY(!input.isEmpty());

    Diagnostics diagnostics;
    const auto first = readRtcXml(input, path, &diagnostics);
    QVERIFY2(first && !hasErrors(diagnostics), qPrintable(errorsOf(diagnostics)));

    const QByteArray saved = writeRtcXml(*first);
    Diagnostics again;
    const auto second
        = reload(readRtcXml(saved, QStringLiteral("saved.xml"), &again), first->version);
    QVERIFY2(second, qPrintable(errorsOf(again) + QLatin1Char('\n') + saved));
    QVERIFY2(*second == *first, qPrintable(QString::fromUtf8(saved)));

    auto original = parseXml(input, path, nullptr);
    const auto written = parseXml(saved, QStringLiteral("saved.xml"), nullptr);
    QVERIFY(original && written);
    expectCurrentVersion(*original);
    const QString difference = xmlDifference(*original, *written, rtcQuirks());
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
}

void TestRtcConformance::yamlFiles_data()
{
    addFiles(QStringLiteral("rtc-yaml"), QStringLiteral("*.yaml"));
}

void TestRtcConformance::yamlFiles()
{
    QFETCH(QString, path);
    Diagnostics diagnostics;
    const auto first = readRtcYaml(readFile(path), path, &diagnostics);
    QVERIFY2(first && !hasErrors(diagnostics), qPrintable(errorsOf(diagnostics)));
    QVERIFY(!first->basicInfo.name.isEmpty()
            || first->missing.contains(QStringLiteral("BasicInfo")));

    const QByteArray yaml = writeRtcYaml(*first);
    Diagnostics yamlDiagnostics;
    const auto fromYaml
        = reload(readRtcYaml(yaml, QStringLiteral("saved.yaml"), &yamlDiagnostics), first->version);
    QVERIFY2(fromYaml, qPrintable(errorsOf(yamlDiagnostics) + QLatin1Char('\n') + yaml));
    QVERIFY2(*fromYaml == *first, yaml.constData());

    const QByteArray xml = writeRtcXml(*first);
    Diagnostics xmlDiagnostics;
    const auto fromXml
        = reload(readRtcXml(xml, QStringLiteral("saved.xml"), &xmlDiagnostics), first->version);
    QVERIFY2(fromXml, qPrintable(errorsOf(xmlDiagnostics) + QLatin1Char('\n') + xml));
    QVERIFY2(*fromXml == *first, xml.constData());

    // Every key of RTC Builder's dialect is understood; only the old per-language element of
    // the EMF sample (`java: library: …`) has no place in the schema and rides along as extras.
    const QSet<QString> known = schemaNames();
    QVERIFY(known.contains(QStringLiteral("occerrence")));
    QStringList unmapped = unmappedNames(rtcProfileToXml(*first), known);
    unmapped.removeAll(QStringLiteral("java"));
    unmapped.removeAll(QStringLiteral("library"));
    QVERIFY2(unmapped.isEmpty(), qPrintable(unmapped.join(QLatin1String(", "))));
}

void TestRtcConformance::constraintStrings_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("index");
    const QDir dir(conformanceDir(QStringLiteral("rtc")));
    for (const QString &name : dir.entryList({QStringLiteral("*.xml")}, QDir::Files, QDir::Name)) {
        const auto profile = readRtcXml(readFile(dir.filePath(name)), name, nullptr);
        if (!profile)
            continue;
        const std::size_t count = constraintsOf(*profile).size();
        for (std::size_t i = 0; i < count; ++i) {
            QTest::newRow(qPrintable(QStringLiteral("%1 #%2").arg(name).arg(i)))
                << dir.filePath(name) << int(i);
        }
    }
}

void TestRtcConformance::constraintStrings()
{
    QFETCH(QString, path);
    QFETCH(int, index);
    const auto profile = readRtcXml(readFile(path), path, nullptr);
    QVERIFY(profile);
    const std::vector<RtcConstraint> constraints = constraintsOf(*profile);
    QVERIFY(index < int(constraints.size()));
    const RtcConstraint &tree = constraints[std::size_t(index)];
    const QString text = constraintToString(tree);
    QVERIFY(!text.isEmpty());
    const ConstraintParseResult parsed = parseConstraintString(text);
    QVERIFY2(parsed.ok(), qPrintable(text + QLatin1String(": ") + parsed.error->toString()));
    QVERIFY2(parsed.constraint == tree, qPrintable(text));
}

QTEST_GUILESS_MAIN(TestRtcConformance)
#include "tst_rtcconformance.moc"
