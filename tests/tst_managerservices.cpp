// SPDX-License-Identifier: MIT
// rtmanager's answers beyond its own process, live: a master aggregating its slaves' components
// (stopped and dead slaves skipped within a bound), restart(), fork() and get_service().
#include "corbautil.h"
#include "livesystem.h"

#include <Manager.hh>
#include <omniORB4/Naming.hh>
#include <omniORB4/omniORB.h>

#include "common/nvlist.h"

#include <QtTest>

#include <csignal>

namespace {

QStringList instanceNames(const RTC::ComponentProfileList &profiles)
{
    QStringList names;
    for (CORBA::ULong i = 0; i < profiles.length(); ++i)
        names << QString::fromUtf8(profiles[i].instance_name.in());
    names.sort();
    return names;
}

// -1 while the manager does not answer (restarting), else how many components it lists.
int componentCount(RTM::Manager_ptr manager)
{
    try {
        RTC::RTCList_var list = manager->get_components();
        return int(list->length());
    } catch (const CORBA::Exception &) {
        return -1;
    }
}

} // namespace

class TestManagerServices : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cleanupTestCase();

    void masterAggregatesSlaves();
    void stoppedAndDeadSlavesAreSkipped();
    void restartRunsAgainFresh();
    void forkStartsRegisteredSlaves();
    void servicesByName();

private:
    RTM::Manager_ptr managerAt(quint16 port);
    RTM::Manager_ptr slave(const QString &name);
    RTC::RTObject_ptr create(const QString &request);

    CORBA::ORB_var m_orb;
    std::unique_ptr<LiveTest::LiveSystem> m_live;
    RTM::Manager_var m_master;
    QProcess *m_process = nullptr;
    quint16 m_port = 0;
};

void TestManagerServices::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    // Creating on a new slave starts a process: allow for it, but never wait forever.
    omniORB::setClientCallTimeout(15000);
}

void TestManagerServices::init()
{
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startNameServer(&error), qPrintable(error));
    m_port = LiveTest::freePort();
    // A slow watchdog, so that a stopped slave stays listed while the master is asked.
    const QStringList options {"corba.nameservers=" + m_live->namingServer(),
                               "naming.formats=svchost.host_cxt/%n.rtc",
                               "manager.naming_formats=svchost.host_cxt/%n.mgr",
                               "manager.components.precreate=ConsoleIn",
                               "manager.slave_call_timeout=800",
                               "manager.slave_check_interval=60000"};
    m_process = m_live->startManager(RTMANAGER_PATH, m_port, options, &error);
    QVERIFY2(m_process, qPrintable(error));
    m_master = managerAt(m_port);
    QVERIFY(!CORBA::is_nil(m_master));
}

void TestManagerServices::cleanup()
{
    m_master = RTM::Manager::_nil();
    m_live.reset(); // kills the master; slaves it started follow it
}

void TestManagerServices::cleanupTestCase()
{
    m_orb->destroy();
}

RTM::Manager_ptr TestManagerServices::managerAt(quint16 port)
{
    CORBA::Object_var object = m_orb->string_to_object(LiveTest::managerLocation(port).constData());
    return RTM::Manager::_unchecked_narrow(object);
}

RTM::Manager_ptr TestManagerServices::slave(const QString &name)
{
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    for (CORBA::ULong i = 0; i < slaves->length(); ++i) {
        RTM::ManagerProfile_var profile = slaves[i]->get_profile();
        if (nv(profile->properties, "instance_name") == name)
            return RTM::Manager::_duplicate(slaves[i]);
    }
    return RTM::Manager::_nil();
}

RTC::RTObject_ptr TestManagerServices::create(const QString &request)
{
    return m_master->create_component(request.toUtf8().constData());
}

void TestManagerServices::masterAggregatesSlaves()
{
    RTC::RTObject_var a = create("ConsoleOut?manager_name=slaveA&instance_name=OutA");
    RTC::RTObject_var b = create("Sensor?instance_name=SensB&manager_name=slaveB");
    QVERIFY(!CORBA::is_nil(a) && !CORBA::is_nil(b));

    RTC::ComponentProfileList_var profiles = m_master->get_component_profiles();
    QCOMPARE(instanceNames(profiles.in()), QStringList({"ConsoleIn0", "OutA", "SensB"}));
    QCOMPARE(componentCount(m_master), 3);
    // By name, as OpenRTM-aist's: each manager answers for its own components only, named
    // `Instance`, `*` + `/Instance` or `category/Instance`.
    RTC::RTCList_var named = m_master->get_components_by_name("SensB");
    QCOMPARE(named->length(), CORBA::ULong(0));
    RTM::Manager_var slaveB = slave("slaveB");
    QVERIFY(!CORBA::is_nil(slaveB));
    named = slaveB->get_components_by_name("SensB");
    QCOMPARE(named->length(), CORBA::ULong(1));
    QVERIFY(named[0]->_is_equivalent(b));
    for (const char *name : {"ConsoleIn0", "*/ConsoleIn0", "example/ConsoleIn0"}) {
        named = m_master->get_components_by_name(name);
        QVERIFY2(named->length() == 1, name);
    }
    for (const char *name : {"Nobody", "other/ConsoleIn0", "ConsoleIn"}) {
        named = m_master->get_components_by_name(name);
        QVERIFY2(named->length() == 0, name);
    }
    // A slave answers for itself only.
    RTM::Manager_var slaveA = slave("slaveA");
    QVERIFY(!CORBA::is_nil(slaveA));
    QCOMPARE(componentCount(slaveA), 1);
    profiles = slaveA->get_component_profiles();
    QCOMPARE(instanceNames(profiles.in()), QStringList({"OutA"}));
}

void TestManagerServices::stoppedAndDeadSlavesAreSkipped()
{
    RTC::RTObject_var a = create("ConsoleOut?manager_name=slaveA&instance_name=OutA");
    RTC::RTObject_var b = create("ConsoleOut?manager_name=slaveB&instance_name=OutB");
    QVERIFY(!CORBA::is_nil(a) && !CORBA::is_nil(b));
    RTM::Manager_var slaveA = slave("slaveA");
    RTM::Manager_var slaveB = slave("slaveB");
    const qint64 pidA
        = nv(RTM::ManagerProfile_var(slaveA->get_profile())->properties, "pid").toLongLong();
    const qint64 pidB
        = nv(RTM::ManagerProfile_var(slaveB->get_profile())->properties, "pid").toLongLong();
    QVERIFY(pidA > 0 && pidB > 0);

    QCOMPARE(::kill(pid_t(pidB), SIGSTOP), 0);
    QVERIFY2(LiveTest::waitUntilStopped(pidB), "slaveB did not stop");
    QElapsedTimer timer;
    timer.start();
    RTC::ComponentProfileList_var profiles = m_master->get_component_profiles();
    const qint64 elapsed = timer.elapsed();
    ::kill(pid_t(pidB), SIGCONT);
    QCOMPARE(instanceNames(profiles.in()), QStringList({"ConsoleIn0", "OutA"}));
    // The stopped slave was asked and given up on after manager.slave_call_timeout (800 ms).
    QVERIFY2(elapsed >= 700 && elapsed < 800 + 1500, qPrintable(QString::number(elapsed)));
    QCOMPARE(componentCount(m_master), 3);

    QCOMPARE(::kill(pid_t(pidA), SIGKILL), 0);
    QTRY_COMPARE(componentCount(m_master), 2);
    profiles = m_master->get_component_profiles();
    QCOMPARE(instanceNames(profiles.in()), QStringList({"ConsoleIn0", "OutB"}));
}

void TestManagerServices::restartRunsAgainFresh()
{
    RTC::RTObject_var extra = create("ConsoleOut?instance_name=Extra0");
    QVERIFY(!CORBA::is_nil(extra));
    QCOMPARE(componentCount(m_master), 2);
    const QString pid = nv(RTM::ManagerProfile_var(m_master->get_profile())->properties, "pid");

    QCOMPARE(m_master->restart(), RTC::RTC_OK);
    // Same process image replaced, same endpoint; the precreated component only, made anew.
    QTRY_COMPARE_WITH_TIMEOUT(componentCount(m_master), 1, 15000);
    QCOMPARE(nv(RTM::ManagerProfile_var(m_master->get_profile())->properties, "pid"), pid);
    QCOMPARE(m_process->state(), QProcess::Running);
    RTC::RTCList_var list = m_master->get_components_by_name("ConsoleIn0");
    QCOMPARE(list->length(), CORBA::ULong(1));
    bool oldGone = false;
    try {
        oldGone = extra->_non_existent();
    } catch (const CORBA::Exception &) {
        oldGone = true;
    }
    QVERIFY(oldGone);
    list = m_master->get_components_by_name("Extra0");
    QCOMPARE(list->length(), CORBA::ULong(0));
}

void TestManagerServices::forkStartsRegisteredSlaves()
{
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(0));
    QCOMPARE(m_master->fork(), RTC::RTC_OK);
    slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(1));
    RTM::ManagerProfile_var profile = slaves[0]->get_profile();
    QCOMPARE(nv(profile->properties, "is_master"), QString("NO"));
    QVERIFY(nv(profile->properties, "pid")
            != nv(RTM::ManagerProfile_var(m_master->get_profile())->properties, "pid"));
    // A fork asked of the slave registers its new sibling with the same master.
    QCOMPARE(slaves[0]->fork(), RTC::RTC_OK);
    QTRY_COMPARE_WITH_TIMEOUT(RTM::ManagerList_var(m_master->get_slave_managers())->length(),
                              CORBA::ULong(2), 15000);
}

void TestManagerServices::servicesByName()
{
    CORBA::Object_var self = m_master->get_service("manager");
    QVERIFY(!CORBA::is_nil(self) && Runtime::sameObject(self, m_master));
    CORBA::Object_var master = m_master->get_service("master");
    QVERIFY(!CORBA::is_nil(master) && Runtime::sameObject(master, m_master));
    CORBA::Object_var unknown = m_master->get_service("NoSuchService");
    QVERIFY(CORBA::is_nil(unknown));

    CORBA::Object_var object = m_master->get_service("NameService");
    CosNaming::NamingContext_var naming = CosNaming::NamingContext::_narrow(object);
    QVERIFY(!CORBA::is_nil(naming));
    CosNaming::Name name;
    name.length(2);
    name[0].id = "svchost";
    name[0].kind = "host_cxt";
    name[1].id = "manager";
    name[1].kind = "mgr";
    CORBA::Object_var bound = naming->resolve(name);
    QVERIFY(Runtime::sameObject(bound, m_master));

    RTC::RTObject_var onSlave = create("ConsoleOut?manager_name=slaveS");
    QVERIFY(!CORBA::is_nil(onSlave));
    RTM::Manager_var slaveS = slave("slaveS");
    CORBA::Object_var slavesMaster = slaveS->get_service("master");
    QVERIFY(!CORBA::is_nil(slavesMaster) && Runtime::sameObject(slavesMaster, m_master));
    CORBA::Object_var slaveSelf = slaveS->get_service("manager");
    QVERIFY(Runtime::sameObject(slaveSelf, slaveS));
}

QTEST_GUILESS_MAIN(TestManagerServices)
#include "tst_managerservices.moc"
