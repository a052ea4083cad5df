// SPDX-License-Identifier: MIT
// SDK modules in a master and in slave managers: a type that is not registered yet is loaded
// from the load path where the component is created (the master's own process or a slave
// started for it), and a component that crashes in onExecute takes down only its own slave.
#include "livesystem.h"
#include "rtctlrunner.h"

#include <QtTest>

class TestSdkSlaves : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void typeFromLoadPathInMasterAndSlaves();
    void crashTakesDownOnlyItsSlave();

private:
    RtctlResult rtctl(const QStringList &arguments);
    QString host() const { return QStringLiteral("/%1/slavehost.host_cxt").arg(m_live.namingServer()); }
    bool isActive(const QString &component) { return rtctl({"cat", component}).out.contains("Active"); }

    LiveTest::LiveSystem m_live;
};

RtctlResult TestSdkSlaves::rtctl(const QStringList &arguments)
{
    return runRtctl(arguments, {{QStringLiteral("RTCSH_CWD"), host()}, {QStringLiteral("RTCTREE_NAMESERVERS"), QString()}});
}

void TestSdkSlaves::initTestCase()
{
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList options{"corba.nameservers=" + m_live.namingServer(), "naming.formats=slavehost.host_cxt/%n.rtc",
                              "manager.naming_formats=slavehost.host_cxt/%n.mgr",
                              "manager.modules.load_path=" SDK_TEST_MODULE_DIR};
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, LiveTest::freePort(), options, &error), qPrintable(error));
}

void TestSdkSlaves::typeFromLoadPathInMasterAndSlaves()
{
    // No load: CrashProbe.so is found in manager.modules.load_path by every process that needs it.
    const RtctlResult r = rtctl({"mgr", host() + "/manager.mgr", "create", "CrashProbe?instance_name=Local", "create",
                                 "CrashProbe?instance_name=Victim&manager_name=crashslave", "create",
                                 "CrashProbe?instance_name=Survivor&manager_name=otherslave"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QCOMPARE(r.lines(), QStringList({"Local", "Victim", "Survivor"}));
    const RtctlResult act = rtctl({"act", "Local.rtc", "Victim.rtc", "Survivor.rtc"});
    QVERIFY2(act.code == 0, qPrintable(act.out + act.err));
    for (const char *component : {"Local.rtc", "Victim.rtc", "Survivor.rtc"})
        QTRY_VERIFY_WITH_TIMEOUT(isActive(component), 10000);
}

void TestSdkSlaves::crashTakesDownOnlyItsSlave()
{
    const RtctlResult r = rtctl({"conf", "Victim.rtc", "set", "crash", "1"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "Victim.rtc"}).code != 0, 20000);
    QVERIFY(isActive("Local.rtc"));
    QVERIFY(isActive("Survivor.rtc"));
    const RtctlResult list = rtctl({"mgr", host() + "/manager.mgr", "list"});
    QVERIFY2(list.code == 0, qPrintable(list.out + list.err));
    QVERIFY(list.out.contains("Survivor"));
    QVERIFY(!list.out.contains("Victim"));
}

QTEST_GUILESS_MAIN(TestSdkSlaves)
#include "tst_sdkslaves.moc"
