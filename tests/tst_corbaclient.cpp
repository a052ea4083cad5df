// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "corbaerror.h"
#include "errorof.h"
#include "livesystem.h"
#include "managerproxy.h"
#include "namingbrowser.h"
#include "orb.h"
#include "portconnection.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTest>
#include <QThread>

#include <signal.h>

#include <atomic>
#include <thread>

using namespace Corba;
using LiveTest::kindOf;
using LiveTest::messageOf;

// Every client call against live peers: omniNames plus rtstudio_livepeer processes.
class TestCorbaClient : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void browsesNamingTreeWithZombies();
    void missingNamesAreNotFound();
    void readsComponentProfileAndPorts();
    void changesStatesInExecutionContexts();
    void controlsExecutionContexts();
    void editsConfigurationSets();
    void connectsAndDisconnectsDataPorts();
    void connectsServicePortsAndRefusesIllegalPairs();
    void drivesTheManager();
    void managerReachableByCorbaloc();
    void exitedComponentIsGone();
    void bindsAndUnbindsNames();
    void shutsTheManagerDown();
    void unreachablePeersGiveTypedErrors();
    void stoppedPeerTimesOut();
    void callsFromWorkerThreads();

private:
    RtPath path(const QString &relative) const;
    ComponentProxy component(const QString &instance) const;

    LiveTest::LiveSystem m_live;
    quint16 m_peerPort = 0;
};

RtPath TestCorbaClient::path(const QString &relative) const
{
    const QString text
        = QStringLiteral("/%1/livehost.host_cxt/%2").arg(m_live.namingServer(), relative);
    const auto parsed = RtPath::parse(text);
    return parsed ? *parsed : RtPath();
}

ComponentProxy TestCorbaClient::component(const QString &instance) const
{
    const RtPath p = path(instance + QStringLiteral(".rtc"));
    return ComponentProxy(NamingBrowser::resolve(p), p.toString());
}

void TestCorbaClient::initTestCase()
{
    Orb::setCallTimeout(2000);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList components {"ConsoleIn?instance_name=ConsoleIn0",
                                  "ConsoleOut?instance_name=ConsoleOut0",
                                  "ConsoleOut?instance_name=ConsoleOut1",
                                  "SeqIn?instance_name=SeqIn0",
                                  "MyServiceProvider?instance_name=MyServiceProvider0",
                                  "MyServiceConsumer?instance_name=MyServiceConsumer0",
                                  "ConfigSample?instance_name=ConfigSample0"};
    QVERIFY2(m_live.startPeer(components, &error, &m_peerPort, "livehost", true),
             qPrintable(error));
}

void TestCorbaClient::browsesNamingTreeWithZombies()
{
    const RtPath server = *RtPath::parse(QLatin1Char('/') + m_live.namingServer());
    const auto contexts = NamingBrowser::list(server);
    QCOMPARE(contexts.size(), size_t(1));
    QCOMPARE(contexts[0].name, QString("livehost.host_cxt"));
    QCOMPARE(contexts[0].type, NodeType::Context);

    QMap<QString, NodeType> types;
    for (const NamingNode &node : NamingBrowser::list(path(QString())))
        types.insert(node.name, node.type);
    QCOMPARE(types.value("ConsoleIn0.rtc"), NodeType::Component);
    QCOMPARE(types.value("ConfigSample0.rtc"), NodeType::Component);
    QCOMPARE(types.value("manager.mgr"), NodeType::Manager);
    QCOMPARE(types.value("Ghost0.rtc"), NodeType::Zombie);
    QCOMPARE(types.value("Stranger0.rtc"), NodeType::Zombie);
    QCOMPARE(types.size(), 10);

    const NamingNode ghost = NamingBrowser::node(path("Ghost0.rtc"));
    QCOMPARE(ghost.type, NodeType::Zombie);
    QVERIFY2(ghost.reason.contains("Ghost0.rtc"), qPrintable(ghost.reason));
    const NamingNode stranger = NamingBrowser::node(path("Stranger0.rtc"));
    QVERIFY2(stranger.reason.contains("not an RTObject"), qPrintable(stranger.reason));

    // The whole tree from the root, with the manager's components below the manager.
    const NamingNode root = NamingBrowser::tree(*RtPath::parse("/"), -1, {m_live.namingServer()});
    QCOMPARE(root.children.size(), size_t(1));
    const NamingNode &context = root.children[0].children.at(0);
    QCOMPARE(context.name, QString("livehost.host_cxt"));
    const auto manager = std::find_if(context.children.begin(), context.children.end(),
                                      [](const NamingNode &n) { return n.name == "manager.mgr"; });
    QVERIFY(manager != context.children.end());
    QCOMPARE(manager->children.size(), size_t(7));
    QCOMPARE(manager->children[0].name, QString("ConsoleIn0.rtc"));
    // Depth limits stop the recursion.
    QVERIFY(NamingBrowser::tree(server, 1).children.at(0).children.empty());
}

void TestCorbaClient::missingNamesAreNotFound()
{
    QCOMPARE(kindOf([&] { NamingBrowser::node(path("Nobody0.rtc")); }), Error::Kind::NotFound);
    const QString message = messageOf([&] { NamingBrowser::resolve(path("Nobody0.rtc")); });
    QVERIFY2(message.contains("/livehost.host_cxt/Nobody0.rtc: no such name"), qPrintable(message));
    QCOMPARE(kindOf([&] { component("ConsoleIn0").port("nothere"); }), Error::Kind::NotFound);
}

void TestCorbaClient::readsComponentProfileAndPorts()
{
    const ComponentInfo info = component("ConsoleIn0").profile();
    QCOMPARE(info.instanceName, QString("ConsoleIn0"));
    QCOMPARE(info.typeName, QString("ConsoleIn"));
    QCOMPARE(info.vendor, QString("AIST"));
    QCOMPARE(info.category, QString("example"));
    QCOMPARE(propertyValue(info.properties, "implementation_id"), QString("ConsoleIn"));
    QCOMPARE(info.ports.size(), size_t(1));
    QCOMPARE(info.ports[0].name, QString("ConsoleIn0.out"));
    QCOMPARE(info.ports[0].shortName(), QString("out"));
    QVERIFY(info.ports[0].isDataOut());
    QCOMPARE(propertyValue(info.ports[0].properties, "dataport.data_type"),
             QString("IDL:RTC/TimedLong:1.0"));

    const PortInfo service = component("MyServiceProvider0").port("MyService");
    QVERIFY(service.isService());
    QCOMPARE(service.interfaces.size(), size_t(1));
    QCOMPARE(service.interfaces[0].instanceName, QString("myservice"));
    QCOMPARE(service.interfaces[0].typeName, QString("SimpleService::MyService"));
    QVERIFY(service.interfaces[0].provided);
    QCOMPARE(component("SeqIn0").ports().size(), size_t(2));
}

void TestCorbaClient::changesStatesInExecutionContexts()
{
    const ComponentProxy rtc = component("ConsoleOut1");
    const auto contexts = rtc.executionContexts();
    QCOMPARE(contexts.size(), size_t(1));
    QVERIFY(contexts[0].owned);
    QCOMPARE(contexts[0].handle, 0);
    QCOMPARE(contexts[0].kind, QString("PERIODIC"));
    QCOMPARE(contexts[0].state, LifeCycleState::Inactive);

    rtc.activate();
    QCOMPARE(rtc.state(), LifeCycleState::Active);
    QCOMPARE(kindOf([&] { rtc.activate(); }), Error::Kind::Refused);
    const QString refused = messageOf([&] { rtc.reset(); });
    QVERIFY2(refused.contains("ConsoleOut1.rtc: reset returned PRECONDITION_NOT_MET"),
             qPrintable(refused));
    rtc.deactivate();
    QCOMPARE(rtc.state(), LifeCycleState::Inactive);
    QCOMPARE(kindOf([&] { rtc.state(1); }), Error::Kind::NotFound);
    QCOMPARE(kindOf([&] { rtc.activate(5); }), Error::Kind::NotFound);
}

void TestCorbaClient::controlsExecutionContexts()
{
    const ComponentProxy rtc = component("ConsoleOut1");
    QVERIFY(rtc.executionContexts().at(0).running);
    rtc.stopContext();
    QVERIFY(!rtc.executionContexts().at(0).running);
    QCOMPARE(kindOf([&] { rtc.stopContext(); }), Error::Kind::Refused);
    rtc.startContext();
    QVERIFY(rtc.executionContexts().at(0).running);
    rtc.setRate(25.5);
    QCOMPARE(rtc.executionContexts().at(0).rate, 25.5);
    QCOMPARE(kindOf([&] { rtc.setRate(-1); }), Error::Kind::Refused);
}

void TestCorbaClient::editsConfigurationSets()
{
    const ComponentProxy rtc = component("ConfigSample0");
    QStringList ids;
    for (const ConfigurationSet &set : rtc.configurationSets())
        ids.append(set.id);
    QCOMPARE(ids, QStringList({"default", "mode0", "__widget__"}));
    QCOMPARE(rtc.activeConfigurationSet(), QString("default"));
    QCOMPARE(rtc.parameter("mode0", "str_param0"), QString("foo"));

    rtc.setParameter("default", "int_param0", "42");
    QCOMPARE(rtc.parameter("default", "int_param0"), QString("42"));
    QCOMPARE(kindOf([&] { rtc.setParameter("default", "nope", "1"); }), Error::Kind::NotFound);
    QCOMPARE(kindOf([&] { rtc.parameter("nope", "int_param0"); }), Error::Kind::NotFound);

    rtc.addConfigurationSet({"mode9", "added", {{"int_param0", "9"}}});
    QCOMPARE(rtc.parameter("mode9", "int_param0"), QString("9"));
    QCOMPARE(kindOf([&] { rtc.addConfigurationSet({"mode9", "", {}}); }), Error::Kind::Refused);
    rtc.activateConfigurationSet("mode9");
    QCOMPARE(rtc.activeConfigurationSet(), QString("mode9"));
    QCOMPARE(kindOf([&] { rtc.removeConfigurationSet("mode9"); }), Error::Kind::Refused);
    rtc.activateConfigurationSet("default");
    rtc.removeConfigurationSet("mode9");
    QCOMPARE(kindOf([&] { rtc.configurationSet("mode9"); }), Error::Kind::NotFound);
    QCOMPARE(kindOf([&] { rtc.activateConfigurationSet("mode9"); }), Error::Kind::Refused);
}

void TestCorbaClient::connectsAndDisconnectsDataPorts()
{
    const ComponentProxy source = component("ConsoleIn0");
    const ComponentProxy sink = component("ConsoleOut0");
    ConnectionRequest request;
    request.properties = {{"dataport.subscription_type", "flush"}};
    const ConnectorInfo made = PortConnection::connect({source.port("out"), sink.port("in")},
                                                       request, "ConsoleIn0.rtc:out");
    QVERIFY(!made.id.isEmpty());
    QCOMPARE(made.name, QString("out_in"));

    const PortInfo in = sink.port("in");
    QCOMPARE(in.connectors.size(), size_t(1));
    const ConnectorInfo &seen = in.connectors[0];
    QCOMPARE(seen.id, made.id);
    QCOMPARE(seen.ports, QStringList({"ConsoleIn0.out", "ConsoleOut0.in"}));
    QCOMPARE(propertyValue(seen.properties, "dataport.subscription_type"), QString("flush"));
    QCOMPARE(propertyValue(seen.properties, "dataport.dataflow_type"), QString("push"));
    QCOMPARE(propertyValue(seen.properties, "dataport.data_type"),
             QString("IDL:RTC/TimedLong:1.0"));

    request.noDuplicates = true;
    const QString duplicate = messageOf([&] {
        PortConnection::connect({source.port("out"), sink.port("in")}, request,
                                "ConsoleIn0.rtc:out");
    });
    QVERIFY2(duplicate.contains("already connected (connector " + made.id), qPrintable(duplicate));

    // A named connector with a chosen id, then disconnect by id and disconnect all.
    ConnectionRequest named;
    named.name = "second";
    named.id = "fixed-id";
    PortConnection::connect({source.port("out"), sink.port("in")}, named, "ConsoleIn0.rtc:out");
    QCOMPARE(source.port("out").connectors.size(), size_t(2));
    QCOMPARE(source.port("out").connectors[1].name, QString("second"));
    PortConnection::disconnect(source.port("out"), "fixed-id", "ConsoleIn0.rtc:out");
    QCOMPARE(sink.port("in").connectors.size(), size_t(1));
    QCOMPARE(kindOf([&] { PortConnection::disconnect(source.port("out"), "fixed-id", "x"); }),
             Error::Kind::Refused);
    PortConnection::disconnectAll(sink.port("in"), "ConsoleOut0.rtc:in");
    QVERIFY(source.port("out").connectors.empty());

    // The wrong data type is refused with the reason, and nothing gets connected.
    const QString mismatch = messageOf([&] {
        PortConnection::connect({source.port("out"), component("SeqIn0").port("Double")}, {},
                                "src");
    });
    QVERIFY2(
        mismatch.contains("SeqIn0.Double does not allow dataport.data_type=IDL:RTC/TimedLong:1.0"),
        qPrintable(mismatch));
    QVERIFY(source.port("out").connectors.empty());
}

void TestCorbaClient::connectsServicePortsAndRefusesIllegalPairs()
{
    const PortInfo provider = component("MyServiceProvider0").port("MyService");
    const PortInfo consumer = component("MyServiceConsumer0").port("MyService");
    const ConnectorInfo made = PortConnection::connect({consumer, provider}, {}, "consumer");
    QCOMPARE(component("MyServiceProvider0").port("MyService").connectors.at(0).id, made.id);
    QVERIFY(!hasProperty(made.properties, "dataport.dataflow_type"));
    PortConnection::disconnect(consumer, made.id, "consumer");

    QCOMPARE(kindOf([&] {
                 PortConnection::connect({provider, provider}, {}, "p");
             }),
             Error::Kind::Incompatible);
    QCOMPARE(kindOf([&] {
                 PortConnection::connect({provider, component("ConsoleOut0").port("in")}, {}, "p");
             }),
             Error::Kind::Incompatible);
    QVERIFY(component("MyServiceProvider0").port("MyService").connectors.empty());
}

void TestCorbaClient::drivesTheManager()
{
    const RtPath mgrPath = path("manager.mgr");
    const ManagerProxy manager(NamingBrowser::resolve(mgrPath), mgrPath.toString());
    QVERIFY(manager.isMaster());
    QCOMPARE(propertyValue(manager.profile(), "instance_name"), QString("manager"));
    QCOMPARE(manager.components().size(), 7);
    QCOMPARE(manager.componentProfiles().at(1).instanceName, QString("ConsoleOut0"));
    QCOMPARE(manager.componentsByName("SeqIn0").size(), 1);
    QCOMPARE(manager.factoryProfiles().size(), size_t(7));
    QCOMPARE(manager.loadableModules().size(), size_t(7));

    manager.loadModule("Motor.so", "MotorInit");
    QCOMPARE(propertyValue(manager.loadedModules().at(0), "file_path"), QString("Motor.so"));
    manager.unloadModule("Motor.so");
    QVERIFY(manager.loadedModules().empty());
    QCOMPARE(kindOf([&] { manager.unloadModule("Motor.so"); }), Error::Kind::Refused);

    const QString ior
        = manager.createComponent("Motor?exec_cxt.periodic.rate=10&instance_name=Motor7");
    QCOMPARE(ComponentProxy(ior, "Motor7").profile().instanceName, QString("Motor7"));
    QCOMPARE(NamingBrowser::node(path("Motor7.rtc")).type, NodeType::Component);
    QCOMPARE(kindOf([&] { manager.createComponent("Motor?instance_name=Motor7"); }),
             Error::Kind::Refused);
    QCOMPARE(kindOf([&] { manager.createComponent("NoSuchType"); }), Error::Kind::Refused);
    // An OpenRTM-aist manager has no create_components: the caller is told so, nothing is made.
    QVERIFY(!manager.createComponents({"Motor?instance_name=Motor8"}));
    QVERIFY(manager.componentsByName("Motor8").isEmpty());
    manager.deleteComponent("Motor7");
    QCOMPARE(kindOf([&] { NamingBrowser::node(path("Motor7.rtc")); }), Error::Kind::NotFound);
    QCOMPARE(kindOf([&] { manager.deleteComponent("Motor7"); }), Error::Kind::Refused);

    manager.setConfiguration("logger.enable", "NO");
    QCOMPARE(propertyValue(manager.configuration(), "logger.enable"), QString("NO"));

    manager.addSlaveManager(manager.ior());
    QCOMPARE(manager.slaveManagers().size(), 1);
    QCOMPARE(NamingBrowser::list(mgrPath).back().name, QString("slave0.mgr"));
    manager.removeSlaveManager(manager.ior());
    QVERIFY(manager.slaveManagers().isEmpty());
    manager.addMasterManager(manager.ior());
    QCOMPARE(manager.masterManagers().size(), 1);
    manager.removeMasterManager(manager.ior());
    QCOMPARE(kindOf([&] { manager.removeMasterManager(manager.ior()); }), Error::Kind::Refused);
    QCOMPARE(kindOf([&] { manager.fork(); }), Error::Kind::Refused);
    QCOMPARE(kindOf([&] { manager.restart(); }), Error::Kind::Refused);
    QVERIFY(manager.service("anything").isEmpty());
}

void TestCorbaClient::managerReachableByCorbaloc()
{
    const auto direct = RtPath::parse(QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_peerPort));
    QVERIFY(direct.has_value());
    QCOMPARE(NamingBrowser::node(*direct).type, NodeType::Manager);
    const ManagerProxy manager(NamingBrowser::resolve(*direct), direct->toString());
    QVERIFY(manager.isMaster());
    QCOMPARE(NamingBrowser::list(*direct).size(), size_t(7));
}

void TestCorbaClient::exitedComponentIsGone()
{
    QString error;
    QVERIFY2(m_live.startPeer({"ConsoleIn?instance_name=Leaving0"}, &error, nullptr, "exithost"),
             qPrintable(error));
    const auto p = RtPath::parse(
        QStringLiteral("/%1/exithost.host_cxt/Leaving0.rtc").arg(m_live.namingServer()));
    const ComponentProxy leaving(NamingBrowser::resolve(*p), p->toString());
    leaving.exit();
    QCOMPARE(kindOf([&] { leaving.profile(); }), Error::Kind::ObjectNotExist);
    const QString message = messageOf([&] { leaving.profile(); });
    QVERIFY2(message.startsWith(p->toString() + ": object does not exist"), qPrintable(message));
}

void TestCorbaClient::bindsAndUnbindsNames()
{
    // An object bound under a new name, then the zombie cleared the way "kill zombies" does.
    const QString ior = NamingBrowser::resolve(path("ConsoleIn0.rtc"));
    NamingBrowser::bind(path("Alias0.rtc"), ior);
    QCOMPARE(NamingBrowser::node(path("Alias0.rtc")).type, NodeType::Component);
    QCOMPARE(
        ComponentProxy(NamingBrowser::resolve(path("Alias0.rtc")), "alias").profile().instanceName,
        QString("ConsoleIn0"));
    NamingBrowser::unbind(path("Alias0.rtc"));
    QCOMPARE(kindOf([&] { NamingBrowser::node(path("Alias0.rtc")); }), Error::Kind::NotFound);
    QCOMPARE(kindOf([&] { NamingBrowser::unbind(path("Alias0.rtc")); }), Error::Kind::NotFound);
    const auto nowhere
        = RtPath::parse(QStringLiteral("/%1/none.host_cxt/X.rtc").arg(m_live.namingServer()));
    QCOMPARE(kindOf([&] { NamingBrowser::bind(*nowhere, ior); }), Error::Kind::NotFound);
}

void TestCorbaClient::shutsTheManagerDown()
{
    QString error;
    quint16 port = 0;
    QProcess *peer = m_live.startPeer({"ConsoleIn"}, &error, &port, "downhost");
    QVERIFY2(peer, qPrintable(error));
    const auto direct = RtPath::parse(QStringLiteral("corbaloc::127.0.0.1:%1").arg(port));
    const ManagerProxy manager(NamingBrowser::resolve(*direct), direct->toString());
    manager.shutdown();
    QVERIFY(peer->waitForFinished(10000));
    QCOMPARE(peer->exitCode(), 0);
    // Depending on whether the old connection is noticed as closed first, the peer is gone either
    // way.
    const Error::Kind gone = kindOf([&] { manager.isMaster(); });
    QVERIFY2(gone == Error::Kind::Transient || gone == Error::Kind::CommFailure,
             qPrintable(Error::kindName(gone)));
    const auto context
        = RtPath::parse(QStringLiteral("/%1/downhost.host_cxt").arg(m_live.namingServer()));
    QVERIFY(NamingBrowser::list(*context).empty());
}

void TestCorbaClient::unreachablePeersGiveTypedErrors()
{
    const quint16 nobody = LiveTest::freePort();
    const auto server = RtPath::parse(QStringLiteral("/127.0.0.1:%1").arg(nobody));
    QCOMPARE(kindOf([&] { NamingBrowser::list(*server); }), Error::Kind::Transient);
    const QString message = messageOf([&] { NamingBrowser::list(*server); });
    QVERIFY2(message.startsWith(QStringLiteral("/127.0.0.1:%1: unreachable").arg(nobody)),
             qPrintable(message));
    const auto direct = RtPath::parse(QStringLiteral("corbaloc::127.0.0.1:%1").arg(nobody));
    const ManagerProxy manager(direct->corbaloc, direct->toString());
    QCOMPARE(kindOf([&] { manager.isMaster(); }), Error::Kind::Transient);
    QCOMPARE(kindOf([&] { ComponentProxy("not an ior", "bad").profile(); }), Error::Kind::BadPath);
    // Unreachable servers listed at the root show up as zombies instead of failing the listing.
    const NamingNode root
        = NamingBrowser::tree(*RtPath::parse("/"), 2, {QStringLiteral("127.0.0.1:%1").arg(nobody)});
    QCOMPARE(root.children.at(0).type, NodeType::Zombie);
}

void TestCorbaClient::stoppedPeerTimesOut()
{
    QString error;
    QProcess *peer
        = m_live.startPeer({"ConsoleIn?instance_name=Frozen0"}, &error, nullptr, "frozenhost");
    QVERIFY2(peer, qPrintable(error));
    const auto p = RtPath::parse(
        QStringLiteral("/%1/frozenhost.host_cxt/Frozen0.rtc").arg(m_live.namingServer()));
    const ComponentProxy frozen(NamingBrowser::resolve(*p), p->toString());
    QCOMPARE(frozen.state(), LifeCycleState::Inactive); // the connection is open before the stop

    const int timeout = 700;
    Orb::setCallTimeout(timeout);
    QCOMPARE(::kill(pid_t(peer->processId()), SIGSTOP), 0);
    QVERIFY2(LiveTest::waitUntilStopped(peer->processId()), "the peer did not stop");
    QElapsedTimer timer;
    timer.start();
    const Error::Kind kind = kindOf([&] { frozen.state(); });
    const qint64 elapsed = timer.elapsed();
    ::kill(pid_t(peer->processId()), SIGCONT);
    Orb::setCallTimeout(2000);
    QCOMPARE(kind, Error::Kind::Timeout);
    QVERIFY2(elapsed >= timeout - 50 && elapsed < timeout + 1500,
             qPrintable(QString::number(elapsed)));
    // A zombie check of the same name does not hang either: it is reported and the peer recovers.
    QCOMPARE(frozen.state(), LifeCycleState::Inactive);
}

void TestCorbaClient::callsFromWorkerThreads()
{
    std::atomic<int> good {0};
    std::vector<std::thread> threads;
    const QString ior = NamingBrowser::resolve(path("ConsoleIn0.rtc"));
    for (int i = 0; i < 4; ++i) {
        threads.emplace_back([&] {
            for (int n = 0; n < 10; ++n) {
                if (ComponentProxy(ior, "worker").profile().instanceName == "ConsoleIn0")
                    ++good;
            }
        });
    }
    for (std::thread &thread : threads)
        thread.join();
    QCOMPARE(good.load(), 40);
}

QTEST_GUILESS_MAIN(TestCorbaClient)
#include "tst_corbaclient.moc"
