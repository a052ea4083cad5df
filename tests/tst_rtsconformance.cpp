// SPDX-License-Identifier: MIT
// Runs every RTS Profile of the shared conformance folder (files made by OpenRTP and rtsprofile)
// through load → save → load, in XML and YAML, and compares the saved XML with the original.
#include "rtsxml.h"
#include "rtsyaml.h"
#include "xmlequivalence.h"

#include <QDir>
#include <QFile>
#include <QTest>

using namespace Profile;

namespace {

QString conformanceDir()
{
    return RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/rts");
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

/// Only the quirks documented in formats.md are forgiven.
XmlNormalization rtsQuirks()
{
    const QString rts = QStringLiteral("http://www.openrtp.org/namespaces/rts");
    const QString ext = QStringLiteral("http://www.openrtp.org/namespaces/rts_ext");
    XmlNormalization n;
    n.elementRenames.insert(XmlNormalization::key(ext, QStringLiteral("VersionUpLog")),
                            XmlNormalization::key(ext, QStringLiteral("VersionUpLogs")));
    n.attributeRenames.insert(XmlNormalization::key(rts, QStringLiteral("groupID")),
                              XmlNormalization::key(rts, QStringLiteral("groupId")));
    n.valueNormalizers.insert(XmlNormalization::key(ext, QStringLiteral("direction")),
                              &XmlNormalization::upperCase);
    n.valueNormalizers.insert(XmlNormalization::key(rts, QStringLiteral("isRequired")),
                              &XmlNormalization::boolean);
    return n;
}

} // namespace

class TestRtsConformance : public QObject
{
    Q_OBJECT

private slots:
    void xmlFiles_data();
    void xmlFiles();
    void yamlFiles_data();
    void yamlFiles();

private:
    void addFiles(const QString &pattern);
};

void TestRtsConformance::addFiles(const QString &pattern)
{
    QTest::addColumn<QString>("path");
    const QDir dir(conformanceDir());
    if (!dir.exists()) {
        QTest::newRow("no conformance folder") << QString(); // so that the test can say why
        return;
    }
    for (const QString &name : dir.entryList({pattern}, QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(name)) << dir.filePath(name);
}

void TestRtsConformance::xmlFiles_data()
{
    addFiles(QStringLiteral("*.xml"));
}

void TestRtsConformance::xmlFiles()
{
    if (!QDir(conformanceDir()).exists())
        QSKIP("the shared conformance folder is not beside the project");
    QFETCH(QString, path);
    const QByteArray input = readFile(path);
    QVERIFY2(!input.isEmpty(), qPrintable(path));

    Diagnostics diagnostics;
    const auto profile = readRtsXml(input, path, &diagnostics);
    QVERIFY2(profile, qPrintable(errorsOf(diagnostics)));
    QVERIFY2(!hasErrors(diagnostics), qPrintable(errorsOf(diagnostics)));
    QVERIFY(!profile->id.isEmpty());

    const QByteArray saved = writeRtsXml(*profile);
    Diagnostics again;
    const auto reloaded = readRtsXml(saved, QStringLiteral("saved.xml"), &again);
    QVERIFY2(reloaded, qPrintable(errorsOf(again)));
    QVERIFY2(again.isEmpty(), qPrintable(again.value(0).toString()));
    QVERIFY2(*reloaded == *profile, saved.constData());

    const auto original = parseXml(input, path, nullptr);
    const auto written = parseXml(saved, QStringLiteral("saved.xml"), nullptr);
    QVERIFY(original && written);
    const QString difference = xmlDifference(*original, *written, rtsQuirks());
    QVERIFY2(difference.isEmpty(), qPrintable(difference));

    // Nothing these files hold is XML-only, so the YAML form carries all of it.
    const auto viaYaml = readRtsYaml(writeRtsYaml(*profile), QStringLiteral("saved.yaml"), &again);
    QVERIFY2(viaYaml, qPrintable(errorsOf(again)));
    QVERIFY(*viaYaml == *profile);
}

void TestRtsConformance::yamlFiles_data()
{
    addFiles(QStringLiteral("*.yaml"));
}

void TestRtsConformance::yamlFiles()
{
    if (!QDir(conformanceDir()).exists())
        QSKIP("the shared conformance folder is not beside the project");
    QFETCH(QString, path);
    Diagnostics diagnostics;
    const auto profile = readRtsYaml(readFile(path), path, &diagnostics);
    QVERIFY2(profile, qPrintable(errorsOf(diagnostics)));
    QVERIFY2(diagnostics.isEmpty(), qPrintable(diagnostics.value(0).toString()));
    QVERIFY(!profile->components.isEmpty());

    const QByteArray savedYaml = writeRtsYaml(*profile);
    Diagnostics again;
    const auto fromYaml = readRtsYaml(savedYaml, QStringLiteral("saved.yaml"), &again);
    QVERIFY2(fromYaml, qPrintable(errorsOf(again)));
    QVERIFY2(again.isEmpty(), qPrintable(again.value(0).toString()));
    QVERIFY2(*fromYaml == *profile, savedYaml.constData());

    const QByteArray savedXml = writeRtsXml(*profile);
    const auto fromXml = readRtsXml(savedXml, QStringLiteral("saved.xml"), &again);
    QVERIFY2(fromXml, qPrintable(errorsOf(again)));
    QVERIFY2(again.isEmpty(), qPrintable(again.value(0).toString()));
    QVERIFY2(*fromXml == *profile, savedXml.constData());
}

QTEST_GUILESS_MAIN(TestRtsConformance)
#include "tst_rtsconformance.moc"
