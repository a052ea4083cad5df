// SPDX-License-Identifier: MIT
// The FSM API matches OpenRTM-aist's: the lamp scenario (sdkfsm/lampmachine.h) built against
// OpenRTM-aist's own Macho prints the trace the SDK's machines produce (sdkfsm/lamp.trace), and
// the hand-written TrafficLight component (sdkmodules/trafficlight), built unchanged with
// OpenRTM-aist's CMake package and run as its standalone program, is driven through rtctl by
// rtmanager's ConsoleIn components exactly as the SDK build is in tst_sdkfsmlive.
//
// Needs the prefix of an OpenRTM-aist installation (CMake cache variable RTSTUDIO_OPENRTM_PREFIX,
// ctest label "interop"); without one the test is skipped.
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkproject.h"
#include "trafficlightdriver.h"

#include <QtTest>

namespace {

const QString openRtmPrefix = QStringLiteral(RTSTUDIO_OPENRTM_PREFIX);

bool copyFiles(const QString &from, const QStringList &names, const QString &to)
{
    for (const QString &name : names) {
        if (!QFile::copy(from + '/' + name, to + '/' + name))
            return false;
    }
    return true;
}

} // namespace

class TestInteropFsm : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void traceMatchesOpenRtmMacho();
    void openRtmComponentIsDriven();

private:
    QTemporaryDir m_work;
    QString m_project;
    LiveTest::LiveSystem m_live;
    CORBA::ORB_var m_orb;
};

void TestInteropFsm::initTestCase()
{
    if (openRtmPrefix.isEmpty())
        QSKIP("skipped: no OpenRTM-aist");
    QVERIFY2(QFile::exists(openRtmPrefix + "/include/openrtm-2.1/rtm/Macho.h"),
             qPrintable("RTSTUDIO_OPENRTM_PREFIX has no rtm/Macho.h"));
    LiveTest::useOpenRtm(openRtmPrefix);
    QVERIFY(m_work.isValid());
    m_project = m_work.filePath("TrafficLight");
    QVERIFY(QDir().mkpath(m_project));
    QVERIFY(copyFiles(SDK_TRAFFICLIGHT_DIR,
                      {"CMakeLists.txt", "TrafficLight.h", "TrafficLight.cpp", "TrafficLightComp.cpp",
                       "TrafficLightFsm.h", "TrafficLightFsm.cpp"},
                      m_project));
    QVERIFY(copyFiles(SDK_FSM_DIR, {"lampmachine.h", "lampids.cpp", "fsmtrace.cpp"}, m_project));
    QString log;
    QVERIFY2(SdkTest::buildProject(m_project, openRtmPrefix, &log), qPrintable(log));
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
}

void TestInteropFsm::cleanupTestCase()
{
    m_live.stopAll();
}

void TestInteropFsm::traceMatchesOpenRtmMacho()
{
    QProcess trace;
    trace.start(m_project + "/build/fsmtrace", {});
    QVERIFY(trace.waitForFinished(20000));
    QCOMPARE(trace.exitCode(), 0);
    QFile expected(SDK_FSM_DIR + QStringLiteral("/lamp.trace"));
    QVERIFY(expected.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList wanted = QString::fromUtf8(expected.readAll()).split('\n', Qt::SkipEmptyParts);
    const QStringList lines = QString::fromUtf8(trace.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines, wanted);
}

void TestInteropFsm::openRtmComponentIsDriven()
{
    QString error;
    const QStringList options{"corba.nameservers=" + m_live.namingServer(), "naming.formats=ours.host_cxt/%n.rtc",
                              "manager.naming_formats=ours.host_cxt/%n.mgr",
                              SdkFsmTest::TrafficLightDriver::precreate()};
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, LiveTest::freePort(), options, &error), qPrintable(error));
    // OpenRTM-aist 2.1's EventInPort lists no marshaling type of its own, so it refuses every
    // connection unless the component's configuration names one for it.
    QFile conf(m_work.filePath("trafficlight.conf"));
    QVERIFY(conf.open(QIODevice::WriteOnly | QIODevice::Text));
    conf.write("port.inport.event.dataport.marshaling_types: cdr\n");
    conf.close();
    // OpenRTM-aist's manager without a servant looks for no master; it registers in our name server.
    QStringList arguments;
    for (const QString &option : {"corba.nameservers:" + m_live.namingServer(), QString("corba.endpoints:127.0.0.1:"),
                                  QString("naming.formats:interop.host_cxt/%n.rtc"),
                                  QString("manager.corba_servant:NO"), QString("logger.enable:NO"),
                                  "test.TrafficLight.config_file:" + conf.fileName()})
        arguments << "-o" << option;
    QVERIFY2(m_live.startProcess(m_project + "/build/TrafficLightComp", arguments, QString(), &error, 0),
             qPrintable(error));
    const QString light = QStringLiteral("/%1/interop.host_cxt/TrafficLight0.rtc").arg(m_live.namingServer());
    SdkFsmTest::TrafficLightDriver driver(m_orb, m_live.namingServer(), "ours", light);
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"cat", light}, {{"RTCTREE_NAMESERVERS", QString()}}).code == 0, 30000);
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"cat", driver.path("StateView")}, {{"RTCTREE_NAMESERVERS", QString()}}).code == 0,
                             20000);
    error = driver.connectAll();
    QVERIFY2(error.isEmpty(), qPrintable(error));
    error = driver.activate();
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(driver.lastValue(), QString("0"), 20000);
    for (const SdkFsmTest::TrafficStep &step : SdkFsmTest::trafficScenario()) {
        QString seen;
        QVERIFY2(driver.press(step.button, step.wanted, &seen), qPrintable(step.why + ", values seen: " + seen));
    }
}

QTEST_GUILESS_MAIN(TestInteropFsm)
#include "tst_interopfsm.moc"
