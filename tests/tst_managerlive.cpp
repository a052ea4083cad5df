// SPDX-License-Identifier: MIT
// rtmanager as a real process next to a real omniNames (free loopback ports, always stopped):
// naming, create with parameters, data flow in one process and across slaves, slaves that die,
// bad requests, loadable modules and shutdown.
#include "corbautil.h"
#include "livesystem.h"
#include "referenceguard.h"
#include "roguereference.h"

#include <RTStudioManager.hh>
#include <omniORB4/Naming.hh>
#include <omniORB4/omniORB.h>

#include "common/nvlist.h"

#include <QtTest>
#include <QHostAddress>
#include <QTcpSocket>

#include <algorithm>
#include <csignal>
#include <thread>
#include <cstring>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

QString localHost()
{
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return QString::fromLocal8Bit(name);
}

void setNv(SDOPackage::NVList &list, const char *name, const QString &value)
{
    const CORBA::ULong n = list.length();
    list.length(n + 1);
    list[n].name = name;
    list[n].value <<= value.toUtf8().constData();
}

/// False once the process has exited (also while it waits, a zombie, for its new parent to reap it).
bool processRuns(qint64 pid)
{
    QFile stat(QString("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return false;
    const QByteArray text = stat.readAll();
    const int close = text.lastIndexOf(')');
    return close > 0 && text.mid(close + 2, 1) != "Z";
}

long status(RTC::RTObject_ptr rtc, const char *name)
{
    try {
        SDOPackage::NVList_var list = rtc->get_status_list();
        return nv(list.in(), name).toLong();
    } catch (const CORBA::Exception &) {
        return -1;
    }
}

QString statusText(RTC::RTObject_ptr rtc, const char *name)
{
    SDOPackage::NVList_var list = rtc->get_status_list();
    return nv(list.in(), name);
}

RTC::PortService_ptr port(RTC::RTObject_ptr rtc, const char *shortName)
{
    RTC::PortServiceList_var ports = rtc->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        if (QByteArray(profile->name).endsWith(QByteArray(".") + shortName))
            return RTC::PortService::_duplicate(ports[i]);
    }
    return RTC::PortService::_nil();
}

RTC::ReturnCode_t activate(RTC::RTObject_ptr rtc)
{
    RTC::ExecutionContextList_var ecs = rtc->get_owned_contexts();
    return ecs->length() ? ecs[0]->activate_component(rtc) : RTC::BAD_PARAMETER;
}

} // namespace

class TestManagerLive : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cleanupTestCase();

    void masterServesAndRegisters();
    void dataFlow_data();
    void dataFlow();
    void createParametersInAnyOrder();
    void configurationThroughManager();
    void deleteComponent();
    void badRequests_data();
    void badRequests();
    void refusalsAreKeptByRequest();
    void createsInOneCall();
    void killedSlaveLeavesOthersWorking();
    void loadModule();
    void loadableModulesNameTheirTypes();
    void modulesOutsideTheLoadPathRefused();
    void remoteConfigurationCannotChooseCode();
    void limitsRefuseRunawayClients();
    void connectionsBeyondTheLimitAreClosed();
    void undecodableReferencesLeaveNoTrace();
    void shutdownUnregisters();
    void slavesFollowKilledMaster();
    void startupKeys();
    void preconnectAndPreactivation();
    void namesReturnToARestartedNameServer();
    void commandLine();
    void shutdownWithoutComponents_data();
    void shutdownWithoutComponents();
    void masterKnownByAnyReference();
    void idleContextsDoNotTick();
    void forwardsToARestartedManagerOnAnotherHost();
    void sameHostPeersUseUnixSocket_data();
    void sameHostPeersUseUnixSocket();
    void oneNameServerConnectionPerProcess();
    void registrationsSideBySideMakeContextsOnce();
    void slavesStartedSideBySideServeOneConnection();
    void startedProcessesAreCalledRtmanager();
    void startedSlavesStayOutOfNaming();
    void slaveFoundByItsExpandedName();

private:
    /// rtmanager as the master; a non-empty @p environment replaces this process's for it.
    RTM::Manager_ptr startMaster(QString *error, QProcess **process = nullptr, const QStringList &extra = {},
                                 const QProcessEnvironment &environment = {});
    /// Stops the name server and master of init() and starts new ones, the master with @p extra.
    void restartMaster(const QStringList &extra, const QProcessEnvironment &environment = {});
    RTC::RTObject_ptr create(const QString &request);
    QString lastError(RTM::Manager_ptr manager);
    CORBA::Object_ptr resolve(const QString &path);
    void connect(RTC::PortService_ptr out, RTC::PortService_ptr in, const QString &flow, const QString &subscription);
    qint64 slavePid(const QString &name);

    CORBA::ORB_var m_orb;
    std::unique_ptr<LiveTest::LiveSystem> m_live;
    RTM::Manager_var m_master;
    QProcess *m_masterProcess = nullptr;
    quint16 m_masterPort = 0;
};

void TestManagerLive::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    // Creating on a new slave starts a process: allow for it, but never wait forever.
    omniORB::setClientCallTimeout(20000);
    omniORB::setClientConnectTimeout(3000);
}

void TestManagerLive::init()
{
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startNameServer(&error), qPrintable(error));
    m_master = startMaster(&error, &m_masterProcess);
    QVERIFY2(!CORBA::is_nil(m_master), qPrintable(error));
}

void TestManagerLive::cleanup()
{
    m_master = RTM::Manager::_nil();
    m_live.reset(); // kills rtmanager (its slaves follow it) and omniNames
}

void TestManagerLive::cleanupTestCase()
{
    m_orb->destroy();
}

RTM::Manager_ptr TestManagerLive::startMaster(QString *error, QProcess **process, const QStringList &extra,
                                              const QProcessEnvironment &environment)
{
    m_masterPort = LiveTest::freePort();
    // `extra` last: its keys override these.
    const QStringList args = QStringList{"-f", RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/manager/rtc.conf"),
                              "-o", QString("corba.endpoints=127.0.0.1:%1").arg(m_masterPort),
                              "-o", "corba.nameservers=" + m_live->namingServer(),
                              "-o", QStringLiteral("manager.modules.load_path=") + MANAGER_TEST_MODULE_DIR}
                             + extra;
    QProcess *started = m_live->startProcess(RTMANAGER_PATH, args, "rtmanager ready", error, 20000, environment);
    if (!started)
        return RTM::Manager::_nil();
    if (process)
        *process = started;
    CORBA::Object_var object
        = m_orb->string_to_object(LiveTest::managerLocation(m_masterPort).constData());
    return RTM::Manager::_narrow(object);
}

void TestManagerLive::restartMaster(const QStringList &extra, const QProcessEnvironment &environment)
{
    cleanup();
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startNameServer(&error), qPrintable(error));
    m_master = startMaster(&error, &m_masterProcess, extra, environment);
    QVERIFY2(!CORBA::is_nil(m_master), qPrintable(error));
}

RTC::RTObject_ptr TestManagerLive::create(const QString &request)
{
    return m_master->create_component(request.toUtf8().constData());
}

QString TestManagerLive::lastError(RTM::Manager_ptr manager)
{
    RTM::ManagerProfile_var profile = manager->get_profile();
    return nv(profile->properties, "last_error");
}

CORBA::Object_ptr TestManagerLive::resolve(const QString &path)
{
    CORBA::Object_var object = m_orb->string_to_object(
        QString("corbaloc:iiop:%1/NameService").arg(m_live->namingServer()).toUtf8().constData());
    CosNaming::NamingContext_var root = CosNaming::NamingContext::_narrow(object);
    const QStringList parts = path.split('/');
    CosNaming::Name name;
    name.length(CORBA::ULong(parts.size()));
    for (int i = 0; i < parts.size(); ++i) {
        const int dot = parts[i].lastIndexOf('.');
        name[CORBA::ULong(i)].id = parts[i].left(dot).toUtf8().constData();
        name[CORBA::ULong(i)].kind = parts[i].mid(dot + 1).toUtf8().constData();
    }
    try {
        return root->resolve(name);
    } catch (const CosNaming::NamingContext::NotFound &) {
        return CORBA::Object::_nil();
    }
}

void TestManagerLive::connect(RTC::PortService_ptr out, RTC::PortService_ptr in, const QString &flow,
                              const QString &subscription)
{
    RTC::ConnectorProfile profile;
    profile.name = "live";
    profile.connector_id = "";
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(out);
    profile.ports[1] = RTC::PortService::_duplicate(in);
    setNv(profile.properties, "dataport.interface_type", "corba_cdr");
    setNv(profile.properties, "dataport.dataflow_type", flow);
    setNv(profile.properties, "dataport.subscription_type", subscription);
    setNv(profile.properties, "dataport.data_type", "IDL:RTC/TimedLong:1.0");
    setNv(profile.properties, "dataport.publisher.push_rate", "100");
    QCOMPARE(out->connect(profile), RTC::RTC_OK);
}

qint64 TestManagerLive::slavePid(const QString &name)
{
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    for (CORBA::ULong i = 0; i < slaves->length(); ++i) {
        RTM::ManagerProfile_var profile = slaves[i]->get_profile();
        if (nv(profile->properties, "instance_name") == name)
            return nv(profile->properties, "pid").toLongLong();
    }
    return 0;
}

void TestManagerLive::masterServesAndRegisters()
{
    QVERIFY(m_master->is_master());
    RTM::ManagerProfile_var profile = m_master->get_profile();
    QCOMPARE(nv(profile->properties, "address"), QString("127.0.0.1:%1").arg(m_masterPort));
    // As OpenRTM-aist's, the profile holds the configuration's manager.* keys without the prefix.
    QCOMPARE(nv(profile->properties, "naming_formats"), QString("%h.host_cxt/%n.mgr"));
    QCOMPARE(nv(profile->properties, "modules.load_path"), MANAGER_TEST_MODULE_DIR);
    QCOMPARE(nv(profile->properties, "slave_check_interval"), QString("200"));
    QCOMPARE(nv(profile->properties, "pid"), QString::number(m_masterProcess->processId()));
    for (CORBA::ULong i = 0; i < profile->properties.length(); ++i) {
        const QByteArray key(profile->properties[i].name.in());
        QVERIFY2(!key.startsWith("manager.") && !key.startsWith("corba.")
                     && !key.startsWith("exec_cxt."),
                 key.constData());
    }
    RTM::NVList_var config = m_master->get_configuration();
    QCOMPARE(nv(config.in(), "exec_cxt.periodic.rate"), QString("200")); // from the rtc.conf file
    QCOMPARE(m_master->set_configuration("user.key", "v"), RTC::RTC_OK);
    config = m_master->get_configuration();
    QCOMPARE(nv(config.in(), "user.key"), QString("v"));
    const QString host = localHost();
    CORBA::Object_var named = resolve(host + ".host_cxt/manager.mgr");
    QVERIFY(!CORBA::is_nil(named));
    QVERIFY(Runtime::sameObject(named, m_master));
    RTM::ModuleProfileList_var factories = m_master->get_factory_profiles();
    QStringList types;
    for (CORBA::ULong i = 0; i < factories->length(); ++i)
        types << nv(factories[i].properties, "implementation_id");
    for (const char *type : {"ConsoleIn", "ConsoleOut", "Sensor", "Controller", "Motor", "SeqOut", "SeqIn",
                             "MyServiceProvider", "MyServiceConsumer", "ConfigSample"})
        QVERIFY2(types.contains(type), type);
}

void TestManagerLive::dataFlow_data()
{
    QTest::addColumn<QString>("flow");
    QTest::addColumn<QString>("subscription");
    QTest::addColumn<bool>("slaves");
    for (bool slaves : {false, true}) {
        const char *where = slaves ? "two slaves" : "one process";
        for (const char *subscription : {"flush", "new", "periodic"})
            QTest::addRow("%s, push %s", where, subscription) << "push" << subscription << slaves;
        QTest::addRow("%s, pull", where) << "pull" << "" << slaves;
    }
}

void TestManagerLive::dataFlow()
{
    QFETCH(QString, flow);
    QFETCH(QString, subscription);
    QFETCH(bool, slaves);
    RTC::RTObject_var source = create(slaves ? "ConsoleIn?manager_name=slaveA" : "ConsoleIn");
    QVERIFY2(!CORBA::is_nil(source), qPrintable(lastError(m_master)));
    RTC::RTObject_var sink = create(slaves ? "ConsoleOut?manager_name=slaveB" : "ConsoleOut");
    QVERIFY2(!CORBA::is_nil(sink), qPrintable(lastError(m_master)));
    RTM::ManagerList_var slaveList = m_master->get_slave_managers();
    QCOMPARE(slaveList->length(), CORBA::ULong(slaves ? 2 : 0));

    RTC::PortService_var out = port(source, "out");
    RTC::PortService_var in = port(sink, "in");
    connect(out, in, flow, subscription);
    QCOMPARE(activate(sink), RTC::RTC_OK);
    QCOMPARE(activate(source), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(status(sink, "received_count") > 20, 10000);
    const long last = statusText(sink, "last_value").toLong();
    QVERIFY(last > 0);
    QVERIFY(last <= status(source, "sent_count"));

    // Components live where they were asked to.
    const QString host = localHost();
    CORBA::Object_var named = resolve(host + ".host_cxt/ConsoleOut0.rtc");
    QVERIFY(!CORBA::is_nil(named));
    // The master lists its slaves' components too; the slaves hold exactly theirs.
    RTC::RTCList_var all = m_master->get_components();
    QCOMPARE(all->length(), CORBA::ULong(2));
    CORBA::ULong onSlaves = 0;
    for (CORBA::ULong i = 0; i < slaveList->length(); ++i)
        onSlaves += RTC::RTCList_var(slaveList[i]->get_components())->length();
    QCOMPARE(onSlaves, CORBA::ULong(slaves ? 2 : 0));
}

void TestManagerLive::createParametersInAnyOrder()
{
    RTC::RTObject_var first =
        create("ConsoleIn?instance_name=early&exec_cxt.periodic.rate=50&manager_name=slaveP");
    QVERIFY2(!CORBA::is_nil(first), qPrintable(lastError(m_master)));
    RTC::RTObject_var second =
        create("ConsoleIn?manager_name=slaveP&exec_cxt.periodic.rate=25&instance_name=late");
    QVERIFY2(!CORBA::is_nil(second), qPrintable(lastError(m_master)));
    RTC::RTObject_var third = create("ConsoleIn?exec_cxt.periodic.rate=40&manager_name=slaveP&instance_name=mid");
    QVERIFY2(!CORBA::is_nil(third), qPrintable(lastError(m_master)));
    // All three went to the one slave named slaveP.
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(1));
    RTC::RTCList_var onSlave = slaves[0]->get_components();
    QCOMPARE(onSlave->length(), CORBA::ULong(3));
    RTC::ComponentProfile_var profile = first->get_component_profile();
    QCOMPARE(QByteArray(profile->instance_name), QByteArray("early"));
    profile = second->get_component_profile();
    QCOMPARE(QByteArray(profile->instance_name), QByteArray("late"));
    RTC::ExecutionContextList_var ecs = second->get_owned_contexts();
    QCOMPARE(ecs[0]->get_rate(), 25.0);
    ecs = third->get_owned_contexts();
    QCOMPARE(ecs[0]->get_rate(), 40.0);
    QVERIFY(!slaves[0]->is_master());
    RTM::ManagerList_var masters = slaves[0]->get_master_managers();
    QCOMPARE(masters->length(), CORBA::ULong(1));
    QVERIFY(Runtime::sameObject(masters[0], m_master));
    RTC::RTCList_var byName = slaves[0]->get_components_by_name("mid");
    QCOMPARE(byName->length(), CORBA::ULong(1));

    // The same via manager_address, the key first and last; a new slave starts on that port.
    const quint16 port = LiveTest::freePort();
    RTC::RTObject_var viaAddress =
        create(QString("ConsoleOut?manager_address=127.0.0.1:%1&instance_name=addr1").arg(port));
    QVERIFY2(!CORBA::is_nil(viaAddress), qPrintable(lastError(m_master)));
    RTC::RTObject_var viaAddressLast =
        create(QString("ConsoleOut?instance_name=addr2&manager_address=localhost:%1").arg(port));
    QVERIFY2(!CORBA::is_nil(viaAddressLast), qPrintable(lastError(m_master)));
    slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(2));
    QVERIFY(LiveTest::isListening(port));
    // Instance names stay unique per manager.
    RTC::RTObject_var duplicate = create("ConsoleIn?instance_name=early&manager_name=slaveP");
    QVERIFY(CORBA::is_nil(duplicate));
    QVERIFY2(lastError(m_master).contains("already in use"), qPrintable(lastError(m_master)));
}

void TestManagerLive::configurationThroughManager()
{
    RTC::RTObject_var sample = create("ConfigSample?conf.default.int_param0=7&conf.mode0.str_param1=given");
    QVERIFY2(!CORBA::is_nil(sample), qPrintable(lastError(m_master)));
    QCOMPARE(statusText(sample, "int_param0"), QString("7"));
    SDOPackage::Configuration_var config = sample->get_configuration();
    SDOPackage::ConfigurationSet_var mode0 = config->get_configuration_set("mode0");
    QCOMPARE(nv(mode0->configuration_data, "str_param1"), QString("given"));
    QCOMPARE(activate(sample), RTC::RTC_OK);
    QVERIFY(config->activate_configuration_set("mode1"));
    QTRY_COMPARE(statusText(sample, "str_param0"), QString("mode1"));
    SDOPackage::ConfigurationSet_var active = config->get_active_configuration_set();
    QCOMPARE(QByteArray(active->id), QByteArray("mode1"));

    // A component configuration file as OpenRTM's config_file key names it; the request still wins.
    RTC::RTObject_var fromFile = create(QStringLiteral("ConfigSample?config_file=") + RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/manager/configsample.conf&conf.default.int_param1=5"));
    QVERIFY2(!CORBA::is_nil(fromFile), qPrintable(lastError(m_master)));
    QCOMPARE(statusText(fromFile, "int_param0"), QString("99"));
    QCOMPARE(statusText(fromFile, "int_param1"), QString("5"));
    RTC::ExecutionContextList_var fileEcs = fromFile->get_owned_contexts();
    QCOMPARE(fileEcs[0]->get_rate(), 20.0);
    RTC::RTObject_var noFile = create("ConfigSample?config_file=/nonexistent.conf");
    QVERIFY(CORBA::is_nil(noFile));
    QVERIFY(lastError(m_master).contains("cannot read config_file"));

    RTC::RTObject_var motor = create("Motor?conf.default.motor_id=3&manager_name=slaveM");
    QVERIFY2(!CORBA::is_nil(motor), qPrintable(lastError(m_master)));
    SDOPackage::Configuration_var motorConfig = motor->get_configuration();
    SDOPackage::ConfigurationSet_var defaults = motorConfig->get_configuration_set("default");
    QCOMPARE(nv(defaults->configuration_data, "motor_id"), QString("3"));
}

void TestManagerLive::deleteComponent()
{
    RTC::RTObject_var a = create("ConsoleIn");
    RTC::RTObject_var b = create("ConsoleOut?instance_name=sink");
    QVERIFY(!CORBA::is_nil(a) && !CORBA::is_nil(b));
    const QString host = localHost();
    CORBA::Object_var named = resolve(host + ".host_cxt/sink.rtc");
    QVERIFY(!CORBA::is_nil(named));
    QCOMPARE(m_master->delete_component("sink"), RTC::RTC_OK);
    RTC::RTCList_var left = m_master->get_components();
    QCOMPARE(left->length(), CORBA::ULong(1));
    named = resolve(host + ".host_cxt/sink.rtc");
    QVERIFY(CORBA::is_nil(named));
    RTC::ComponentProfileList_var profiles = m_master->get_component_profiles();
    QCOMPARE(profiles->length(), CORBA::ULong(1));
    QCOMPARE(QByteArray(profiles[0].instance_name), QByteArray("ConsoleIn0"));
    // exit() on the component itself also removes it from its manager.
    QCOMPARE(a->exit(), RTC::RTC_OK);
    QTRY_COMPARE(RTC::RTCList_var(m_master->get_components())->length(), CORBA::ULong(0));
    // Both names are free again: the one asked for, and the lowest number of the type.
    RTC::RTObject_var sinkAgain = create("ConsoleOut?instance_name=sink");
    QVERIFY2(!CORBA::is_nil(sinkAgain), qPrintable(lastError(m_master)));
    RTC::RTObject_var numberedAgain = create("ConsoleIn");
    QVERIFY2(!CORBA::is_nil(numberedAgain), qPrintable(lastError(m_master)));
    QCOMPARE(QByteArray(
                 RTC::ComponentProfile_var(numberedAgain->get_component_profile())->instance_name),
             QByteArray("ConsoleIn0"));
}

void TestManagerLive::badRequests_data()
{
    QTest::addColumn<QString>("request");
    QTest::addColumn<QString>("message");
    QTest::newRow("two ?") << "ConsoleIn?a=1?b=2" << "more than one '?'";
    QTest::newRow("unknown type") << "NoSuchType" << "unknown component type 'NoSuchType'";
    QTest::newRow("malformed address") << "ConsoleIn?manager_address=nohost" << "malformed manager address";
    QTest::newRow("bad port") << "ConsoleIn?manager_address=127.0.0.1:70000" << "port out of range";
    QTest::newRow("unreachable address") << "ConsoleIn?manager_address=192.0.2.1:9" << "unreachable";
    QTest::newRow("unknown type on slave") << "NoSuchType?manager_name=slaveX" << "unknown component type";
    QTest::newRow("delete unknown") << "delete:ghost" << "no component named 'ghost'";
    QTest::newRow("load text file") << "load:notamodule.so" << "is not a loadable module";
    QTest::newRow("load missing") << "load:missing.so" << "no module file 'missing.so'";
}

void TestManagerLive::badRequests()
{
    QFETCH(QString, request);
    QFETCH(QString, message);
    if (request.startsWith("delete:")) {
        QCOMPARE(m_master->delete_component(request.mid(7).toUtf8().constData()), RTC::BAD_PARAMETER);
    } else if (request.startsWith("load:")) {
        // The text file is looked at in a load path of its own: a module from elsewhere is refused first.
        if (request.mid(5) == "notamodule.so")
            restartMaster({"-o", QStringLiteral("manager.modules.load_path=") + RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/manager")});
        QCOMPARE(m_master->load_module(request.mid(5).toUtf8().constData(), ""), RTC::BAD_PARAMETER);
    } else {
        QDeadlineTimer bound(10000);
        RTC::RTObject_var result = create(request);
        QVERIFY(CORBA::is_nil(result));
        QVERIFY(!bound.hasExpired());
    }
    QVERIFY2(lastError(m_master).contains(message), qPrintable(lastError(m_master)));
    // The manager keeps serving.
    RTC::RTObject_var fine = create("ConsoleIn");
    QVERIFY2(!CORBA::is_nil(fine), qPrintable(lastError(m_master)));
}

// Creates sent side by side each read why they were refused by their request text: last_error
// holds only the latest refusal of all.
void TestManagerLive::refusalsAreKeptByRequest()
{
    RTC::RTObject_var taken = create("ConsoleIn?instance_name=keptName");
    QVERIFY2(!CORBA::is_nil(taken), qPrintable(lastError(m_master)));
    const QString sameName = "ConsoleIn?instance_name=keptName";
    const QString unknownType = "NoSuchKeptType?instance_name=other";
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create(sameName))));
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create(unknownType))));
    const auto reasonOf = [this](const QString &request) {
        RTM::ManagerProfile_var profile = m_master->get_profile();
        return nv(profile->properties, ("rtstudio.create_error." + request).toUtf8().constData());
    };
    QVERIFY2(reasonOf(sameName).contains("'keptName' is already in use"), qPrintable(reasonOf(sameName)));
    QVERIFY2(reasonOf(unknownType).contains("NoSuchKeptType"), qPrintable(reasonOf(unknownType)));
    QVERIFY2(lastError(m_master).contains("NoSuchKeptType"), qPrintable(lastError(m_master)));

    // A refusal on a slave is kept on the master under the request as sent, with the slave's reason.
    RTC::RTObject_var far = create("ConsoleIn?instance_name=keptFar&manager_name=keptSlave");
    QVERIFY2(!CORBA::is_nil(far), qPrintable(lastError(m_master)));
    const QString farTaken = "ConsoleIn?instance_name=keptFar&manager_name=keptSlave";
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create(farTaken))));
    QVERIFY2(reasonOf(farTaken).contains("'keptFar' is already in use"), qPrintable(reasonOf(farTaken)));

    // A request too long to be a key has its reason in last_error only.
    const QString tooLong = "NoSuchKeptType?instance_name=" + QString(1100, 'x');
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create(tooLong))));
    QVERIFY(reasonOf(tooLong).isEmpty());
    QVERIFY2(lastError(m_master).contains("NoSuchKeptType"), qPrintable(lastError(m_master)));

    // The profile keeps the latest refusals only.
    for (int i = 0; i < 64; ++i)
        QVERIFY(CORBA::is_nil(RTC::RTObject_var(create(QString("NoSuchKeptType?instance_name=n%1").arg(i)))));
    QVERIFY(reasonOf(sameName).isEmpty());
    QVERIFY(!reasonOf("NoSuchKeptType?instance_name=n63").isEmpty());
}

// RTStudio::Manager's create_components: creates in one call as one after the other would, up to
// the first refusal. The manager's references still name RTM::Manager, as OpenRTM-aist's do.
void TestManagerLive::createsInOneCall()
{
    CORBA::Object_var named = resolve(localHost() + ".host_cxt/manager.mgr");
    CORBA::String_var ior = m_orb->object_to_string(named);
    // An IOR's encapsulation: byte order, three octets of padding, the repository id's length, the
    // id.
    const QByteArray encapsulation = QByteArray::fromHex(QByteArray(ior.in()).mid(4));
    QCOMPARE(encapsulation.mid(8, 20), QByteArray("IDL:RTM/Manager:1.0", 20));
    QVERIFY(m_master->_is_a(RTStudio::Manager::_PD_repoId));

    RTStudio::Manager_var manager = RTStudio::Manager::_unchecked_narrow(m_master);
    const auto requests = [](const QStringList &texts) {
        RTStudio::CreateRequestList list;
        list.length(CORBA::ULong(texts.size()));
        for (CORBA::ULong i = 0; i < list.length(); ++i)
            list[i] = texts.at(int(i)).toUtf8().constData();
        return list;
    };
    const QString host = localHost();
    CORBA::String_var error;
    RTC::RTCList_var made = manager->create_components(
        requests({"ConsoleIn?instance_name=Batch0", "ConsoleOut?instance_name=Batch1",
                  "ConsoleIn?instance_name=Batch2&manager_name=batchslave", "ConsoleIn"}),
        error.out());
    QCOMPARE(made->length(), 4u);
    QCOMPARE(QString(error.in()), QString());
    const QStringList names {"Batch0", "Batch1", "Batch2", "ConsoleIn0"};
    for (CORBA::ULong i = 0; i < made->length(); ++i) {
        RTC::ComponentProfile_var profile = made[i]->get_component_profile();
        QCOMPARE(QString(profile->instance_name.in()), names.at(int(i)));
        // Registered when the call returns, as create_component's are.
        CORBA::Object_var bound = resolve(host + ".host_cxt/" + names.at(int(i)) + ".rtc");
        QVERIFY2(!CORBA::is_nil(bound), qPrintable(names.at(int(i))));
        QVERIFY(Runtime::sameObject(bound, made[i]));
    }

    // The first refusal ends the call: what came before stays, what comes after is not tried.
    made = manager->create_components(
        requests({"ConsoleIn?instance_name=Batch3", "NoSuchType?instance_name=Batch4",
                  "ConsoleIn?instance_name=Batch5"}),
        error.out());
    QCOMPARE(made->length(), 1u);
    QVERIFY2(QString(error.in()).contains("unknown component type 'NoSuchType'"), error.in());
    QVERIFY(!CORBA::is_nil(CORBA::Object_var(resolve(host + ".host_cxt/Batch3.rtc"))));
    QVERIFY(CORBA::is_nil(CORBA::Object_var(resolve(host + ".host_cxt/Batch5.rtc"))));
    RTC::RTCList_var after = m_master->get_components_by_name("Batch5");
    QCOMPARE(after->length(), 0u);
    made = manager->create_components(requests({"ConsoleIn?instance_name=Batch3"}), error.out());
    QCOMPARE(made->length(), 0u);
    QVERIFY2(QString(error.in()).contains("'Batch3' is already in use"), error.in());
    made = manager->create_components(requests({}), error.out());
    QCOMPARE(made->length(), 0u);
    QCOMPARE(QString(error.in()), QString());
}

void TestManagerLive::killedSlaveLeavesOthersWorking()
{
    RTC::RTObject_var doomed = create("ConsoleIn?manager_name=slaveK");
    RTC::RTObject_var source = create("ConsoleIn?manager_name=slaveL");
    RTC::RTObject_var sink = create("ConsoleOut?manager_name=slaveL");
    QVERIFY(!CORBA::is_nil(doomed) && !CORBA::is_nil(source) && !CORBA::is_nil(sink));
    const qint64 pid = slavePid("slaveK");
    QVERIFY(pid > 0);
    QCOMPARE(::kill(pid_t(pid), SIGKILL), 0);
    QTRY_COMPARE_WITH_TIMEOUT(RTM::ManagerList_var(m_master->get_slave_managers())->length(), CORBA::ULong(1),
                              10000);
    QCOMPARE(slavePid("slaveK"), 0);
    // The other slave still hosts working components.
    connect(port(source, "out"), port(sink, "in"), "push", "flush");
    QCOMPARE(activate(sink), RTC::RTC_OK);
    QCOMPARE(activate(source), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(status(sink, "received_count") > 10, 10000);
    // And the master still creates, also on a new slave of the dead one's name.
    RTC::RTObject_var local = create("ConsoleIn");
    QVERIFY(!CORBA::is_nil(local));
    RTC::RTObject_var reborn = create("ConsoleIn?manager_name=slaveK");
    QVERIFY2(!CORBA::is_nil(reborn), qPrintable(lastError(m_master)));
    QVERIFY(slavePid("slaveK") != pid);
}

void TestManagerLive::loadModule()
{
    RTM::ModuleProfileList_var loadable = m_master->get_loadable_modules();
    bool listed = false;
    for (CORBA::ULong i = 0; i < loadable->length(); ++i)
        listed = listed || nv(loadable[i].properties, "module_file_name") == "ManagerTestModule.so";
    QVERIFY(listed);
    QCOMPARE(m_master->load_module("ManagerTestModule", ""), RTC::RTC_OK);
    RTM::ModuleProfileList_var loaded = m_master->get_loaded_modules();
    QCOMPARE(loaded->length(), CORBA::ULong(1));
    QVERIFY(nv(loaded[0].properties, "file_path").endsWith("ManagerTestModule.so"));
    QCOMPARE(nv(loaded[0].properties, "init_function"), QString("ManagerTestModuleInit"));
    QCOMPARE(m_master->load_module("ManagerTestModule", ""), RTC::BAD_PARAMETER);
    QVERIFY(lastError(m_master).contains("already loaded"));

    RTC::RTObject_var counter = create("RTC:RTStudioTests:example:ModuleCounter:C++:2.0.0");
    QVERIFY2(!CORBA::is_nil(counter), qPrintable(lastError(m_master)));
    QCOMPARE(activate(counter), RTC::RTC_OK);
    QTRY_VERIFY(status(counter, "sent_count") > 3);

    QCOMPARE(m_master->unload_module((MANAGER_TEST_MODULE_DIR + QStringLiteral("/ManagerTestModule.so")).toUtf8().constData()),
             RTC::RTC_OK);
    loaded = m_master->get_loaded_modules();
    QCOMPARE(loaded->length(), CORBA::ULong(0));
    RTM::ModuleProfileList_var factories = m_master->get_factory_profiles();
    for (CORBA::ULong i = 0; i < factories->length(); ++i)
        QVERIFY(nv(factories[i].properties, "implementation_id") != "ModuleCounter");
    QCOMPARE(m_master->load_module(qPrintable(MANAGER_TEST_MODULE_DIR + QStringLiteral("/ManagerTestModule.so")), "NoSuchInit"),
             RTC::BAD_PARAMETER);
    QVERIFY(lastError(m_master).contains("no init function 'NoSuchInit'"));
}

// A caller may not make the manager run any library on the machine: only modules in its module
// folders load unless manager.modules.abs_path_allowed says YES (OpenRTM-aist's key; its default
// is YES, ours NO).
void TestManagerLive::modulesOutsideTheLoadPathRefused()
{
    QTemporaryDir elsewhere;
    QVERIFY(elsewhere.isValid());
    const QString module = elsewhere.filePath("ManagerTestModule.so");
    QVERIFY(QFile::copy(MANAGER_TEST_MODULE_DIR + QStringLiteral("/ManagerTestModule.so"), module));
    const QByteArray path = module.toUtf8();
    QCOMPARE(m_master->load_module(path.constData(), ""), RTC::BAD_PARAMETER);
    QVERIFY2(lastError(m_master).contains("abs_path_allowed is NO"), qPrintable(lastError(m_master)));
    // Nor by a relative name leading out of the load path, nor by a create naming the file.
    const QByteArray outward = QDir(MANAGER_TEST_MODULE_DIR).relativeFilePath(module).toUtf8();
    QVERIFY(outward.startsWith("../"));
    QCOMPARE(m_master->load_module(outward.constData(), ""), RTC::BAD_PARAMETER);
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create(module.chopped(3)))));
    QCOMPARE(RTM::ModuleProfileList_var(m_master->get_loaded_modules())->length(), 0u);
    // The same file in the load path loads by its full path.
    QCOMPARE(m_master->load_module(qPrintable(MANAGER_TEST_MODULE_DIR + QStringLiteral("/ManagerTestModule.so")), ""), RTC::RTC_OK);

    restartMaster({"-o", "manager.modules.abs_path_allowed=YES"});
    QCOMPARE(m_master->load_module(path.constData(), ""), RTC::RTC_OK);
    RTM::ModuleProfileList_var loaded = m_master->get_loaded_modules();
    QCOMPARE(loaded->length(), 1u);
    QCOMPARE(nv(loaded[0].properties, "file_path"), module);
}

void TestManagerLive::remoteConfigurationCannotChooseCode()
{
    // What decides which code runs, where packages come from and how the manager is reached stays
    // as the manager's own configuration says.
    for (const char *key : {"manager.modules.load_path", "manager.modules.abs_path_allowed", "manager.modules.preload",
                            "manager.packages.keyring", "manager.components.precreate", "corba.args",
                            "example.ConsoleIn.config_file", "logger.file_name", "manager.slaves.max",
                            "manager.local_service.modules", "manager.is_master",
                            "corba.ssl.certificate_authority_file", "corba.ssl.key_file"}) {
        QCOMPARE(m_master->set_configuration(key, "/tmp"), RTC::BAD_PARAMETER);
        QVERIFY2(lastError(m_master).contains(QString("'%1' is taken from the manager's own configuration").arg(key)),
                 qPrintable(lastError(m_master)));
    }
    RTM::NVList_var config = m_master->get_configuration();
    QCOMPARE(nv(config, "manager.modules.load_path"), MANAGER_TEST_MODULE_DIR);
    QCOMPARE(nv(config, "manager.modules.abs_path_allowed"), QString());
    // Other keys stay settable, as in OpenRTM-aist.
    QCOMPARE(m_master->set_configuration("manager.naming_formats", "%h.host_cxt/%n.mgr"), RTC::RTC_OK);
}

void TestManagerLive::limitsRefuseRunawayClients()
{
    restartMaster({"-o", "manager.components.max=3", "-o", "manager.slaves.max=1"});
    const CORBA::ULong before = RTC::RTCList_var(m_master->get_components())->length();
    QVERIFY(before < 3);
    for (CORBA::ULong n = before; n < 3; ++n)
        QVERIFY2(!CORBA::is_nil(RTC::RTObject_var(create("ConsoleIn"))), qPrintable(lastError(m_master)));
    // The next one is refused with the reason; the manager serves on and takes one again when
    // one goes.
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create("ConsoleIn"))));
    QVERIFY2(lastError(m_master).contains("hosts 3 components, as many as manager.components.max allows"),
             qPrintable(lastError(m_master)));
    QCOMPARE(RTC::RTCList_var(m_master->get_components())->length(), 3u);
    QCOMPARE(m_master->delete_component("ConsoleIn0"), RTC::RTC_OK);
    QVERIFY2(!CORBA::is_nil(RTC::RTObject_var(create("ConsoleIn"))), qPrintable(lastError(m_master)));

    // One slave may run; a second is refused, the first keeps taking components.
    QCOMPARE(m_master->delete_component("ConsoleIn1"), RTC::RTC_OK);
    QVERIFY2(!CORBA::is_nil(RTC::RTObject_var(create("ConsoleOut?manager_name=first"))), qPrintable(lastError(m_master)));
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create("ConsoleOut?manager_name=second"))));
    QVERIFY2(lastError(m_master).contains("runs 1 slaves, as many as manager.slaves.max allows"),
             qPrintable(lastError(m_master)));
    QCOMPARE(RTM::ManagerList_var(m_master->get_slave_managers())->length(), 1u);
    QVERIFY2(!CORBA::is_nil(RTC::RTObject_var(create("ConsoleOut?manager_name=first"))), qPrintable(lastError(m_master)));
}

void TestManagerLive::connectionsBeyondTheLimitAreClosed()
{
    restartMaster({"-o", "corba.max_connections=4"});
    // This test's ORB holds one of the four connections.
    QCOMPARE(m_master->is_master(), CORBA::Boolean(true));
    std::vector<std::unique_ptr<QTcpSocket>> sockets;
    for (int i = 0; i < 6; ++i) {
        sockets.push_back(std::make_unique<QTcpSocket>());
        sockets.back()->connectToHost(QHostAddress::LocalHost, m_masterPort);
        QVERIFY(sockets.back()->waitForConnected(5000));
    }
    // The manager closes those beyond four as it accepts them; three of these stay open.
    const auto count = [&sockets](QAbstractSocket::SocketState state) {
        return std::count_if(sockets.begin(), sockets.end(), [state](const auto &s) { return s->state() == state; });
    };
    QTRY_COMPARE_WITH_TIMEOUT(count(QAbstractSocket::UnconnectedState), 3, 5000);
    QCOMPARE(count(QAbstractSocket::ConnectedState), 3);
    // It serves on over the connection it had.
    QCOMPARE(m_master->is_master(), CORBA::Boolean(true));
}

// omniORB 4.2.5 refuses a reference whose profile does not decode with MARSHAL and loses it, with
// every byte of its profile: a peer repeating such requests grew the manager's memory without end.
// The manager takes such a reference as one to no object instead.
void TestManagerLive::undecodableReferencesLeaveNoTrace()
{
    // This process makes such references the same way, so that it can send one.
    Corba::ReferenceGuard::install();
    const QByteArray text = LiveTest::undecodableReference(128 * 1024);
    CORBA::Object_var undecodable = m_orb->string_to_object(text.constData());
    QVERIFY(!CORBA::is_nil(undecodable));
    QVERIFY(undecodable->_non_existent());
    RTC::LightweightRTObject_var component = RTC::LightweightRTObject::_unchecked_narrow(undecodable);
    QVERIFY_THROWS_EXCEPTION(CORBA::OBJECT_NOT_EXIST, component->is_alive(RTC::ExecutionContext::_nil()));

    // Under AddressSanitizer freed memory waits in a quarantine (256 MiB) before it is used again:
    // without it the manager's memory shows only what it keeps.
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("ASAN_OPTIONS", environment.value("ASAN_OPTIONS") + ":quarantine_size_mb=0");
    restartMaster({}, environment);
    RTC::RTObject_var rtc = create("ConsoleIn");
    QVERIFY2(!CORBA::is_nil(rtc), qPrintable(lastError(m_master)));
    RTC::ExecutionContextList_var contexts = rtc->get_owned_contexts();
    QCOMPARE(contexts->length(), 1u);
    const qint64 before = LiveTest::residentKiB(m_masterProcess->processId());
    QVERIFY(before > 0);
    // 1,000 requests carrying 128 KiB each: 128 MiB if the manager kept what it read.
    for (int i = 0; i < 1000; ++i) {
        try {
            QCOMPARE(contexts[0]->remove_component(component), RTC::BAD_PARAMETER);
        } catch (const CORBA::Exception &e) {
            const QString reason = QString::fromStdString(Runtime::describeException(e));
            QFAIL(qPrintable(QString("request %1: %2").arg(i).arg(reason)));
        }
    }
    const qint64 after = LiveTest::residentKiB(m_masterProcess->processId());
    QVERIFY2(after - before < 32 * 1024,
             qPrintable(QString("the manager grew from %1 KiB to %2 KiB").arg(before).arg(after)));
    QCOMPARE(m_master->delete_component(RTC::ComponentProfile_var(rtc->get_component_profile())->instance_name),
             RTC::RTC_OK);
}

// As OpenRTM-aist's: a loadable module is listed by the component types its init function
// registers (found by loading it in a process of its own), a library without one is not listed.
void TestManagerLive::loadableModulesNameTheirTypes()
{
    QTemporaryDir modules;
    QVERIFY(modules.isValid());
    const QString module = modules.filePath("ManagerTestModule.so");
    QVERIFY(QFile::copy(MANAGER_TEST_MODULE_DIR + QStringLiteral("/ManagerTestModule.so"), module));
    QVERIFY(QFile::copy(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/manager/notamodule.so"),
                        modules.filePath("notamodule.so")));
    restartMaster({"-o", "manager.modules.load_path=" + modules.path()});
    RTM::ModuleProfileList_var loadable = m_master->get_loadable_modules();
    QCOMPARE(loadable->length(), 1u);
    const SDOPackage::NVList &profile = loadable[0].properties;
    QCOMPARE(nv(profile, "implementation_id"), QString("ModuleCounter"));
    QCOMPARE(nv(profile, "type_name"), QString("ModuleCounter"));
    QCOMPARE(nv(profile, "vendor"), QString("RTStudioTests"));
    QCOMPARE(nv(profile, "language"), QString("C++"));
    QCOMPARE(nv(profile, "module_file_name"), QString("ManagerTestModule.so"));
    QCOMPARE(nv(profile, "module_file_path"), module);
    // Listing ran the module elsewhere: it is not loaded here.
    QCOMPARE(RTM::ModuleProfileList_var(m_master->get_loaded_modules())->length(), 0u);
    // A type a listed module registers is created by loading that module (the file is not named
    // after the type).
    RTC::RTObject_var found = create("ModuleCounter?instance_name=Found0");
    QVERIFY2(!CORBA::is_nil(found), qPrintable(lastError(m_master)));
    RTM::ModuleProfileList_var loaded = m_master->get_loaded_modules();
    QCOMPARE(loaded->length(), 1u);
    QCOMPARE(nv(loaded[0].properties, "file_path"), module);
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(create("NoSuchModuleType"))));

    // A file that changes is looked at again.
    QVERIFY(QFile::remove(module));
    QVERIFY(QFile::copy(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/manager/notamodule.so"), module));
    QCOMPARE(RTM::ModuleProfileList_var(m_master->get_loadable_modules())->length(), 0u);

    // A module whose init function does not return is given manager.modules.profile_timeout.
    m_live.reset();
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startNameServer(&error), qPrintable(error));
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("MANAGER_TEST_MODULE_INIT_DELAY_MS", "60000");
    const quint16 port = LiveTest::freePort();
    QProcess *hanging = m_live->startProcess(
        RTMANAGER_PATH,
        {"-o", QString("corba.endpoints=127.0.0.1:%1").arg(port), "-o",
         "corba.nameservers=" + m_live->namingServer(), "-o",
         QStringLiteral("manager.modules.load_path=") + MANAGER_TEST_MODULE_DIR, "-o",
         "manager.modules.profile_timeout=300"},
        "rtmanager ready", &error, 10000, environment);
    QVERIFY2(hanging, qPrintable(error));
    CORBA::Object_var object = m_orb->string_to_object(LiveTest::managerLocation(port).constData());
    RTM::Manager_var manager = RTM::Manager::_narrow(object);
    QElapsedTimer timer;
    timer.start();
    QCOMPARE(RTM::ModuleProfileList_var(manager->get_loadable_modules())->length(), 0u);
    QVERIFY2(timer.elapsed() < 5000, qPrintable(QString::number(timer.elapsed())));
    // Nothing of it is left running.
    QTRY_COMPARE(QProcess::execute("pgrep", {"-f", QStringLiteral("module-profile ") + MANAGER_TEST_MODULE_DIR}), 1);
}

void TestManagerLive::shutdownUnregisters()
{
    RTC::RTObject_var local = create("ConsoleIn?instance_name=bye");
    RTC::RTObject_var remote = create("ConsoleIn?instance_name=far&manager_name=slaveS");
    QVERIFY(!CORBA::is_nil(local) && !CORBA::is_nil(remote));
    const qint64 slave = slavePid("slaveS");
    QVERIFY(slave > 0);
    const QString host = localHost();
    QCOMPARE(m_master->shutdown(), RTC::RTC_OK);
    QVERIFY(m_masterProcess->waitForFinished(10000));
    QCOMPARE(m_masterProcess->exitStatus(), QProcess::NormalExit);
    QCOMPARE(m_masterProcess->exitCode(), 0);
    CORBA::Object_var named = resolve(host + ".host_cxt/bye.rtc");
    QVERIFY(CORBA::is_nil(named));
    named = resolve(host + ".host_cxt/manager.mgr");
    QVERIFY(CORBA::is_nil(named));
    // The slave was shut down with its master and took its names along.
    QTRY_VERIFY_WITH_TIMEOUT(!processRuns(slave), 10000);
    named = resolve(host + ".host_cxt/far.rtc");
    QVERIFY(CORBA::is_nil(named));
}

void TestManagerLive::slavesFollowKilledMaster()
{
    RTC::RTObject_var remote = create("ConsoleIn?manager_name=slaveZ");
    QVERIFY(!CORBA::is_nil(remote));
    const qint64 slave = slavePid("slaveZ");
    QVERIFY(processRuns(slave));
    m_live->stop(m_masterProcess); // SIGKILL: no chance to shut its slaves down
    QTRY_VERIFY_WITH_TIMEOUT(!processRuns(slave), 10000);
}

void TestManagerLive::startupKeys()
{
    QString error;
    RTM::Manager_var other = startMaster(&error, nullptr,
                                         {"-o", "manager.preload.modules=ManagerTestModule",
                                          "-o", "manager.components.precreate=ConsoleIn,ModuleCounter?instance_name=pre",
                                          "-o", "manager.instance_name=other"});
    QVERIFY2(!CORBA::is_nil(other), qPrintable(error));
    RTM::ModuleProfileList_var loaded = other->get_loaded_modules();
    QCOMPARE(loaded->length(), CORBA::ULong(1));
    RTC::RTCList_var components = other->get_components();
    QCOMPARE(components->length(), CORBA::ULong(2));
    RTC::RTCList_var pre = other->get_components_by_name("pre");
    QCOMPARE(pre->length(), CORBA::ULong(1));
    CORBA::Object_var named = resolve(localHost() + ".host_cxt/other.mgr");
    QVERIFY(!CORBA::is_nil(named));
}

void TestManagerLive::preconnectAndPreactivation()
{
    // rtc.conf's preconnect and preactivation as OpenRTM-aist's manager reads them: the components
    // precreate made are connected (by instance name and by naming address, with the connector's
    // properties) and activated before the manager reports ready; entries naming what is not there are
    // reported one by one, and the others still made.
    const QString byName = QStringLiteral("ConsoleIn0.out?port=ConsoleOut0.in&subscription_type=flush");
    const QString byAddress = QStringLiteral("ConsoleIn0.out?port=rtcname://%1/%2.host_cxt/ConsoleOut1.in")
                                  .arg(m_live->namingServer(), localHost());
    // OpenRTM-aist 1.x's form, which older rtc.conf files use.
    const QString oldForm = QStringLiteral("ConsoleIn0.out^ConsoleOut2.in(dataflow_type=push&subscription_type=new)");
    const QStringList entries{byName, byAddress, oldForm, "Missing0.out?port=ConsoleOut0.in",
                              "ConsoleIn0.nosuch?port1=ConsoleOut0.in"};
    QString error;
    QProcess *process = nullptr;
    m_live->setErrorsRead(true);
    RTM::Manager_var other = startMaster(&error, &process,
                                         {"-o", "manager.components.precreate=ConsoleIn,ConsoleOut,ConsoleOut,ConsoleOut",
                                          "-o", "manager.components.preconnect=" + entries.join(", "),
                                          "-o", "manager.components.preactivation=ConsoleOut0, ConsoleOut1,ConsoleOut2,ConsoleIn0,Nobody0",
                                          "-o", "manager.instance_name=other"});
    m_live->setErrorsRead(false);
    QVERIFY2(!CORBA::is_nil(other), qPrintable(error));
    const QByteArray printed = m_live->printedWhileStarting(process);
    QVERIFY2(printed.contains("manager.components.preconnect: Missing0.out?port=ConsoleOut0.in: no component Missing0"),
             printed.constData());
    QVERIFY2(printed.contains("ConsoleIn0.nosuch?port1=ConsoleOut0.in: ConsoleIn0 has no port ConsoleIn0.nosuch"),
             printed.constData());
    QVERIFY2(printed.contains("manager.components.preactivation: Nobody0: no such component"), printed.constData());
    QVERIFY2(printed.count("manager.components.pre") == 3, printed.constData());

    RTC::RTCList_var source = other->get_components_by_name("ConsoleIn0");
    QCOMPARE(source->length(), CORBA::ULong(1));
    const QHash<QString, QString> connectorOf{{"ConsoleOut0", byName}, {"ConsoleOut1", byAddress}, {"ConsoleOut2", oldForm}};
    for (const char *name : {"ConsoleOut0", "ConsoleOut1", "ConsoleOut2"}) {
        RTC::RTCList_var sink = other->get_components_by_name(name);
        QCOMPARE(sink->length(), CORBA::ULong(1));
        QTRY_VERIFY_WITH_TIMEOUT(status(sink[0], "received_count") > 5, 10000);
        // One connector each, named by its entry.
        RTC::PortService_var in = port(sink[0], "in");
        RTC::ConnectorProfileList_var connectors = in->get_connector_profiles();
        QCOMPARE(connectors->length(), CORBA::ULong(1));
        QCOMPARE(QString(connectors[0].name), connectorOf.value(name));
        if (QString(name) != "ConsoleOut1")
            QCOMPARE(nv(connectors[0].properties, "dataport.subscription_type"),
                     QString(name) == "ConsoleOut0" ? QString("flush") : QString("new"));
        QCOMPARE(nv(connectors[0].properties, "dataport.dataflow_type"), QString("push"));
        QCOMPARE(nv(connectors[0].properties, "dataport.interface_type"), QString("corba_cdr"));
    }
}

void TestManagerLive::namesReturnToARestartedNameServer()
{
    // OpenRTM-aist's naming.update.*: a name server that comes back empty gets the manager's name and
    // its components' names again within an interval; a component deleted meanwhile stays away.
    restartMaster({"-o", "naming.update.interval=0.2", "-o", "manager.instance_name=keeper"});
    RTC::RTObject_var kept = create("ConsoleIn?instance_name=kept");
    QVERIFY2(!CORBA::is_nil(kept), qPrintable(lastError(m_master)));
    RTC::RTObject_var deleted = create("ConsoleIn?instance_name=deleted");
    QVERIFY2(!CORBA::is_nil(deleted), qPrintable(lastError(m_master)));
    const QString context = localHost() + ".host_cxt/";
    const auto bound = [this, &context](const QString &name) {
        try {
            return !CORBA::is_nil(CORBA::Object_var(resolve(context + name)));
        } catch (const CORBA::Exception &) {
            return false; // the server is not back yet
        }
    };
    QVERIFY(bound("keeper.mgr") && bound("kept.rtc") && bound("deleted.rtc"));
    const auto restartNameServer = [this] {
        const quint16 port = m_live->namingPort();
        m_live->stop(m_live->nameServer());
        QString error;
        QVERIFY2(m_live->startNameServer(&error, port), qPrintable(error));
    };
    restartNameServer();
    QTRY_VERIFY_WITH_TIMEOUT(bound("keeper.mgr") && bound("kept.rtc") && bound("deleted.rtc"), 10000);
    QCOMPARE(m_master->delete_component("deleted"), RTC::RTC_OK);
    QVERIFY(!bound("deleted.rtc"));
    // Once more: the round that brings the manager's name back brings every name it still has.
    restartNameServer();
    QTRY_VERIFY_WITH_TIMEOUT(bound("keeper.mgr"), 10000);
    QVERIFY(bound("kept.rtc"));
    QVERIFY(!bound("deleted.rtc"));
}

void TestManagerLive::commandLine()
{
    // -d makes a master, -p picks its port; unknown arguments and unreadable files are refused.
    const quint16 port = LiveTest::freePort();
    QString error;
    QProcess *master = m_live->startProcess(RTMANAGER_PATH,
                                            {"-d", "-p", QString::number(port), "-o", "naming.enable=NO"},
                                            QString("rtmanager ready on 127.0.0.1:%1").arg(port), &error);
    QVERIFY2(master, qPrintable(error));
    CORBA::Object_var object = m_orb->string_to_object(LiveTest::managerLocation(port).constData());
    RTM::Manager_var manager = RTM::Manager::_narrow(object);
    QVERIFY(manager->is_master());

    // A manager that is not a master and finds no master runs on its own, quietly (a standalone
    // component program).
    m_live->setErrorsRead(true);
    QProcess *standalone = m_live->startProcess(
        RTMANAGER_PATH,
        {"-o", "naming.enable=NO", "-o", QStringLiteral("corba.master_manager=127.0.0.1:%1").arg(LiveTest::freePort())},
        QStringLiteral("rtmanager ready"), &error);
    m_live->setErrorsRead(false);
    QVERIFY2(standalone, qPrintable(error));
    QVERIFY2(!m_live->printedWhileStarting(standalone).contains("cannot join master"),
             m_live->printedWhileStarting(standalone).constData());
    m_live->stop(standalone);

    for (const QStringList &bad : {QStringList{"--bogus"}, QStringList{"-f", "/nonexistent/rtc.conf"},
                                   QStringList{"-o", "novalue"}}) {
        QProcess refused;
        refused.start(RTMANAGER_PATH, bad);
        QVERIFY(refused.waitForFinished(10000));
        QCOMPARE(refused.exitCode(), 2);
        QVERIFY(!refused.readAllStandardError().isEmpty());
    }
}

void TestManagerLive::shutdownWithoutComponents_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<bool>("deleteLast");
    QTest::newRow("shutdown_auto") << QStringList{"-o", "manager.shutdown_auto=YES", "-o",
                                                  "manager.auto_shutdown_duration=0.3"}
                                   << false;
    QTest::newRow("shutdown_on_nortcs") << QStringList{"-o", "manager.shutdown_on_nortcs=YES"} << true;
}

void TestManagerLive::shutdownWithoutComponents()
{
    QFETCH(QStringList, options);
    QFETCH(bool, deleteLast);
    const quint16 port = LiveTest::freePort();
    QString error;
    QStringList args = options;
    args << "-o" << QString("corba.endpoints=127.0.0.1:%1").arg(port) << "-o"
         << "corba.nameservers=" + m_live->namingServer() << "-o" << "manager.instance_name=lonely"
         << "-o" << "corba.master_manager="; // a manager of its own, joining no master
    if (deleteLast)
        args << "-o" << "manager.components.precreate=ConsoleIn";
    QProcess *process = m_live->startProcess(RTMANAGER_PATH, args, "rtmanager ready", &error);
    QVERIFY2(process, qPrintable(error));
    if (deleteLast) {
        CORBA::Object_var object
            = m_orb->string_to_object(LiveTest::managerLocation(port).constData());
        RTM::Manager_var lonely = RTM::Manager::_narrow(object);
        QVERIFY(process->state() == QProcess::Running);
        QCOMPARE(lonely->delete_component("ConsoleIn0"), RTC::RTC_OK);
    }
    QVERIFY(process->waitForFinished(10000));
    QCOMPARE(process->exitCode(), 0);
    CORBA::Object_var named = resolve(localHost() + ".host_cxt/lonely.mgr");
    QVERIFY(CORBA::is_nil(named));
}

void TestManagerLive::masterKnownByAnyReference()
{
    // The slave joined through corbaloc (TCP); the master's own reference, as the name server has
    // it, also offers the Unix socket. Both name the same master.
    RTC::RTObject_var onSlave = create("ConsoleIn?manager_name=slaveR");
    QVERIFY2(!CORBA::is_nil(onSlave), qPrintable(lastError(m_master)));
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(1));
    CORBA::Object_var named = resolve(localHost() + ".host_cxt/manager.mgr");
    RTM::Manager_var master = RTM::Manager::_narrow(named);
    QVERIFY(!CORBA::is_nil(master));
    QVERIFY(!named->_is_equivalent(m_master)); // omniORB's view: reached differently
    QCOMPARE(slaves[0]->remove_master_manager(master), RTC::RTC_OK);
    RTM::ManagerList_var masters = slaves[0]->get_master_managers();
    QCOMPARE(masters->length(), CORBA::ULong(0));
}

// 127.0.0.2 is another host to the master (not its address, host name or 127.0.0.1): it uses the
// manager there directly, without making it its slave.
void TestManagerLive::forwardsToARestartedManagerOnAnotherHost()
{
    const QString address = QStringLiteral("127.0.0.2:%1").arg(LiveTest::freePort());
    const QStringList arguments {"-d", "-o", "corba.endpoints=" + address, "-o",
                                 "naming.enable=NO"};
    QString error;
    QProcess *remote = m_live->startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error);
    QVERIFY2(remote, qPrintable(error));
    const QString request = "ConsoleOut?instance_name=%1&manager_address=" + address;
    RTC::RTObject_var first = create(request.arg("far1"));
    QVERIFY2(!CORBA::is_nil(first), qPrintable(lastError(m_master)));
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(0)); // used directly, not made a slave

    // The master's connection to the first process is broken now, yet the new one is reached.
    m_live->stop(remote);
    remote = m_live->startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error);
    QVERIFY2(remote, qPrintable(error));
    RTC::RTObject_var second = create(request.arg("far2"));
    QVERIFY2(!CORBA::is_nil(second), qPrintable(lastError(m_master)));

    // With nobody there, the master says which manager it could not reach.
    m_live->stop(remote);
    RTC::RTObject_var third = create(request.arg("far3"));
    QVERIFY(CORBA::is_nil(third));
    QVERIFY2(lastError(m_master).startsWith("create_component: manager at " + address
                                            + " unreachable: "),
             qPrintable(lastError(m_master)));
}

namespace {

/// Context switches of every thread of @p pid so far: each wake-up of a periodic context counts.
qint64 contextSwitches(qint64 pid)
{
    qint64 total = 0;
    const QDir tasks(QStringLiteral("/proc/%1/task").arg(pid));
    for (const QString &task : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile status(tasks.filePath(task + QStringLiteral("/status")));
        if (!status.open(QIODevice::ReadOnly))
            continue;
        for (const QByteArray &line : status.readAll().split('\n')) {
            if (line.startsWith("voluntary_ctxt_switches:") || line.startsWith("nonvoluntary_ctxt_switches:"))
                total += line.mid(line.indexOf(':') + 1).trimmed().toLongLong();
        }
    }
    return total;
}

} // namespace

void TestManagerLive::idleContextsDoNotTick()
{
    // Twenty components at 1 kHz, none active: their contexts would wake 20,000 times a second.
    QStringList types;
    for (int i = 0; i < 20; ++i)
        types << QStringLiteral("ConsoleIn?instance_name=idle%1").arg(i);
    QString error;
    QProcess *process = nullptr;
    RTM::Manager_var manager = startMaster(&error, &process,
                                           {"-o", "exec_cxt.periodic.rate=1000", "-o",
                                            "manager.components.precreate=" + types.join(','), "-o",
                                            "manager.instance_name=idle"});
    QVERIFY2(!CORBA::is_nil(manager), qPrintable(error));
    RTC::RTCList_var components = manager->get_components();
    QCOMPARE(components->length(), CORBA::ULong(20));
    const qint64 pid = process->processId();
    // A window of measurement, not a wait for a condition.
    qint64 before = contextSwitches(pid);
    QTest::qWait(500);
    const qint64 idle = contextSwitches(pid) - before;
    QVERIFY2(idle < 1000, qPrintable(QStringLiteral("%1 context switches in 0.5 s while idle").arg(idle)));

    // One active component makes its context tick at its rate again.
    RTC::ExecutionContextList_var contexts = components[0]->get_owned_contexts();
    QCOMPARE(contexts[0]->activate_component(components[0]), RTC::RTC_OK);
    before = contextSwitches(pid);
    QTest::qWait(500);
    const qint64 active = contextSwitches(pid) - before;
    QVERIFY2(active > 200, qPrintable(QStringLiteral("%1 context switches in 0.5 s with one active").arg(active)));
    m_live->stop(process);
}

void TestManagerLive::sameHostPeersUseUnixSocket_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<bool>("unixSocket");
    QTest::addColumn<bool>("runtimeDir"); ///< XDG_RUNTIME_DIR set (else TMPDIR only)
    QTest::newRow("default") << QStringList() << true << true;
    QTest::newRow("no XDG_RUNTIME_DIR") << QStringList() << true << false;
    QTest::newRow("corba.unix_socket=NO") << QStringList{"-o", "corba.unix_socket=NO"} << false << true;
}

namespace {

/// Lines of /proc/net/unix for sockets bound to @p path: the listening one and one per accepted
/// connection.
int unixSocketsAt(const QString &path)
{
    QFile table(QStringLiteral("/proc/net/unix"));
    if (!table.open(QIODevice::ReadOnly))
        return -1;
    int count = 0;
    for (const QByteArray &line : table.readAll().split('\n')) {
        if (line.endsWith(' ' + path.toLocal8Bit()))
            ++count;
    }
    return count;
}

/// Leaves a socket file at @p path as a killed process does.
bool leaveSocket(const QString &path)
{
    const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address {};
    address.sun_family = AF_UNIX;
    const QByteArray name = path.toLocal8Bit();
    if (fd < 0 || name.size() >= int(sizeof address.sun_path))
        return false;
    std::memcpy(address.sun_path, name.constData(), size_t(name.size()));
    const bool bound = bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0;
    close(fd);
    return bound;
}

} // namespace

void TestManagerLive::sameHostPeersUseUnixSocket()
{
    QFETCH(QStringList, options);
    QFETCH(bool, unixSocket);
    QFETCH(bool, runtimeDir);
    // The sockets' folder is in XDG_RUNTIME_DIR, else in TMPDIR: private ones keep this test's files
    // apart, and the one not to be used stays empty.
    QTemporaryDir tmp(QStringLiteral("/tmp/rtsock-XXXXXX"));
    QTemporaryDir other(QStringLiteral("/tmp/rtsock-XXXXXX"));
    QVERIFY(tmp.isValid() && other.isValid());
    const QByteArray oldTmp = qgetenv("TMPDIR");
    const QByteArray oldRuntime = qgetenv("XDG_RUNTIME_DIR");
    const auto restore = qScopeGuard([&oldTmp, &oldRuntime] {
        for (const auto &[name, value] : {std::pair {"TMPDIR", oldTmp}, std::pair {"XDG_RUNTIME_DIR", oldRuntime}}) {
            if (value.isNull())
                qunsetenv(name);
            else
                qputenv(name, value);
        }
    });
    if (runtimeDir) {
        qputenv("XDG_RUNTIME_DIR", tmp.path().toLocal8Bit());
        qputenv("TMPDIR", other.path().toLocal8Bit());
    } else {
        qunsetenv("XDG_RUNTIME_DIR");
        qputenv("TMPDIR", tmp.path().toLocal8Bit());
    }
    const auto checkOtherUnused = qScopeGuard([&other] {
        QVERIFY2(QDir(other.path()).isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::System),
                 "sockets in the folder not to be used");
    });
    const QDir folder(tmp.filePath(QStringLiteral("rtstudio-orb-%1").arg(getuid())));
    QVERIFY(QDir().mkpath(folder.path()));
    // A process that is gone, and the socket it left behind.
    const pid_t gone = fork();
    if (gone == 0)
        _exit(0);
    QVERIFY(gone > 0);
    QCOMPARE(waitpid(gone, nullptr, 0), gone);
    const QString stale = folder.filePath(QString::asprintf("%09d-1700000000", int(gone)));
    QVERIFY(leaveSocket(stale));

    QString error;
    QProcess *process = nullptr;
    RTM::Manager_var manager = startMaster(
        &error, &process,
        options + QStringList{"-o", "manager.components.precreate=ConsoleIn", "-o", "manager.instance_name=local"});
    QVERIFY2(!CORBA::is_nil(manager), qPrintable(error));
    const QStringList own = folder.entryList({QString::asprintf("%09d-*", int(process->processId()))},
                                             QDir::System);
    if (!unixSocket) {
        QVERIFY2(own.isEmpty(), qPrintable(own.join(' ')));
        return;
    }
    QVERIFY2(!QFileInfo::exists(stale), "the socket of a process that is gone was not removed");
    QCOMPARE(own.size(), 1);
    const QString path = folder.filePath(own.first());
    QCOMPARE(unixSocketsAt(path), 1); // listening, nobody connected yet
    // The component's reference offers the socket beside TCP; a call from this host takes it.
    RTC::RTCList_var components = manager->get_components();
    QCOMPARE(components->length(), CORBA::ULong(1));
    RTC::ComponentProfile_var profile = components[0]->get_component_profile();
    QCOMPARE(QString(profile->instance_name), QStringLiteral("ConsoleIn0"));
    QVERIFY(unixSocketsAt(path) >= 2);
    m_live->stop(process);
}

void TestManagerLive::startedSlavesStayOutOfNaming()
{
    // As OpenRTM-aist's: the master is in the name server, the slaves it starts are reached through
    // it (their components are named as usual).
    RTC::RTObject_var remote = create("ConsoleIn?instance_name=outside0&manager_name=slaveQ");
    QVERIFY(!CORBA::is_nil(remote));
    QVERIFY(slavePid("slaveQ") > 0);
    QVERIFY(!CORBA::is_nil(CORBA::Object_var(resolve(localHost() + ".host_cxt/manager.mgr"))));
    QVERIFY(!CORBA::is_nil(CORBA::Object_var(resolve(localHost() + ".host_cxt/outside0.rtc"))));
    QVERIFY(CORBA::is_nil(CORBA::Object_var(resolve(localHost() + ".host_cxt/slaveQ.mgr"))));
}

void TestManagerLive::slaveFoundByItsExpandedName()
{
    // A `manager_%p` slave is then `manager_<its pid>`: a request naming it goes to that process.
    RTC::RTObject_var first = create("ConsoleIn?instance_name=byPid0&manager_name=manager_%p");
    QVERIFY(!CORBA::is_nil(first));
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(1));
    const QString pid = nv(RTM::ManagerProfile_var(slaves[0]->get_profile())->properties, "pid");
    QVERIFY(pid.toLongLong() > 0);
    RTC::RTObject_var second = create(QStringLiteral("ConsoleIn?instance_name=byPid1&manager_name=manager_%1").arg(pid));
    QVERIFY(!CORBA::is_nil(second));
    slaves = m_master->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(1));
    RTC::RTCList_var hosted = slaves[0]->get_components();
    QCOMPARE(hosted->length(), CORBA::ULong(2));
}

namespace {

/// The inodes of the sockets process @p pid holds (its /proc/<pid>/fd links read `socket:[<inode>]`).
QSet<QByteArray> socketInodes(qint64 pid)
{
    QSet<QByteArray> sockets;
    const QDir fds(QStringLiteral("/proc/%1/fd").arg(pid));
    for (const QFileInfo &fd : fds.entryInfoList(QDir::System | QDir::NoDotAndDotDot)) {
        const QByteArray name = QFileInfo(fd.symLinkTarget()).fileName().toUtf8();
        if (name.startsWith("socket:["))
            sockets.insert(name.mid(8, name.size() - 9));
    }
    return sockets;
}

/// The rows of /proc/<pid>/net/@p table (split into fields) for sockets process @p pid holds,
/// @p inodeField naming the column of the inode.
QList<QList<QByteArray>> ownSockets(qint64 pid, const QString &table, int inodeField)
{
    const QSet<QByteArray> sockets = socketInodes(pid);
    QFile file(QStringLiteral("/proc/%1/net/%2").arg(pid).arg(table));
    QList<QList<QByteArray>> rows;
    if (!file.open(QIODevice::ReadOnly))
        return rows;
    for (const QByteArray &line : file.readAll().split('\n')) {
        const QList<QByteArray> fields = line.simplified().split(' ');
        if (fields.size() > inodeField && sockets.contains(fields.at(inodeField)))
            rows.append(fields);
    }
    return rows;
}

/// TCP connections of process @p pid to @p port on this host.
int connectionsTo(qint64 pid, quint16 port)
{
    const QByteArray remotePort = ':' + QByteArray::number(port, 16).toUpper().rightJustified(4, '0');
    int count = 0;
    // sl local_address rem_address st … inode: established (01) to the port
    for (const QList<QByteArray> &fields : ownSockets(pid, QStringLiteral("tcp"), 9)) {
        if (fields.at(2).endsWith(remotePort) && fields.at(3) == "01")
            ++count;
    }
    return count;
}

/// Unix socket connections process @p pid accepted: connected (03) and bound to its listening path.
int acceptedUnixConnections(qint64 pid)
{
    int count = 0;
    // Num RefCount Protocol Flags Type St Inode Path
    for (const QList<QByteArray> &fields : ownSockets(pid, QStringLiteral("unix"), 6)) {
        if (fields.size() == 8 && fields.at(5) == "03")
            ++count;
    }
    return count;
}

} // namespace

void TestManagerLive::oneNameServerConnectionPerProcess()
{
    // A manager registers itself and its components over one connection to each name server: the
    // contexts it resolves there are reached over the same connection as the server's root.
    const quint16 namingPort = m_live->namingServer().section(QLatin1Char(':'), -1).toUShort();
    RTC::RTObject_var inMaster = create(QStringLiteral("ConsoleIn?instance_name=named0"));
    QVERIFY(!CORBA::is_nil(inMaster));
    RTC::RTObject_var inSlave = create(QStringLiteral("ConsoleIn?instance_name=named1&manager_name=slaveC"));
    QVERIFY(!CORBA::is_nil(inSlave));
    QVERIFY(!CORBA::is_nil(CORBA::Object_var(resolve(localHost() + ".host_cxt/named0.rtc"))));
    QVERIFY(!CORBA::is_nil(CORBA::Object_var(resolve(localHost() + ".host_cxt/named1.rtc"))));
    QCOMPARE(connectionsTo(m_masterProcess->processId(), namingPort), 1);
    const qint64 slave = slavePid(QStringLiteral("slaveC"));
    QVERIFY(slave > 0);
    QCOMPARE(connectionsTo(slave, namingPort), 1);
}

namespace {

/// Sends @p count create_component requests to @p manager at once, one thread each, `%1` in
/// @p request numbering them; the number of components made.
int createSideBySide(RTM::Manager_ptr manager, const QString &request, int count)
{
    std::vector<std::thread> threads;
    std::atomic<int> created {0};
    for (int i = 0; i < count; ++i) {
        threads.emplace_back([manager, &created, text = request.arg(i).toUtf8()] {
            try {
                RTC::RTObject_var rtc = manager->create_component(text.constData());
                if (!CORBA::is_nil(rtc))
                    ++created;
            } catch (const CORBA::Exception &) {
            }
        });
    }
    for (std::thread &thread : threads)
        thread.join();
    return created;
}

} // namespace

void TestManagerLive::registrationsSideBySideMakeContextsOnce()
{
    // Components created side by side into contexts nobody made yet: each registration finds the
    // contexts missing, and only one of them can make each; the others use it.
    QString error;
    QProcess *process = nullptr;
    RTM::Manager_var manager = startMaster(&error, &process,
                                           {"-o", "naming.formats=%h.host_cxt/side.cxt/%n.cxt/%n.rtc", "-o",
                                            "manager.instance_name=side"});
    QVERIFY2(!CORBA::is_nil(manager), qPrintable(error));
    constexpr int Count = 8;
    QCOMPARE(createSideBySide(manager, QStringLiteral("ConsoleIn?instance_name=side%1"), Count), Count);
    for (int i = 0; i < Count; ++i) {
        const QString path = QStringLiteral("%1.host_cxt/side.cxt/side%2.cxt/side%2.rtc").arg(localHost()).arg(i);
        QVERIFY2(!CORBA::is_nil(CORBA::Object_var(resolve(path))), qPrintable(path));
    }
    m_live->stop(process);
}

void TestManagerLive::slavesStartedSideBySideServeOneConnection()
{
    // A master asks each new slave for its profile and whether it joined, then creates in it: all
    // over one connection. A slave joining must not set off a check of every slave (each check
    // that meets another call to a slave opens a further connection, and a server thread there).
    // No periodic check during the test: only the joins could cause one.
    QString error;
    QProcess *process = nullptr;
    RTM::Manager_var manager = startMaster(&error, &process, {"-o", "manager.slave_check_interval=600000"});
    QVERIFY2(!CORBA::is_nil(manager), qPrintable(error));
    constexpr int Count = 8;
    QCOMPARE(createSideBySide(manager, QStringLiteral("ConsoleIn?instance_name=own%1&manager_name=manager_%p"), Count),
             Count);
    QList<qint64> slaves;
    for (const qint64 forkServer : LiveTest::childProcesses(process->processId()))
        slaves << LiveTest::childProcesses(forkServer);
    QCOMPARE(slaves.size(), Count);
    for (const qint64 slave : std::as_const(slaves))
        QCOMPARE(acceptedUnixConnections(slave), 1);
    m_live->stop(process);
}

namespace {

/// The name the kernel knows process @p pid by (what ps, pgrep and top show).
QByteArray commandName(qint64 pid)
{
    QFile comm(QStringLiteral("/proc/%1/comm").arg(pid));
    return comm.open(QIODevice::ReadOnly) ? comm.readAll().trimmed() : QByteArray();
}

} // namespace

void TestManagerLive::startedProcessesAreCalledRtmanager()
{
    // `pgrep rtmanager` and `killall rtmanager` find every manager process, slaves and the fork
    // server that starts them included.
    RTC::RTObject_var remote = create("ConsoleIn?manager_name=slaveN");
    QVERIFY(!CORBA::is_nil(remote));
    const qint64 slave = slavePid("slaveN");
    QVERIFY(slave > 0);
    QCOMPARE(commandName(slave), QByteArray("rtmanager"));
    // The fork server: the master's child whose child the slave is.
    const QList<qint64> children = LiveTest::childProcesses(m_masterProcess->processId());
    const auto forkServer = std::find_if(children.begin(), children.end(), [slave](qint64 child) {
        return LiveTest::childProcesses(child).contains(slave);
    });
    QVERIFY(forkServer != children.end());
    QCOMPARE(commandName(*forkServer), QByteArray("rtmanager"));
}

QTEST_GUILESS_MAIN(TestManagerLive)
#include "tst_managerlive.moc"
