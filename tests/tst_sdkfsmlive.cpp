// SPDX-License-Identifier: MIT
// A static FSM component written by hand in OpenRTM-aist 2.x style (TrafficLight, built against
// the component SDK) runs in rtmanager: rtmanager's ConsoleIn components send its events through
// rtctl connections to its EventInPort (data type "any", so TimedLong OutPorts connect), events
// named by the connector property fsm_event_name or by the connector's name, one event with a
// TimedLong argument kept in the top state's box; the light it writes on its OutPort reaches a
// ConsoleOut, and its current state shows in its status list.
#include "livesystem.h"
#include "rtctlrunner.h"
#include "trafficlightdriver.h"

#include <QtTest>

class TestSdkFsmLive : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void eventsDriveTheLight();

private:
    LiveTest::LiveSystem m_live;
    CORBA::ORB_var m_orb;
    std::unique_ptr<SdkFsmTest::TrafficLightDriver> m_driver;
};

void TestSdkFsmLive::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList options{"corba.nameservers=" + m_live.namingServer(), "naming.formats=fsmhost.host_cxt/%n.rtc",
                              "manager.naming_formats=fsmhost.host_cxt/%n.mgr",
                              QStringLiteral("manager.modules.load_path=") + SDK_TEST_MODULE_DIR,
                              SdkFsmTest::TrafficLightDriver::precreate()};
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, LiveTest::freePort(), options, &error), qPrintable(error));
    const QString host = QStringLiteral("/%1/fsmhost.host_cxt").arg(m_live.namingServer());
    // TrafficLight.so is found in the load path.
    const RtctlResult r = runRtctlAt(host, {"mgr", host + "/manager.mgr", "create", "TrafficLight?instance_name=Light"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    m_driver = std::make_unique<SdkFsmTest::TrafficLightDriver>(m_orb, m_live.namingServer(), "fsmhost",
                                                                host + "/Light.rtc");
}

void TestSdkFsmLive::cleanupTestCase()
{
    m_live.stopAll();
}

void TestSdkFsmLive::eventsDriveTheLight()
{
    SdkFsmTest::TrafficLightDriver &light = *m_driver;
    const QString lightPath = light.path("Light");
    // The machine starts in Dark (Top's init): no transition has run, yet the state is known.
    QCOMPARE(light.status(lightPath, "fsm_state"), QString("Dark"));
    QString error = light.connectAll();
    QVERIFY2(error.isEmpty(), qPrintable(error));
    error = light.activate();
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(light.lastValue(), QString("0"), 20000);

    for (const SdkFsmTest::TrafficStep &step : SdkFsmTest::trafficScenario()) {
        QString seen;
        QVERIFY2(light.press(step.button, step.wanted, &seen), qPrintable(step.why + ", values seen: " + seen));
        QCOMPARE(light.status(lightPath, "fsm_state"), step.state);
    }
}

QTEST_GUILESS_MAIN(TestSdkFsmLive)
#include "tst_sdkfsmlive.moc"
