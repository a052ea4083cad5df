// SPDX-License-Identifier: MIT
// RTC Builder's YAML dialect: keys, legacy keys, dates, unknown keys through YAML and XML saves,
// broken files.
#include "namespaces.h"
#include "rtcxml.h"
#include "rtcyaml.h"
#include "xmlequivalence.h"

#include <QFile>
#include <QTest>

using namespace Profile;

namespace {

QByteArray readData(const QString &name)
{
    QFile file((RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/")) + name);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot open test data %s", qPrintable(name));
    return file.readAll();
}

QString messagesOf(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

RtcProfile loadYaml(const QByteArray &data, const QString &name = QStringLiteral("t.yaml"))
{
    Diagnostics diagnostics;
    const auto profile = readRtcYaml(data, name, &diagnostics);
    if (!profile || hasErrors(diagnostics))
        qFatal("cannot load %s: %s", qPrintable(name), qPrintable(messagesOf(diagnostics)));
    return *profile;
}

RtcProfile loadFullYaml()
{
    return loadYaml(readData(QStringLiteral("rtc/full.yaml")), QStringLiteral("full.yaml"));
}

/// A profile whose only date is `date`, written as YAML.
QByteArray yamlWithDate(const QString &date)
{
    RtcProfile p = RtcProfile::createDefault();
    p.basicInfo.creationDate = date;
    return writeRtcYaml(p);
}

} // namespace

class TestRtcYaml : public QObject
{
    Q_OBJECT

private slots:
    void readsDialectKeys();
    void readsLegacyKeys();
    void readsDates();
    void writesDates_data();
    void writesDates();
    void keepsUnknownKeysThroughYaml();
    void keepsUnknownKeysThroughXml();
    void writesDialect();
    void xmlThroughYamlKeepsEverything();
    void writesDefaultProfile();
    void warnsAboutMissingAndForeignKeys();
    void reportsBrokenFiles_data();
    void reportsBrokenFiles();
    void rejectsDeepNesting_data();
    void rejectsDeepNesting();
};

void TestRtcYaml::readsDialectKeys()
{
    const RtcProfile p = loadFullYaml();
    QCOMPARE(p.id, QStringLiteral("RTC:Acme:Sensor:Yaml:1.0.0"));
    QCOMPARE(p.basicInfo.name, QStringLiteral("Yaml"));
    QCOMPARE(p.basicInfo.executionRate, QStringLiteral("1000.0"));
    QCOMPARE(p.basicInfo.maxInstances, QStringLiteral("1"));
    QCOMPARE(p.basicInfo.doc->description, QStringLiteral("basic doc"));
    QCOMPARE(p.basicInfo.versionUpLogs,
             QStringList({QStringLiteral("first"), QStringLiteral("second")}));
    QVERIFY(p.actions.isImplemented(RtcAction::OnInitialize));
    QVERIFY(p.actions.isImplemented(RtcAction::OnExecute));
    QCOMPARE(p.actions[RtcAction::OnExecute]->doc->description, QStringLiteral("exec"));
    // An action key without a value is listed with implemented false (EMF leaves out defaults).
    QVERIFY(p.actions[RtcAction::OnFinalize]);
    QCOMPARE(p.actions[RtcAction::OnFinalize]->implemented, QStringLiteral("false"));
    QVERIFY(!p.actions[RtcAction::OnStartup]);

    const RtcConfiguration &gain = p.configurations.at(0);
    QCOMPARE(gain.variableName, QStringLiteral("gainVar"));
    QCOMPARE(gain.widget(), QStringLiteral("slider.0.1"));
    QCOMPARE(gain.constraint->op, RtcConstraintOperator::Between);
    QCOMPARE(gain.constraint->upperBoundary, QStringLiteral("1"));

    const RtcDataPort &ev = p.dataPorts.at(1);
    QCOMPARE(ev.kind(), RtcPortType::Event);
    QCOMPARE(ev.position, QStringLiteral("TOP"));
    QCOMPARE(ev.events.size(), 1);
    QCOMPARE(ev.events.at(0).target, QStringLiteral("Busy"));

    const RtcServicePort &svc = p.servicePorts.at(0);
    QCOMPARE(svc.position, QStringLiteral("RIGHT"));
    QCOMPARE(svc.interfaces.at(0).kind(), RtcDirection::Required);
    QCOMPARE(svc.interfaces.at(0).path, QStringLiteral("idl"));
    QCOMPARE(svc.transMethods.at(0).kind, QStringLiteral("CORBA"));

    QCOMPARE(p.language->kind, QStringLiteral("Python"));
    QCOMPARE(p.language->targets.at(0).cpus, QStringList {QStringLiteral("x86_64")});
    QCOMPARE(p.language->targets.at(0).libraries.at(0).version, QStringLiteral("1.26"));
}

void TestRtcYaml::readsLegacyKeys()
{
    const RtcProfile p = loadFullYaml();
    const RtcDataPort &in = p.dataPorts.at(0);
    QCOMPARE(in.position, QStringLiteral("LEFT"));
    QCOMPARE(in.variableName, QStringLiteral("inVar"));
    QCOMPARE(in.subscriptionType, QStringLiteral("flush"));
    QVERIFY(in.doc);
    QCOMPARE(in.doc->description, QStringLiteral("in doc"));
    QCOMPARE(in.doc->occerrence, QStringLiteral("often"));
    QVERIFY(in.missing.isEmpty());
}

void TestRtcYaml::readsDates()
{
    const RtcProfile p = loadFullYaml();
    QCOMPARE(p.basicInfo.creationDate, QStringLiteral("2020-01-02T03:04:05.250-05:00"));
    QCOMPARE(p.basicInfo.updateDate, QStringLiteral("2021-06-07T08:09:10"));
}

void TestRtcYaml::writesDates_data()
{
    QTest::addColumn<QString>("date");
    QTest::addColumn<bool>("asMapping");
    QTest::newRow("plain") << "2008-04-18T14:00:00" << true;
    QTest::newRow("milliseconds and zone") << "2019-05-27T15:40:44.000+09:00" << true;
    QTest::newRow("negative zone") << "2019-05-27T15:40:44-03:30" << true;
    QTest::newRow("UTC as Z") << "2019-05-27T15:40:44Z" << false;
    QTest::newRow("microseconds") << "2019-05-27T15:40:44.123456" << true;
    QTest::newRow("not a date") << "yesterday" << false;
}

void TestRtcYaml::writesDates()
{
    QFETCH(QString, date);
    QFETCH(bool, asMapping);
    const QByteArray yaml = yamlWithDate(date);
    QCOMPARE(yaml.contains("year: "), asMapping);
    const RtcProfile back = loadYaml(yaml);
    QCOMPARE(back.basicInfo.creationDate, date);
}

void TestRtcYaml::keepsUnknownKeysThroughYaml()
{
    const RtcProfile first = loadFullYaml();
    QCOMPARE(first.extras.attributes.size(), 1);
    QCOMPARE(first.extras.attributes.at(0).name, QStringLiteral("futureTopKey"));
    QCOMPARE(first.extras.children.size(), std::size_t(1));
    QCOMPARE(first.basicInfo.extras.attributes.at(0).namespaceUri, Ns::RtcExt);
    QCOMPARE(first.basicInfo.doc->extras.attributes.at(0).value, QStringLiteral("kept"));
    QCOMPARE(first.dataPorts.at(0).extras.children.size(), std::size_t(2));

    const QByteArray saved = writeRtcYaml(first);
    for (const char *key :
         {"futureTopKey: top value", "futureTopTree:", "nested: value",
          "\"rtcExt::futureExt\": ext value", "futureDocKey: kept", "futurePortList:"})
        QVERIFY2(saved.contains(key), key);
    const RtcProfile second = loadYaml(saved);
    QVERIFY2(second == first, saved.constData());
    QCOMPARE(writeRtcYaml(second), saved);
}

void TestRtcYaml::keepsUnknownKeysThroughXml()
{
    const RtcProfile first = loadFullYaml();
    const QByteArray xml = writeRtcXml(first);
    QVERIFY(xml.contains("rtc:futureTopKey=\"top value\""));
    QVERIFY(xml.contains("rtcExt:futureExt=\"ext value\""));
    Diagnostics diagnostics;
    auto fromXml = readRtcXml(xml, QStringLiteral("saved.xml"), &diagnostics);
    QVERIFY2(fromXml && !hasErrors(diagnostics), qPrintable(messagesOf(diagnostics)));
    QVERIFY2(*fromXml == first, xml.constData());

    // …and back to YAML, where the keys are where they were.
    const RtcProfile again = loadYaml(writeRtcYaml(*fromXml));
    QVERIFY(again == first);
}

void TestRtcYaml::writesDialect()
{
    Diagnostics diagnostics;
    const auto p = readRtcXml(readData(QStringLiteral("rtc/full.xml")), QStringLiteral("full.xml"),
                              &diagnostics);
    QVERIFY(p);
    const QByteArray yaml = writeRtcYaml(*p);
    QVERIFY(yaml.startsWith("---\nrtcProfile:\n"));
    for (const char *text :
         {"  actions:\n    onAborting:\n", "\"rtcDoc::doc\":", "implemented: true",
          "\"rtcExt::position\": LEFT", "executionRate: 500.5", "maxInstances: 3",
          "defaultValue: \"0.5\"", "occerrence: often", "version: \"0.3\"",
          "type: \"RTC::TimedLong\"", "\"rtcExt::versionUpLogs\":", "\"rtcExt::targets\":"})
        QVERIFY2(yaml.contains(text), text);
    // Keys in RTC Builder's order: sorted by the name after any `rtcExt::` prefix.
    const QByteArray basic = yaml.mid(yaml.indexOf("  basicInfo:"));
    QVERIFY(basic.indexOf("activityType:") < basic.indexOf("category:"));
    QVERIFY(basic.indexOf("category:") < basic.indexOf("\"rtcExt::comment\":"));
    QVERIFY(basic.indexOf("\"rtcExt::comment\":") < basic.indexOf("componentKind:"));
}

void TestRtcYaml::xmlThroughYamlKeepsEverything()
{
    const QByteArray input = readData(QStringLiteral("rtc/full.xml"));
    const auto fromXml = readRtcXml(input, QStringLiteral("full.xml"), nullptr);
    QVERIFY(fromXml);
    const RtcProfile fromYaml = loadYaml(writeRtcYaml(*fromXml));
    const auto original = parseXml(input, QStringLiteral("full.xml"), nullptr);
    const auto final = parseXml(writeRtcXml(fromYaml), QStringLiteral("final.xml"), nullptr);
    QVERIFY(original && final);
    const QString difference = xmlDifference(*original, *final);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
}

void TestRtcYaml::writesDefaultProfile()
{
    const RtcProfile p = RtcProfile::createDefault();
    const RtcProfile back = loadYaml(writeRtcYaml(p));
    QVERIFY(back == p);
}

void TestRtcYaml::warnsAboutMissingAndForeignKeys()
{
    const QByteArray yaml = "---\n"
                            "rtcProfile:\n"
                            "  id: \"RTC:V:C:N:1.0.0\"\n"
                            "  version: \"0.3\"\n"
                            "otherTool:\n"
                            "  setting: 1\n";
    Diagnostics diagnostics;
    const auto profile = readRtcYaml(yaml, QStringLiteral("t.yaml"), &diagnostics);
    QVERIFY(profile);
    QVERIFY(!hasErrors(diagnostics));
    QCOMPARE(profile->missing,
             QStringList({QStringLiteral("BasicInfo"), QStringLiteral("Actions")}));
    QCOMPARE(diagnostics.size(), 3);
    QCOMPARE(diagnostics.at(0).line, 5);
    QVERIFY(diagnostics.at(0).message.contains(QStringLiteral("otherTool")));
    QCOMPARE(diagnostics.at(1).line, 3);
    QVERIFY(diagnostics.at(1).message.contains(QStringLiteral("basicInfo")));
}

void TestRtcYaml::reportsBrokenFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("message");
    QTest::newRow("malformed") << "malformed.yaml" << 5 << "syntax";
    QTest::newRow("bad indentation") << "bad-indentation.yaml" << 5 << "syntax";
    QTest::newRow("list for a mapping") << "type-error-list.yaml" << 6 << "basicInfo";
    QTest::newRow("text for a mapping") << "type-error-scalar.yaml" << 10 << "rtcDoc::doc";
    QTest::newRow("list for a value") << "type-error-nested.yaml" << 10 << "defaultValue";
    QTest::newRow("bad date") << "bad-date.yaml" << 8 << "date";
    QTest::newRow("wrong top key") << "wrong-top-key.yaml" << 2 << "rtcProfile";
    QTest::newRow("empty") << "empty.yaml" << 1 << "rtcProfile";
    QTest::newRow("invalid UTF-8") << "invalid-utf8.yaml" << 5 << "UTF-8";
}

void TestRtcYaml::reportsBrokenFiles()
{
    QFETCH(QString, file);
    QFETCH(int, line);
    QFETCH(QString, message);
    const QString name = QStringLiteral("rtc-broken/") + file;
    Diagnostics diagnostics;
    const auto profile = readRtcYaml(readData(name), name, &diagnostics);
    QVERIFY(!profile);
    Diagnostics errors;
    for (const Diagnostic &d : diagnostics) {
        if (d.severity == Diagnostic::Severity::Error)
            errors.append(d);
    }
    QVERIFY2(!errors.isEmpty(), qPrintable(messagesOf(diagnostics)));
    const Diagnostic &first = errors.front();
    QCOMPARE(first.file, name);
    QCOMPARE(first.line, line);
    QVERIFY(first.column > 0);
    QVERIFY2(first.message.contains(message), qPrintable(first.message));
}

void TestRtcYaml::rejectsDeepNesting_data()
{
    QTest::addColumn<int>("depth");
    QTest::newRow("deeper than the reader follows") << 300;
    QTest::newRow("deeper than yaml-cpp parses") << 5000;
}

void TestRtcYaml::rejectsDeepNesting()
{
    QFETCH(int, depth);
    const QByteArray yaml = "rtcProfile:\n  id: \"RTC:V:C:N:1.0\"\n  futureKey: "
        + QByteArray(depth, '[') + QByteArray(depth, ']') + "\n";
    Diagnostics diagnostics;
    QVERIFY(!readRtcYaml(yaml, QStringLiteral("deep.yaml"), &diagnostics));
    QVERIFY(hasErrors(diagnostics));
    for (const Diagnostic &d : diagnostics) {
        if (d.severity == Diagnostic::Severity::Error) {
            QCOMPARE(d.line, 3);
            break;
        }
    }
}

QTEST_GUILESS_MAIN(TestRtcYaml)
#include "tst_rtcyaml.moc"
