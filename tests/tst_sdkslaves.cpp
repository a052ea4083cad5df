// SPDX-License-Identifier: MIT
// SDK modules in a master and in slave managers: a type that is not registered yet is loaded
// from the load path where the component is created (the master's own process or a slave
// started for it), and a component that crashes in onExecute takes down only its own slave.
#include "livesystem.h"
#include "onlinecalls.h"
#include "rtctlrunner.h"

#include <QtTest>

class TestSdkSlaves : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void typeFromLoadPathInMasterAndSlaves();
    void crashTakesDownOnlyItsSlave();
    void restoreCreatesTypeFromLoadPath();
    void restoreWithoutManagerUsesTheSavedHosts();
    void rtcConfPreloadsAndPrecreates();
    void withoutManagerServant();

private:
    RtctlResult rtctl(const QStringList &arguments);
    QString host() const { return QStringLiteral("/%1/slavehost.host_cxt").arg(m_live.namingServer()); }
    bool isActive(const QString &component) { return rtctl({"cat", component}).out.contains("Active"); }

    LiveTest::LiveSystem m_live;
};

RtctlResult TestSdkSlaves::rtctl(const QStringList &arguments)
{
    return runRtctlAt(host(), arguments);
}

void TestSdkSlaves::initTestCase()
{
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList options{"corba.nameservers=" + m_live.namingServer(), "naming.formats=slavehost.host_cxt/%n.rtc",
                              "manager.naming_formats=slavehost.host_cxt/%n.mgr",
                              QStringLiteral("manager.modules.load_path=") + SDK_TEST_MODULE_DIR};
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
    // The component crashes as soon as the value reaches it, which can be before rtctl's last call
    // (activating the set) returns: that call may then fail, so only the outcome is checked.
    const RtctlResult r = rtctl({"conf", "Victim.rtc", "set", "crash", "1"});
    QVERIFY2(r.code == 0 || r.err.contains("Victim.rtc"), qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "Victim.rtc"}).code != 0, 20000);
    QVERIFY(isActive("Local.rtc"));
    QVERIFY(isActive("Survivor.rtc"));
    const RtctlResult list = rtctl({"mgr", host() + "/manager.mgr", "list"});
    QVERIFY2(list.code == 0, qPrintable(list.out + list.err));
    QVERIFY(list.out.contains("Survivor"));
    QVERIFY(!list.out.contains("Victim"));

    // What the online views read of the name server: only the crashed one is marked (its name
    // is still bound, its process is gone), the others run on.
    const SystemEditor::ServerSnapshot snapshot = SystemEditor::OnlineCalls::fetchServer(m_live.namingServer());
    QHash<QString, Corba::NamingNode> byName;
    std::function<void(const Corba::NamingNode &)> collect = [&](const Corba::NamingNode &node) {
        if (node.path.startsWith(host() + '/'))
            byName.insert(node.name, node);
        for (const Corba::NamingNode &child : node.children)
            collect(child);
    };
    collect(snapshot.tree);
    QVERIFY(byName.contains("Victim.rtc"));
    QCOMPARE(byName.value("Victim.rtc").type, Corba::NodeType::Zombie);
    for (const char *survivor : {"Local.rtc", "Survivor.rtc"}) {
        const Corba::NamingNode node = byName.value(survivor);
        QCOMPARE(node.type, Corba::NodeType::Component);
        QCOMPARE(snapshot.states.value(node.path), Corba::LifeCycleState::Active);
    }
}

void TestSdkSlaves::restoreCreatesTypeFromLoadPath()
{
    // A saved system whose component type only exists as a module in the load path.
    QTemporaryDir dir;
    const QString saved = dir.filePath("probe.rtsys");
    RtctlResult r = rtctl({"cryo", "-n", "ProbeSystem", "-o", saved, host() + "/Local.rtc"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"mgr", host() + "/manager.mgr", "delete", "Local"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "Local.rtc"}).code != 0, 10000);

    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, port,
                                 {"corba.nameservers=" + m_live.namingServer(),
                                  "naming.formats=restorehost.host_cxt/%n.rtc",
                                  "manager.naming_formats=restorehost.host_cxt/%n.mgr",
                                  QStringLiteral("manager.modules.load_path=") + SDK_TEST_MODULE_DIR},
                                 &error),
             qPrintable(error));
    r = runRtctl({"resurrect", "--create", "-m", QStringLiteral("corbaloc::127.0.0.1:%1").arg(port), "-s",
                  m_live.namingServer(), saved});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    const QString restored = QStringLiteral("/%1/restorehost.host_cxt/Local.rtc").arg(m_live.namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"cat", restored}).code == 0, 10000);
}

void TestSdkSlaves::restoreWithoutManagerUsesTheSavedHosts()
{
    // No -m: the component is created by the manager registered beside its saved name.
    RtctlResult r = rtctl({"mgr", host() + "/manager.mgr", "create", "CrashProbe?instance_name=Saved"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTemporaryDir dir;
    const QString saved = dir.filePath("saved.rtsys");
    r = rtctl({"cryo", "-n", "SavedSystem", "-o", saved, host() + "/Saved.rtc"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"mgr", host() + "/manager.mgr", "delete", "Saved"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "Saved.rtc"}).code != 0, 10000);
    r = rtctl({"resurrect", "--create", "-s", m_live.namingServer(), saved});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2((r.out + r.err).contains("slavehost.host_cxt/manager.mgr"), qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "Saved.rtc"}).code == 0, 10000);
}

void TestSdkSlaves::rtcConfPreloadsAndPrecreates()
{
    // OpenRTM-aist's usual master rtc.conf, read from a file given with -f: endpoints without a port,
    // the master port in corba.master_manager, modules preloaded and components precreated.
    const quint16 masterPort = LiveTest::freePort();
    QTemporaryDir dir;
    QFile conf(dir.filePath("rtc.conf"));
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write((QStringLiteral("corba.nameservers: %1\n" "corba.endpoints: 127.0.0.1:\n" "corba.master_manager: 127.0.0.1:%2\n" "manager.is_master: YES\n" "naming.formats: confhost.host_cxt/%n.rtc\n" "manager.naming_formats: confhost.host_cxt/%n.mgr\n" "manager.modules.load_path: ") + SDK_TEST_MODULE_DIR + QStringLiteral("\n" "manager.modules.preload: CrashProbe.so\n" "manager.components.precreate: CrashProbe?instance_name=Early\n"))
                   .arg(m_live.namingServer())
                   .arg(masterPort)
                   .toUtf8());
    conf.close();
    QString error;
    QVERIFY2(m_live.startProcess(RTMANAGER_PATH, {"-f", conf.fileName()}, "rtmanager ready", &error),
             qPrintable(error));
    const QString early = QStringLiteral("/%1/confhost.host_cxt/Early.rtc").arg(m_live.namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"cat", early}).code == 0, 10000);
    // The master answers on the master port, where slaves and tools look for it.
    const RtctlResult list = runRtctl({"mgr", QStringLiteral("corbaloc::127.0.0.1:%1").arg(masterPort), "list"});
    QVERIFY2(list.code == 0 && list.out.contains("CrashProbe.so"), qPrintable(list.out + list.err));
}

void TestSdkSlaves::withoutManagerServant()
{
    // `-a`: the process hosts and registers its components but serves no RTM::Manager.
    QString error;
    const QString endpoint = QStringLiteral("corba.endpoints:127.0.0.1:%1").arg(LiveTest::freePort());
    QVERIFY2(m_live.startProcess(RTMANAGER_PATH,
                                 {"-a", "-o", endpoint, "-o", "corba.nameservers:" + m_live.namingServer(), "-o",
                                  "naming.formats:bare.host_cxt/%n.rtc", "-o",
                                  "manager.naming_formats:bare.host_cxt/%n.mgr", "-o", "corba.master_manager:", "-o",
                                  "manager.components.precreate:ConsoleIn"},
                                 "rtmanager ready", &error),
             qPrintable(error));
    const QString context = QStringLiteral("/%1/bare.host_cxt").arg(m_live.namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"ls", context}).out.contains("ConsoleIn0.rtc"), 10000);
    QVERIFY(!runRtctl({"ls", context}).out.contains("manager.mgr"));
}

QTEST_GUILESS_MAIN(TestSdkSlaves)
#include "tst_sdkslaves.moc"
