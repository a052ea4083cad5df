// SPDX-License-Identifier: MIT
// Validation of RTC profiles: each rule, with severities and the source line of the element.
#include "rtcvalidator.h"
#include "rtcxml.h"

#include <QFile>
#include <QTest>

using namespace Profile;

namespace {

const QString FileName = QStringLiteral("invalid.xml");

RtcProfile loadInvalid()
{
    QFile file(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/rtc/invalid.xml"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot open rtc/invalid.xml");
    const auto profile = readRtcXml(file.readAll(), FileName, nullptr);
    if (!profile)
        qFatal("cannot read rtc/invalid.xml");
    return *profile;
}

QString listOf(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

/// How many findings have this severity, line and a message containing `text`.
int count(const Diagnostics &diagnostics, Diagnostic::Severity severity, int line,
          const QString &text)
{
    int n = 0;
    for (const Diagnostic &d : diagnostics) {
        if (d.severity == severity && d.line == line && d.message.contains(text))
            ++n;
    }
    return n;
}

} // namespace

class TestRtcValidator : public QObject
{
    Q_OBJECT

private slots:
    void acceptsDefaultProfile();
    void reportsEachRule_data();
    void reportsEachRule();
    void reportsNothingMoreThanTheRules();
    void warnsAboutIdNotMatchingBasicInfo();
    void acceptsUnlimitedInstancesAndEmptyVariableNames();
    void checksEditedModelsWithoutLocations();
};

void TestRtcValidator::acceptsDefaultProfile()
{
    const Diagnostics findings = validateRtcProfile(RtcProfile::createDefault(), FileName);
    QVERIFY2(findings.isEmpty(), qPrintable(listOf(findings)));
}

void TestRtcValidator::reportsEachRule_data()
{
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("text");
    QTest::newRow("malformed id") << 2 << "malformed id 'RTC:broken'";
    QTest::newRow("name charset") << 3 << "'Bad Name!' may only contain";
    QTest::newRow("component type") << 3 << "unknown component type 'STATIC2'";
    QTest::newRow("activity type is case-sensitive") << 3 << "unknown activity type 'periodic'";
    QTest::newRow("execution rate") << 3 << "execution rate 'fast'";
    QTest::newRow("negative max instances") << 3 << "instances '-1'";
    QTest::newRow("implemented not boolean") << 6 << "'maybe'";
    QTest::newRow("duplicate configuration")
        << 10 << "duplicate configuration name 'gain' (first used at line 9)";
    QTest::newRow("radio without constraint") << 11 << "radio widget";
    QTest::newRow("radio with a range") << 14 << "radio widget";
    QTest::newRow("duplicate variable")
        << 36 << "duplicate variable name 'shared' (first used at line 9)";
    QTest::newRow("duplicate data port")
        << 37 << "duplicate port name 'in' (first used at line 36)";
    QTest::newRow("port type") << 37 << "unknown port type 'DataPort'";
    QTest::newRow("position") << 37 << "unknown position 'MIDDLE'";
    QTest::newRow("service port named like a data port") << 38 << "duplicate port name 'in'";
    QTest::newRow("direction") << 39 << "unknown direction 'Both'";
    QTest::newRow("duplicate interface") << 40 << "duplicate interface name 'if'";
}

void TestRtcValidator::reportsEachRule()
{
    QFETCH(int, line);
    QFETCH(QString, text);
    const Diagnostics findings = validateRtcProfile(loadInvalid(), FileName);
    QVERIFY2(count(findings, Diagnostic::Severity::Error, line, text) == 1,
             qPrintable(listOf(findings)));
    for (const Diagnostic &d : findings) {
        QCOMPARE(d.file, FileName);
        QVERIFY(d.column > 0);
        QVERIFY(!d.object.isEmpty());
    }
}

void TestRtcValidator::reportsNothingMoreThanTheRules()
{
    const Diagnostics findings = validateRtcProfile(loadInvalid(), FileName);
    int errors = 0;
    for (const Diagnostic &d : findings)
        errors += d.severity == Diagnostic::Severity::Error ? 1 : 0;
    // One per row of reportsEachRule; the radio with an enumeration (line 24) is fine.
    QCOMPARE(errors, 17);
    QCOMPARE(count(findings, Diagnostic::Severity::Error, 24, QString()), 0);
}

void TestRtcValidator::warnsAboutIdNotMatchingBasicInfo()
{
    RtcProfile p = RtcProfile::createDefault();
    p.id = QStringLiteral("RTC:Other:Category:ModuleName:1.0.0");
    const Diagnostics findings = validateRtcProfile(p, FileName);
    QCOMPARE(findings.size(), 1);
    QCOMPARE(findings.front().severity, Diagnostic::Severity::Warning);
    QVERIFY(findings.front().message.contains(QStringLiteral("does not match")));
}

void TestRtcValidator::acceptsUnlimitedInstancesAndEmptyVariableNames()
{
    RtcProfile p = RtcProfile::createDefault();
    p.basicInfo.maxInstances = QStringLiteral("0");
    p.basicInfo.executionRate = QStringLiteral("0");
    for (const char *name : {"a", "b"}) {
        RtcDataPort port;
        port.portType = QStringLiteral("DataOutPort");
        port.name = QLatin1String(name);
        port.type = QStringLiteral("RTC::TimedLong");
        port.position = QStringLiteral("RIGHT");
        port.variableName = QString();
        p.dataPorts.append(port);
    }
    const Diagnostics findings = validateRtcProfile(p, FileName);
    QVERIFY2(findings.isEmpty(), qPrintable(listOf(findings)));
}

void TestRtcValidator::checksEditedModelsWithoutLocations()
{
    RtcProfile p = RtcProfile::createDefault();
    RtcServicePort port;
    port.name = QStringLiteral("ModuleName port");
    port.position = QStringLiteral("LEFT");
    p.servicePorts.append(port);
    const Diagnostics findings = validateRtcProfile(p, QString());
    QCOMPARE(findings.size(), 1);
    QCOMPARE(findings.front().line, 0);
    QVERIFY(findings.front().message.contains(QStringLiteral("may only contain")));
    QCOMPARE(findings.front().toString().left(6), QStringLiteral("error:"));
}

QTEST_GUILESS_MAIN(TestRtcValidator)
#include "tst_rtcvalidator.moc"
