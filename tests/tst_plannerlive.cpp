// SPDX-License-Identifier: MIT
// Node facts from live rtmanager processes (two on free loopback ports, told different node.*
// facts) and `rtctl plan` placing a system by them.
#include "livesystem.h"
#include "nodefactsreader.h"
#include "orb.h"
#include "rtctlrunner.h"

#include <QDir>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

class TestPlannerLive : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void readsFactsOfManagers();
    void unreachableManagerIsAnError();
    void rtctlPlanPlacesByNodeFacts();
    void rtctlPlanWithoutTheDeviceNode();

private:
    QString address(quint16 port) const
    {
        return QStringLiteral("corbaloc::127.0.0.1:%1").arg(port);
    }

    LiveTest::LiveSystem m_live;
    QTemporaryDir m_packages; ///< the onboard node's package folder, with one installed package
    quint16 m_onboard = 0;
    quint16 m_base = 0;
};

void TestPlannerLive::initTestCase()
{
    Corba::Orb::setCallTimeout(3000);
    QString error;
    QVERIFY(QDir(m_packages.path()).mkpath(QStringLiteral("rtc-rtstudio-sensor-lidar")));
    m_onboard = LiveTest::freePort();
    QVERIFY2(m_live.startManager(
                 RTMANAGER_PATH, m_onboard,
                 {QStringLiteral("naming.enable=NO"), QStringLiteral("node.devices=lidar0,camera0"),
                  QStringLiteral("node.role=onboard"),
                  QStringLiteral("manager.modules.package_path=") + m_packages.path()},
                 &error),
             qPrintable(error));
    m_base = LiveTest::freePort();
    QVERIFY2(m_live.startManager(
                 RTMANAGER_PATH, m_base,
                 {QStringLiteral("naming.enable=NO"), QStringLiteral("node.role=base")}, &error),
             qPrintable(error));
}

void TestPlannerLive::cleanupTestCase()
{
    m_live.stopAll();
}

void TestPlannerLive::readsFactsOfManagers()
{
    const QList<Deploy::NodeFactsReading> readings
        = Deploy::readNodeFacts({address(m_onboard), address(m_base)});
    QCOMPARE(readings.size(), qsizetype(2));
    for (const Deploy::NodeFactsReading &reading : readings) {
        QVERIFY2(reading.error.isEmpty(), qPrintable(reading.error));
        const Planner::NodeFacts &facts = reading.facts;
        QCOMPARE(facts.os, QStringLiteral("Linux"));
        QVERIFY(facts.architecture && !facts.architecture->isEmpty());
        QVERIFY(facts.hostname && !facts.hostname->isEmpty());
        QVERIFY(facts.cpuCount.value_or(0) > 0);
        QVERIFY(facts.memoryKiB.value_or(0) > 0);
        QVERIFY(facts.loadAverage.has_value());
        QCOMPARE(facts.sdkAbi, QStringLiteral(SDK_SONAME));
        QCOMPARE(facts.languages, QStringList {QStringLiteral("C++")});
        QVERIFY(facts.loadableTypes && facts.loadableTypes->contains(QStringLiteral("ConsoleIn")));
    }
    QCOMPARE(readings.at(0).facts.name, address(m_onboard));
    QCOMPARE(readings.at(0).facts.devices(),
             (QStringList {QStringLiteral("lidar0"), QStringLiteral("camera0")}));
    QCOMPARE(readings.at(0).facts.userFacts.value(QStringLiteral("role")),
             QStringLiteral("onboard"));
    QCOMPARE(readings.at(0).facts.packages,
             QStringList {QStringLiteral("rtc-rtstudio-sensor-lidar")});
    QCOMPARE(readings.at(1).facts.userFacts.value(QStringLiteral("role")), QStringLiteral("base"));
    QVERIFY(readings.at(1).facts.devices().isEmpty());
}

void TestPlannerLive::unreachableManagerIsAnError()
{
    QElapsedTimer clock;
    clock.start();
    const QList<Deploy::NodeFactsReading> readings
        = Deploy::readNodeFacts({address(LiveTest::freePort()), address(m_base)});
    QVERIFY(!readings.at(0).error.isEmpty());
    QVERIFY(readings.at(1).error.isEmpty());
    QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
}

void TestPlannerLive::rtctlPlanPlacesByNodeFacts()
{
    const RtctlResult result = runRtctl(
        {QStringLiteral("plan"), RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/planner/live.xml"),
         QStringLiteral("--nodes"), address(m_base) + QLatin1Char(',') + address(m_onboard),
         QStringLiteral("--json"), QStringLiteral("--timeout"), QStringLiteral("3000")});
    QVERIFY2(result.code == 0, qPrintable(result.err));
    QHash<QString, QString> nodeOf;
    for (const QJsonValue &value :
         result.json().object().value(QStringLiteral("placements")).toArray()) {
        const QJsonObject p = value.toObject();
        nodeOf.insert(p.value(QStringLiteral("component")).toString(),
                      p.value(QStringLiteral("node")).toString());
    }
    QCOMPARE(nodeOf.value(QStringLiteral("Scan0")), address(m_onboard));
    QCOMPARE(nodeOf.value(QStringLiteral("Sink0")), address(m_onboard));
    QCOMPARE(nodeOf.value(QStringLiteral("Station0")), address(m_base));
    QVERIFY(result.json().object().value(QStringLiteral("installs")).toArray().isEmpty());
}

void TestPlannerLive::rtctlPlanWithoutTheDeviceNode()
{
    const RtctlResult result = runRtctl({QStringLiteral("plan"),
                                         RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/planner/live.xml"),
                                         QStringLiteral("--nodes"), address(m_base),
                                         QStringLiteral("--timeout"), QStringLiteral("3000")});
    QCOMPARE(result.code, 1);
    QVERIFY2(result.err.contains(
                 QStringLiteral(
                     "Scan0: device lidar0 - no node meets it; closest %1 has no devices listed")
                     .arg(address(m_base))),
             qPrintable(result.err));
}

QTEST_GUILESS_MAIN(TestPlannerLive)
#include "tst_plannerlive.moc"
