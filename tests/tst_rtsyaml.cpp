// SPDX-License-Identifier: MIT
#include "rtsxml.h"
#include "rtsyaml.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTest>

using namespace Profile;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/")) + name;
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

QString joined(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

RtsProfile loadYaml(const QString &name)
{
    Diagnostics diagnostics;
    const auto profile = readRtsYaml(readFile(dataPath(name)), name, &diagnostics);
    if (!profile || !diagnostics.isEmpty())
        qWarning().noquote() << name << joined(diagnostics);
    return profile.value_or(RtsProfile());
}

std::optional<QString> text(const char *value)
{
    return QString::fromUtf8(value);
}

} // namespace

class TestRtsYaml : public QObject
{
    Q_OBJECT

private slots:
    void readsEveryKey();
    void readsMessageSequences();
    void mapsDatesBothWays();
    void keepsUnknownKeys();
    void keepsAliasChainsUnexpanded();
    void roundTrips_data();
    void roundTrips();
    void yamlToXmlKeepsEverything();
    void xmlToYamlKeepsEverything_data();
    void xmlToYamlKeepsEverything();
    void writesRtsprofileDialect();
    void quotesTextThatWouldChangeType_data();
    void quotesTextThatWouldChangeType();
    void rejectsBrokenFiles_data();
    void rejectsBrokenFiles();
};

void TestRtsYaml::readsEveryKey()
{
    const RtsProfile p = loadYaml(QStringLiteral("rts/full.yaml"));
    QCOMPARE(p.id, QStringLiteral("RTSystem:TestVendor:FullSystem:2.1"));
    QCOMPARE(p.version, QStringLiteral("0.2"));
    QCOMPARE(p.abstract, text("Everything the schema has"));
    QCOMPARE(p.comment, text("System comment"));
    QCOMPARE(p.components.size(), 3);

    const RtsComponent &camera = p.components.at(0);
    QCOMPARE(camera.instanceName, QStringLiteral("Camera0"));
    QCOMPARE(camera.isRequired, QStringLiteral("true"));
    QCOMPARE(camera.visible, text("true"));
    QCOMPARE(camera.comment, text("The camera"));
    QCOMPARE(camera.activeConfigurationSet, text("default"));
    QCOMPARE(camera.dataPorts.at(0).comment, text("images out"));
    QCOMPARE(camera.dataPorts.at(0).properties.at(0).value, text("DataOutPort"));
    QCOMPARE(camera.dataPorts.at(1).visible, text("false"));
    QCOMPARE(camera.servicePorts.at(0).name, QStringLiteral("Camera0.control"));
    QCOMPARE(camera.configurationSets.at(0).data.at(0).data, text("640"));
    QCOMPARE(camera.configurationSets.at(0).data.at(1).data, std::nullopt);
    QCOMPARE(camera.executionContexts.at(0).id, QStringLiteral("0"));
    QCOMPARE(camera.executionContexts.at(0).rate, text("30.0"));
    QCOMPARE(camera.executionContexts.at(0).participants.at(0).properties.at(0).value,
             text("attached"));
    QCOMPARE(camera.executionContexts.at(0).properties.at(0).value, text("YES"));
    QCOMPARE(camera.executionContexts.at(1).rate, std::nullopt);
    QVERIFY(camera.layout);
    QCOMPARE(camera.layout->direction, QStringLiteral("RIGHT"));
    QCOMPARE(camera.layout->height, QStringLiteral("-1"));
    QCOMPARE(camera.layout->x, QStringLiteral("10"));
    QCOMPARE(camera.properties.at(1).value, std::nullopt);

    QCOMPARE(p.components.at(1).isRequired, QStringLiteral("true"));
    QCOMPARE(p.components.at(1).layout, std::nullopt);
    const RtsComponent &pipeline = p.components.at(2);
    QCOMPARE(pipeline.isRequired, QStringLiteral("false"));
    QCOMPARE(pipeline.participants.size(), 2);
    QCOMPARE(pipeline.participants.at(1).participant.properties.at(0).value, text("2"));

    QCOMPARE(p.groups.at(0).groupId, QStringLiteral("sensors"));
    QCOMPARE(p.groups.at(0).members.size(), 1);
    const RtsDataPortConnector &image = p.dataPortConnectors.at(0);
    QCOMPARE(image.pushInterval, text("15.0"));
    QCOMPARE(image.subscriptionType, text("periodic"));
    QCOMPARE(image.properties.at(0).value, text("{1:(150,30)}"));
    QCOMPARE(image.target.properties.at(0).name, QStringLiteral("COMPONENT_PATH_ID"));
    QCOMPARE(p.servicePortConnectors.at(0).transMethod, text("corba"));
    QCOMPARE(p.servicePortConnectors.at(0).visible, text("false"));
    QCOMPARE(p.versionUpLogs,
             (QStringList {QStringLiteral("2024-01-02 created"), QStringLiteral("2.0")}));
    QCOMPARE(p.properties.at(0).value, text("lab"));
    QCOMPARE(p.systems.at(0).path, QStringLiteral("sub/Arm.xml"));
    QCOMPARE(p.components.at(0).location.line, 8);
}

void TestRtsYaml::readsMessageSequences()
{
    const RtsProfile p = loadYaml(QStringLiteral("rts/full.yaml"));
    QVERIFY(p.startUp);
    QCOMPARE(p.startUp->targets.size(), 2);
    QCOMPARE(p.startUp->targets.at(0).waitTime->waitTime, text("100"));
    QCOMPARE(p.startUp->targets.at(0).properties.at(0).value, text("first"));
    const RtsPreceding &preceding = *p.startUp->targets.at(1).preceding;
    QCOMPARE(preceding.timeout, text("500"));
    QCOMPARE(preceding.sendingTiming, text("SYNC"));
    QCOMPARE(preceding.precedingComponents.at(0).id, QStringLiteral("0"));
    QCOMPARE(p.shutDown->targets.at(0).targetComponent.id, QStringLiteral("CameraEc1"));
    QCOMPARE(p.shutDown->targets.at(0).preceding->timeout, std::nullopt);
    QCOMPARE(p.activation->targets.at(0).waitTime->waitTime, text("0"));
    QVERIFY(!p.deactivation->targets.at(0).waitTime && !p.deactivation->targets.at(0).preceding);
    QCOMPARE(p.resetting->targets.at(0).waitTime->waitTime, std::nullopt);
    QVERIFY(p.initializing && p.initializing->targets.isEmpty());
    QVERIFY(p.finalizing && p.finalizing->targets.isEmpty());
}

void TestRtsYaml::mapsDatesBothWays()
{
    const RtsProfile p = loadYaml(QStringLiteral("rts/full.yaml"));
    QCOMPARE(p.creationDate, QStringLiteral("2024-01-02T03:04:05.678+09:00"));
    QCOMPARE(p.updateDate, QStringLiteral("2024-02-03T04:05:06"));

    RtsProfile odd = p;
    odd.updateDate = QStringLiteral("last Tuesday"); // kept as text, never lost
    const QByteArray yaml = writeRtsYaml(odd);
    QVERIFY(yaml.contains("updateDate: last Tuesday"));
    QVERIFY(yaml.contains("fraction: '678'"));
    QVERIFY(yaml.contains("timeZone: '+09:00'"));
    Diagnostics diagnostics;
    const auto again = readRtsYaml(yaml, QStringLiteral("odd.yaml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QCOMPARE(again->updateDate, odd.updateDate);
    QCOMPARE(again->creationDate, p.creationDate);
}

void TestRtsYaml::keepsAliasChainsUnexpanded()
{
    // Ten levels of nine aliases each below an unknown key: expanded, a billion scalars. Kept as
    // written, the saved file stays the size of the original and reads back the same.
    const QByteArray original = readFile(dataPath(QStringLiteral("rts/alias-chain.yaml")));
    const RtsProfile p = loadYaml(QStringLiteral("rts/alias-chain.yaml"));
    QCOMPARE(p.yamlExtras.entries.size(), 1);
    QCOMPARE(p.yamlExtras.entries.at(0).key, QStringLiteral("unknownBomb"));
    const QByteArray saved = writeRtsYaml(p);
    QVERIFY2(saved.size() < 4 * original.size(), qPrintable(QString::number(saved.size())));
    Diagnostics diagnostics;
    const auto again = readRtsYaml(saved, QStringLiteral("saved.yaml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY(*again == p);
}

void TestRtsYaml::keepsUnknownKeys()
{
    const RtsProfile p = loadYaml(QStringLiteral("rts/unknown-keys.yaml"));
    QCOMPARE(p.yamlExtras.entries.size(), 1);
    QCOMPARE(p.yamlExtras.entries.at(0).key, QStringLiteral("futureRoot"));
    QCOMPARE(p.components.at(0).yamlExtras.entries.at(0).key, QStringLiteral("futureComponent"));
    QCOMPARE(p.components.at(0).yamlExtras.entries.at(0).yaml, QStringLiteral("42"));
    QCOMPARE(p.components.at(0).dataPorts.at(0).yamlExtras.entries.size(), 1);
    QCOMPARE(p.components.at(0).layout->yamlExtras.entries.size(), 1);
    QCOMPARE(p.components.at(0).properties.at(0).yamlExtras.entries.size(), 1);
    QCOMPARE(p.dataPortConnectors.at(0).yamlExtras.entries.size(), 1);
    QCOMPARE(p.dataPortConnectors.at(0).source.yamlExtras.entries.size(), 1);
    QCOMPARE(p.activation->yamlExtras.entries.size(), 1);
    const RtsCondition &condition = p.activation->targets.at(0);
    QCOMPARE(condition.yamlExtras.entries.size(), 2);
    QCOMPARE(condition.yamlExtras.entries.at(0).key, QStringLiteral("condition/futureCondition"));
    QCOMPARE(condition.waitTime->yamlExtras.entries.size(), 1);

    const QByteArray saved = writeRtsYaml(p);
    Diagnostics diagnostics;
    const auto again = readRtsYaml(saved, QStringLiteral("saved.yaml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY2(*again == p, saved.constData());
    QVERIFY(saved.contains("futureCondition: c"));
    QVERIFY(saved.contains("deeper: true"));
    QVERIFY(!saved.contains("condition/"));
}

void TestRtsYaml::roundTrips_data()
{
    QTest::addColumn<QString>("name");
    const QDir dir(dataPath(QStringLiteral("rts")));
    for (const QString &file : dir.entryList({QStringLiteral("*.yaml")}, QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(file)) << QStringLiteral("rts/") + file;
}

void TestRtsYaml::roundTrips()
{
    QFETCH(QString, name);
    Diagnostics diagnostics;
    const auto profile = readRtsYaml(readFile(dataPath(name)), name, &diagnostics);
    QVERIFY2(profile && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    const QByteArray saved = writeRtsYaml(*profile);
    const auto again = readRtsYaml(saved, QStringLiteral("saved.yaml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY2(*again == *profile, saved.constData());
    QCOMPARE(writeRtsYaml(*again), saved);
}

void TestRtsYaml::yamlToXmlKeepsEverything()
{
    const RtsProfile p = loadYaml(QStringLiteral("rts/full.yaml"));
    QVERIFY(!p.components.isEmpty());
    const QByteArray xml = writeRtsXml(p);
    Diagnostics diagnostics;
    const auto fromXml = readRtsXml(xml, QStringLiteral("converted.xml"), &diagnostics);
    QVERIFY2(fromXml && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY2(*fromXml == p, xml.constData());
}

void TestRtsYaml::xmlToYamlKeepsEverything_data()
{
    QTest::addColumn<QString>("name");
    // full.xml carries unknown XML content, which only the XML form can hold.
    QTest::newRow("legacy") << "rts/legacy.xml";
    QTest::newRow("minimal") << "rts/minimal.xml";
}

void TestRtsYaml::xmlToYamlKeepsEverything()
{
    QFETCH(QString, name);
    Diagnostics diagnostics;
    const auto fromXml = readRtsXml(readFile(dataPath(name)), name, &diagnostics);
    QVERIFY2(fromXml && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    const QByteArray yaml = writeRtsYaml(*fromXml);
    const auto fromYaml = readRtsYaml(yaml, QStringLiteral("converted.yaml"), &diagnostics);
    QVERIFY2(fromYaml && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY2(*fromYaml == *fromXml, yaml.constData());
}

void TestRtsYaml::writesRtsprofileDialect()
{
    const QByteArray yaml = writeRtsYaml(loadYaml(QStringLiteral("rts/full.yaml")));
    QVERIFY(yaml.startsWith("rtsProfile:\n"));
    for (const char *expected : {"version: '0.2'",
                                 "\"rtsExt::location\":",
                                 "\"rtsExt::visible\": 'true'",
                                 "isRequired: 'true'",
                                 "\"rtsExt::properties\":",
                                 "\"rtsExt::versionUpLogs\":",
                                 "\"rtsExt::systems\":",
                                 "dataPortConnectors:",
                                 "servicePortConnectors:",
                                 "startUp:",
                                 "shutDown:",
                                 "activation:",
                                 "deactivation:",
                                 "resetting:",
                                 "initializing:",
                                 "finalizing:",
                                 "precedingComponents:",
                                 "sendingTiming: SYNC",
                                 "rate: 30.0",
                                 "year: 2024",
                                 "id: '0'"}) {
        QVERIFY2(yaml.contains(expected), expected);
    }
    // Every target has a condition mapping: rtsprofile looks it up unconditionally.
    QCOMPARE(yaml.count("condition:"), yaml.count("targetComponent:"));
    QVERIFY(!yaml.contains("groupID"));
}

void TestRtsYaml::quotesTextThatWouldChangeType_data()
{
    QTest::addColumn<QString>("value");
    for (const char *value :
         {"yes", "No", "true", "OFF", "null", "~", "", "0.2", "12", "-3.5e2", "0x1F", ".inf",
          "a: b", "#hash", " padded ", "line\nbreak", "日本語"}) {
        const QByteArray name = "'" + QByteArray(value).replace('\n', "\\n") + "'";
        QTest::newRow(name.constData()) << QString::fromUtf8(value);
    }
}

void TestRtsYaml::quotesTextThatWouldChangeType()
{
    QFETCH(QString, value);
    RtsProfile p
        = RtsProfile::createNew(QStringLiteral("V"), QStringLiteral("N"), QStringLiteral("1"));
    p.comment = value;
    p.abstract = value;
    p.versionUpLogs << value;
    const QByteArray yaml = writeRtsYaml(p);
    const QByteArray line = yaml.mid(yaml.indexOf("abstract:"));
    const QByteArray first = line.left(line.indexOf('\n'));
    static const QRegularExpression plainSpecial(
        QStringLiteral(R"(^abstract: (yes|No|true|OFF|null|~|0\.2|12|-3\.5e2|0x1F|\.inf)?$)"));
    QVERIFY2(!plainSpecial.match(QString::fromUtf8(first)).hasMatch(), first.constData());
    Diagnostics diagnostics;
    const auto again = readRtsYaml(yaml, QStringLiteral("q.yaml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QCOMPARE(again->abstract, std::optional<QString>(value));
    QCOMPARE(again->comment, std::optional<QString>(value));
    QCOMPARE(again->versionUpLogs, QStringList {value});
}

void TestRtsYaml::rejectsBrokenFiles_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("understood"); // true: a profile with errors; false: nothing
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("fragment");
    QTest::newRow("malformed") << "malformed.yaml" << false << 6 << QString();
    QTest::newRow("list expected")
        << "type-error-list.yaml" << true << 6 << "'components' must be a list";
    QTest::newRow("value expected")
        << "type-error-scalar.yaml" << true << 10 << "'instanceName' must be a single value";
    QTest::newRow("bad date") << "type-error-date.yaml" << true << 6 << "creationDate.year";
    QTest::newRow("not a system") << "not-rts.yaml" << false << 1 << "rtsProfile";
    QTest::newRow("invalid utf-8") << "invalid-utf8.yaml" << false << 4 << "UTF-8";
    QTest::newRow("deep nesting") << "deep-nesting.yaml" << false << 3 << QString();
}

void TestRtsYaml::rejectsBrokenFiles()
{
    QFETCH(QString, name);
    QFETCH(bool, understood);
    QFETCH(int, line);
    QFETCH(QString, fragment);
    const QByteArray data = readFile(dataPath(QStringLiteral("rts-broken/") + name));
    QVERIFY(!data.isEmpty());
    Diagnostics diagnostics;
    const auto profile = readRtsYaml(data, name, &diagnostics);
    QCOMPARE(bool(profile), understood);
    QVERIFY(hasErrors(diagnostics));
    const Diagnostic &first = diagnostics.first();
    QCOMPARE(first.severity, Diagnostic::Severity::Error);
    QCOMPARE(first.file, name);
    QVERIFY2(first.line == line && first.column > 0, qPrintable(first.toString()));
    QVERIFY2(first.message.contains(fragment), qPrintable(first.toString()));
}

QTEST_GUILESS_MAIN(TestRtsYaml)
#include "tst_rtsyaml.moc"
