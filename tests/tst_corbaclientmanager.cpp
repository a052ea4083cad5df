// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "corbaerror.h"
#include "errorof.h"
#include "livesystem.h"
#include "managerproxy.h"
#include "namingbrowser.h"
#include "orb.h"
#include "portconnection.h"

#include <RTC.hh>

#include <QElapsedTimer>
#include <QTest>

#include <atomic>
#include <csignal>
#include <thread>

using namespace Corba;
using LiveTest::kindOf;

// The client library against the project's real rtmanager (manager/) and omniNames.
class TestCorbaClientManager : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void browsesTheManagersNames();
    void readsProfilesAndPorts();
    void activatesInTheRealExecutionContext();
    void attachesToAnotherComponentsContext();
    void connectsDataPortsWithNegotiation();
    void connectsServicePorts();
    void editsConfiguration();
    void createsAndDeletesComponents();
    void createsInOneCall();
    void timeoutsArePerThread();

private:
    RtPath path(const QString &name) const;
    ComponentProxy component(const QString &instance) const;

    LiveTest::LiveSystem m_live;
    quint16 m_port = 0;
};

RtPath TestCorbaClientManager::path(const QString &name) const
{
    return *RtPath::parse(
        QStringLiteral("/%1/rtmhost.host_cxt/%2").arg(m_live.namingServer(), name));
}

ComponentProxy TestCorbaClientManager::component(const QString &instance) const
{
    const RtPath p = path(instance + QStringLiteral(".rtc"));
    return ComponentProxy(NamingBrowser::resolve(p), p.toString());
}

void TestCorbaClientManager::initTestCase()
{
    Orb::setCallTimeout(3000);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_port = LiveTest::freePort();
    const QStringList arguments {
        "-d",
        "-o",
        QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(m_port),
        "-o",
        "corba.nameservers=" + m_live.namingServer(),
        "-o",
        "naming.formats=rtmhost.host_cxt/%n.rtc",
        "-o",
        "manager.naming_formats=rtmhost.host_cxt/%n.mgr",
        "-o",
        "manager.components.precreate=ConsoleIn,ConsoleOut,ConfigSample,MyServiceProvider,"
        "MyServiceConsumer",
        "-o",
        QStringLiteral("manager.modules.load_path=") + MANAGER_TEST_MODULE_DIR};
    QVERIFY2(
        m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error),
        qPrintable(error));
}

void TestCorbaClientManager::browsesTheManagersNames()
{
    QStringList names;
    for (const NamingNode &node : NamingBrowser::list(path(QString()))) {
        QVERIFY2(node.type == NodeType::Component || node.type == NodeType::Manager,
                 qPrintable(node.name));
        names.append(node.name);
    }
    names.sort();
    QCOMPARE(names,
             QStringList({"ConfigSample0.rtc", "ConsoleIn0.rtc", "ConsoleOut0.rtc",
                          "MyServiceConsumer0.rtc", "MyServiceProvider0.rtc", "manager.mgr"}));
    const auto direct = RtPath::parse(QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_port));
    QCOMPARE(NamingBrowser::node(*direct).type, NodeType::Manager);
    QCOMPARE(NamingBrowser::list(*direct).size(), size_t(5));
}

void TestCorbaClientManager::readsProfilesAndPorts()
{
    const ComponentInfo info = component("ConsoleIn0").profile();
    QCOMPARE(info.instanceName, QString("ConsoleIn0"));
    QCOMPARE(info.typeName, QString("ConsoleIn"));
    const PortInfo out = component("ConsoleIn0").port("out");
    QCOMPARE(out.name, QString("ConsoleIn0.out"));
    QVERIFY(out.isDataOut());
    QVERIFY2(propertyValue(out.properties, "dataport.data_type").contains("TimedLong"),
             qPrintable(propertyValue(out.properties, "dataport.data_type")));
    const PortInfo service = component("MyServiceProvider0").port("MyService");
    QVERIFY(service.isService());
    QCOMPARE(service.interfaces.at(0).instanceName, QString("myservice"));
    const auto contexts = component("ConsoleIn0").executionContexts();
    QVERIFY(!contexts.empty());
    QVERIFY(contexts[0].owned);
    QCOMPARE(contexts[0].kind, QString("PERIODIC"));
}

void TestCorbaClientManager::activatesInTheRealExecutionContext()
{
    const ComponentProxy rtc = component("ConsoleOut0");
    QCOMPARE(rtc.state(), LifeCycleState::Inactive);
    rtc.activate();
    QTRY_COMPARE(rtc.state(), LifeCycleState::Active);
    rtc.deactivate();
    QTRY_COMPARE(rtc.state(), LifeCycleState::Inactive);
    rtc.setRate(200);
    QCOMPARE(rtc.executionContexts().at(0).rate, 200.0);
}

static QStringList memberNames(const std::vector<ContextMember> &members)
{
    QStringList names;
    for (const ContextMember &member : members)
        names.append(member.name);
    return names;
}

void TestCorbaClientManager::attachesToAnotherComponentsContext()
{
    const ComponentProxy owner = component("ConsoleIn0");
    const ComponentProxy guest = component("ConsoleOut0");
    const QString context = owner.executionContexts().at(0).ior;
    guest.attachContext(context);

    const auto guestContexts = guest.executionContexts(ComponentProxy::ContextDetail::Members);
    QCOMPARE(guestContexts.size(), size_t(2));
    QVERIFY(!guestContexts[1].owned);
    QCOMPARE(guestContexts[1].owner.name, QString("ConsoleIn0"));
    QCOMPARE(memberNames(guestContexts[1].participants), QStringList {"ConsoleOut0"});
    QCOMPARE(guestContexts[0].owner.name, QString("ConsoleOut0"));
    QVERIFY(guestContexts[0].participants.empty());
    const auto ownerContexts = owner.executionContexts(ComponentProxy::ContextDetail::Members);
    QCOMPARE(ownerContexts.at(0).owner.name, QString("ConsoleIn0"));
    QCOMPARE(ownerContexts.at(0).owner.ior, owner.ior());
    QCOMPARE(memberNames(ownerContexts.at(0).participants), QStringList {"ConsoleOut0"});
    QCOMPARE(ownerContexts.at(0).participants.at(0).ior, guest.ior());
    QVERIFY(guest.executionContexts().at(1).owner.ior.isEmpty()); // Basic reads no members

    guest.activate(1);
    QTRY_COMPARE(guest.state(1), LifeCycleState::Active);
    QCOMPARE(guest.state(0), LifeCycleState::Inactive);
    QCOMPARE(kindOf([&] { guest.detachContext(context); }), Error::Kind::Refused);
    guest.deactivate(1);
    QTRY_COMPARE(guest.state(1), LifeCycleState::Inactive);
    QCOMPARE(kindOf([&] { guest.attachContext(context); }), Error::Kind::Refused);
    QCOMPARE(kindOf([&] { owner.attachContext(context); }), Error::Kind::Refused);
    QCOMPARE(kindOf([&] { owner.detachContext(context); }), Error::Kind::Refused);

    guest.detachContext(context);
    QCOMPARE(guest.executionContexts().size(), size_t(1));
    QVERIFY(owner.executionContexts(ComponentProxy::ContextDetail::Members)
                .at(0)
                .participants.empty());
    QCOMPARE(kindOf([&] { guest.detachContext(context); }), Error::Kind::NotFound);
    QCOMPARE(kindOf([&] { guest.attachContext("no reference"); }), Error::Kind::BadPath);
}

void TestCorbaClientManager::connectsDataPortsWithNegotiation()
{
    const ComponentProxy source = component("ConsoleIn0");
    const ComponentProxy sink = component("ConsoleOut0");
    ConnectionRequest request;
    request.properties = {{"dataport.subscription_type", "flush"}};
    const ConnectorInfo made
        = PortConnection::connect({source.port("out"), sink.port("in")}, request, "src");
    QVERIFY(!made.id.isEmpty());
    const PortInfo in = sink.port("in");
    QCOMPARE(in.connectors.size(), size_t(1));
    QCOMPARE(in.connectors[0].id, made.id);
    QCOMPARE(in.connectors[0].ports, QStringList({"ConsoleIn0.out", "ConsoleOut0.in"}));
    // The push connection carried the inport's IOR through the negotiation.
    QVERIFY(hasProperty(made.properties, "dataport.corba_cdr.inport_ior"));
    PortConnection::disconnect(source.port("out"), made.id, "src");
    QVERIFY(sink.port("in").connectors.empty());
    QCOMPARE(kindOf([&] {
                 PortConnection::connect({sink.port("in"), sink.port("in")}, {}, "x");
             }),
             Error::Kind::Incompatible);
}

void TestCorbaClientManager::connectsServicePorts()
{
    const PortInfo consumer = component("MyServiceConsumer0").port("MyService");
    const PortInfo provider = component("MyServiceProvider0").port("MyService");
    const ConnectorInfo made = PortConnection::connect({consumer, provider}, {}, "svc");
    QCOMPARE(component("MyServiceProvider0").port("MyService").connectors.at(0).id, made.id);
    PortConnection::disconnectAll(consumer, "svc");
    QVERIFY(component("MyServiceConsumer0").port("MyService").connectors.empty());
}

void TestCorbaClientManager::editsConfiguration()
{
    const ComponentProxy rtc = component("ConfigSample0");
    QStringList ids;
    for (const ConfigurationSet &set : rtc.configurationSets())
        ids.append(set.id);
    QVERIFY2(ids.contains("default") && ids.contains("mode0"), qPrintable(ids.join(',')));
    QCOMPARE(rtc.activeConfigurationSet(), QString("default"));
    rtc.setParameter("default", "int_param0", "321");
    QCOMPARE(rtc.parameter("default", "int_param0"), QString("321"));
    rtc.activateConfigurationSet("mode0");
    QCOMPARE(rtc.activeConfigurationSet(), QString("mode0"));
    rtc.activateConfigurationSet("default");

    // rtmanager, like OpenRTM-aist, has no active set after a write until an activation; every
    // write of the proxy activates again the set that was active, so the component stays usable.
    rtc.setParameter("mode0", "int_param0", "7");
    QCOMPARE(rtc.activeConfigurationSet(), QString("default"));
    rtc.addConfigurationSet({"extra", "", {{"int_param0", "8"}}});
    QCOMPARE(rtc.activeConfigurationSet(), QString("default"));
    rtc.setConfigurationSetValues({"extra", "", {{"int_param0", "9"}}});
    QCOMPARE(rtc.activeConfigurationSet(), QString("default"));
    rtc.removeConfigurationSet("extra");
    QCOMPARE(rtc.activeConfigurationSet(), QString("default"));
    QCOMPARE(rtc.parameter("mode0", "int_param0"), QString("7"));

    // Left inactive by another tool: readers report no active set instead of failing.
    const QByteArray ior = rtc.ior().toUtf8();
    int argc = 0;
    CORBA::ORB_var orb = CORBA::ORB_init(argc, nullptr); // the client library's ORB
    RTC::RTObject_var object = RTC::RTObject::_narrow(orb->string_to_object(ior.constData()));
    SDOPackage::Configuration_var conf = object->get_configuration();
    SDOPackage::ConfigurationSet_var mode0 = conf->get_configuration_set("mode0");
    QVERIFY(conf->set_configuration_set_values(mode0.in()));
    QCOMPARE(rtc.activeConfigurationSet(), QString());
    QCOMPARE(rtc.parameter("mode0", "int_param0"), QString("7"));
    rtc.activateConfigurationSet("default");
    QCOMPARE(rtc.activeConfigurationSet(), QString("default"));
}

void TestCorbaClientManager::createsAndDeletesComponents()
{
    const RtPath mgrPath = path("manager.mgr");
    const ManagerProxy manager(NamingBrowser::resolve(mgrPath), mgrPath.toString());
    QVERIFY(manager.isMaster());
    QStringList factories;
    for (const Properties &factory : manager.factoryProfiles())
        factories.append(propertyValue(factory, "implementation_id"));
    QVERIFY2(factories.contains("ConsoleIn"), qPrintable(factories.join(',')));
    const int before = manager.components().size();
    const QString ior = manager.createComponent("ConsoleOut?instance_name=Extra0");
    QCOMPARE(ComponentProxy(ior, "Extra0").profile().instanceName, QString("Extra0"));
    QCOMPARE(manager.components().size(), before + 1);
    QCOMPARE(manager.componentsByName("Extra0").size(), 1);
    QCOMPARE(kindOf([&] { manager.createComponent("ConsoleOut?instance_name=Extra0"); }),
             Error::Kind::Refused);
    // The refusal says why, as the manager put it.
    try {
        manager.createComponent("NoSuchType");
        QFAIL("created a component of an unknown type");
    } catch (const Error &e) {
        QVERIFY2(e.message().endsWith("could not create 'NoSuchType' (create_component: unknown "
                                      "component type 'NoSuchType')"),
                 qPrintable(e.message()));
    }
    manager.deleteComponent("Extra0");
    QCOMPARE(manager.components().size(), before);
    QVERIFY(!manager.profile().isEmpty());
    QVERIFY(!manager.configuration().isEmpty());
}

void TestCorbaClientManager::createsInOneCall()
{
    const RtPath mgrPath = path("manager.mgr");
    const ManagerProxy manager(NamingBrowser::resolve(mgrPath), mgrPath.toString());
    std::optional<ManagerProxy::Created> created = manager.createComponents(
        {"ConsoleOut?instance_name=One0", "ConsoleOut?instance_name=One1"});
    QVERIFY(created);
    QCOMPARE(created->iors.size(), 2);
    QCOMPARE(created->refusal, QString());
    QCOMPARE(ComponentProxy(created->iors.at(1), "One1").profile().instanceName, QString("One1"));
    QCOMPARE(NamingBrowser::node(path("One0.rtc")).type, NodeType::Component);

    // The first refusal ends the call and reads as createComponent's would.
    created = manager.createComponents(
        {"ConsoleOut?instance_name=One2", "NoSuchType", "ConsoleOut?instance_name=One3"});
    QVERIFY(created);
    QCOMPARE(created->iors.size(), 1);
    QVERIFY2(created->refusal.endsWith("could not create 'NoSuchType' (create_component: unknown "
                                       "component type 'NoSuchType')"),
             qPrintable(created->refusal));
    QVERIFY(manager.componentsByName("One3").isEmpty());

    // Each create has the call timeout a call of its own would have.
    manager.loadModule(MANAGER_TEST_MODULE, "ManagerTestModuleInit");
    {
        const ThreadCallTimeout timeout(600);
        QStringList slow;
        for (int i = 0; i < 3; ++i)
            slow << QStringLiteral("ModuleCounter?init_delay_ms=400&instance_name=Slow%1").arg(i);
        created = manager.createComponents(slow);
    }
    QVERIFY(created);
    QCOMPARE(created->iors.size(), 3);
    for (const QString name : {"One0", "One1", "One2", "Slow0", "Slow1", "Slow2"})
        manager.deleteComponent(name);
}

namespace {

struct TimedCall
{
    Error::Kind kind = Error::Kind(-1);
    qint64 elapsed = -1;
};

// One call of `manager` under `timeout` ms in a thread of its own (a plain std::thread, which
// omniORB did not create).
TimedCall timedCall(const ManagerProxy &manager, int timeout)
{
    const ThreadCallTimeout scope(timeout);
    TimedCall result;
    QElapsedTimer timer;
    timer.start();
    result.kind = kindOf([&] { manager.components(); });
    result.elapsed = timer.elapsed();
    return result;
}

} // namespace

void TestCorbaClientManager::timeoutsArePerThread()
{
    QString error;
    const quint16 frozenPort = LiveTest::freePort();
    QProcess *frozen = m_live.startProcess(
        RTMANAGER_PATH,
        {"-o", QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(frozenPort), "-o",
         "naming.enable=NO", "-o", "corba.master_manager=", "-o",
         "manager.components.precreate=ConsoleIn"},
        "rtmanager ready", &error);
    QVERIFY2(frozen, qPrintable(error));
    const ManagerProxy stopped(QStringLiteral("corbaloc:iiop:127.0.0.1:%1/manager").arg(frozenPort),
                               "frozen");
    const ManagerProxy healthy(QStringLiteral("corbaloc:iiop:127.0.0.1:%1/manager").arg(m_port),
                               "healthy");
    QCOMPARE(stopped.components().size(), 1); // connection open before the stop
    QCOMPARE(::kill(pid_t(frozen->processId()), SIGSTOP), 0);
    QVERIFY2(LiveTest::waitUntilStopped(frozen->processId()), "the manager did not stop");

    // Two threads wait on the stopped manager with different timeouts; the quicker one then uses
    // the healthy manager while the other still waits. Each call keeps its own bound.
    const int longTimeout = 2000;
    const int shortTimeout = 400;
    TimedCall slow;
    TimedCall quick;
    std::atomic<int> healthyCalls {0};
    std::atomic<bool> healthyFailed {false};
    std::atomic<bool> slowDone {false};
    std::thread slowThread([&] {
        slow = timedCall(stopped, longTimeout);
        slowDone = true;
    });
    std::thread quickThread([&] {
        quick = timedCall(stopped, shortTimeout);
        const ThreadCallTimeout scope(shortTimeout);
        for (int n = 0; n < 20 && !slowDone; ++n) {
            try {
                if (healthy.components().size() == 5 && !slowDone)
                    ++healthyCalls;
            } catch (const Error &) {
                healthyFailed = true;
            }
        }
    });
    slowThread.join();
    quickThread.join();
    ::kill(pid_t(frozen->processId()), SIGCONT);

    QCOMPARE(slow.kind, Error::Kind::Timeout);
    QCOMPARE(quick.kind, Error::Kind::Timeout);
    QVERIFY2(slow.elapsed >= longTimeout - 50 && slow.elapsed < longTimeout + 1000,
             qPrintable(QString::number(slow.elapsed)));
    QVERIFY2(quick.elapsed >= shortTimeout - 50 && quick.elapsed < shortTimeout + 1000,
             qPrintable(QString::number(quick.elapsed)));
    QVERIFY(!healthyFailed);
    QVERIFY2(healthyCalls > 0, "no call to the healthy manager finished meanwhile");
    // The process default is untouched by the threads' overrides.
    QCOMPARE(Orb::callTimeout(), 3000);
    QCOMPARE(stopped.components().size(), 1);
}

QTEST_GUILESS_MAIN(TestCorbaClientManager)
#include "tst_corbaclientmanager.moc"
