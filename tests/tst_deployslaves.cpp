// SPDX-License-Identifier: MIT
// Restores spread over a master rtmanager and two slaves it starts (manager_address, one per saved
// host) or a slave named by manager_name: creation from nothing, start/stop order across the
// processes, a slave killed mid-restore, and cryo → restore → cryo keeping the spread.
#include "componentproxy.h"
#include "corbaerror.h"
#include "cryo.h"
#include "livesystem.h"
#include "managerproxy.h"
#include "namingbrowser.h"
#include "orb.h"
#include "portconnection.h"
#include "sequencerunner.h"
#include "tst_deploysupport.h"

#include <QRegularExpression>
#include <QtTest>

#include <csignal>

#include <memory>

using namespace Deploy;
using namespace DeployTest;

class TestDeploySlaves : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void createsFromNothingOnMasterAndTwoSlaves();
    void startAndStopFollowTheOrderAcrossProcesses();
    void findsComponentsOnANamedSlave();
    void slaveKilledMidRestoreRollsBackTheOthers();
    void restoresAgainAfterASlaveDied();
    void connectIgnoresAConnectorToAGonePort();
    void cryoRestoreCryoKeepsTheSpread();

private:
    TargetOptions target() const;
    /// ordered.xml with Mid0 saved on hostB and Sink0 on hostC.
    Profile::RtsProfile spreadSystem() const;
    Corba::ManagerProxy master() const;
    /// Instance name → "master" or the IOR of the slave that hosts it.
    QHash<QString, QString> hostingManagers() const;
    QStringList liveInstances() const;
    Corba::ComponentProxy live(const QString &instance) const;
    void checkSpread(const QStringList &onSlaves);

    std::unique_ptr<LiveTest::LiveSystem> m_live;
    quint16 m_managerPort = 0;
};

void TestDeploySlaves::initTestCase()
{
    // Creating a component on a new slave starts a process: allow for it.
    Corba::Orb::setCallTimeout(20000);
}

// Components are named after the manager that hosts them (%M), as OpenRTM names them after the
// host (%h): a saved system shows where each component ran.
void TestDeploySlaves::init()
{
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(startManager(*m_live, "%M.host_cxt/%n.rtc", "managers.host_cxt/%n.mgr", &m_managerPort,
                          &error),
             qPrintable(error));
}

void TestDeploySlaves::cleanup()
{
    m_live.reset();
}

TargetOptions TestDeploySlaves::target() const
{
    TargetOptions options;
    options.nameServers = {m_live->namingServer()};
    options.manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_managerPort);
    options.create = true;
    for (const char *host : {"hostB", "hostC"})
        options.hostManagers.insert(host, QStringLiteral("127.0.0.1:%1").arg(LiveTest::freePort()));
    return options;
}

Profile::RtsProfile TestDeploySlaves::spreadSystem() const
{
    Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    profile.component("Mid0")->pathUri = m_live->namingServer() + "/hostB.host_cxt/Mid0.rtc";
    profile.component("Sink0")->pathUri = m_live->namingServer() + "/hostC.host_cxt/Sink0.rtc";
    return profile;
}

Corba::ManagerProxy TestDeploySlaves::master() const
{
    return Corba::ManagerProxy(ComponentMapper::resolveManager(target().manager), "master");
}

QHash<QString, QString> TestDeploySlaves::hostingManagers() const
{
    QHash<QString, QString> hosts;
    for (const Corba::ComponentInfo &info : master().componentProfiles())
        hosts.insert(info.instanceName, QStringLiteral("master"));
    for (const QString &slave : master().slaveManagers()) {
        for (const Corba::ComponentInfo &info :
             Corba::ManagerProxy(slave, "slave").componentProfiles())
            hosts.insert(info.instanceName, slave);
    }
    return hosts;
}

QStringList TestDeploySlaves::liveInstances() const
{
    return DeployTest::liveInstances(m_live->namingServer());
}

Corba::ComponentProxy TestDeploySlaves::live(const QString &instance) const
{
    const auto found = ComponentMapper::liveComponents({"/" + m_live->namingServer()}, nullptr);
    const auto it = found.find(instance);
    if (it == found.end())
        return Corba::ComponentProxy(QString(), instance);
    return Corba::ComponentProxy(it->ior, it->path);
}

// Src0 on the master, each of `onSlaves` on a slave of its own.
void TestDeploySlaves::checkSpread(const QStringList &onSlaves)
{
    const QHash<QString, QString> hosts = hostingManagers();
    QCOMPARE(hosts.value("Src0"), QString("master"));
    QSet<QString> slaves;
    for (const QString &name : onSlaves) {
        QVERIFY2(hosts.contains(name) && hosts.value(name) != "master", qPrintable(name));
        slaves.insert(hosts.value(name));
    }
    QCOMPARE(slaves.size(), onSlaves.size());
    QCOMPARE(master().slaveManagers().size(), onSlaves.size());
}

void TestDeploySlaves::createsFromNothingOnMasterAndTwoSlaves()
{
    const Profile::RtsProfile profile = spreadSystem();
    const TargetOptions options = target();
    const RestorePlan plan = planRestore(profile, options);
    QVERIFY2(plan.component("Mid0")->createArgument.endsWith("&manager_address="
                                                             + options.hostManagers.value("hostB")),
             qPrintable(plan.toText()));
    QVERIFY2(plan.component("Sink0")->createArgument.endsWith(
                 "&manager_address=" + options.hostManagers.value("hostC")),
             qPrintable(plan.toText()));
    QVERIFY(!plan.component("Src0")->createArgument.contains("manager_address"));
    QVERIFY(liveInstances().isEmpty());

    const DeployReport report = restoreSystem(profile, plan, options);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(doneSubjects(report, "create"), QStringList({"Src0", "Mid0", "Sink0"}));
    QCOMPARE(liveInstances(), QStringList({"Mid0", "Sink0", "Src0"}));
    checkSpread({"Mid0", "Sink0"});
    // The connector crosses from the master's process into hostB's slave.
    const auto connectors = live("Src0").port("out").connectors;
    QCOMPARE(connectors.size(), size_t(1));
    QCOMPARE(connectors.front().id, QString("conn-src-mid"));
    QCOMPARE(live("Mid0").port("in").connectors.front().id, QString("conn-src-mid"));
    QCOMPARE(live("Sink0").executionContexts().front().rate, 200.0);

    // Restoring again finds all three where they are and changes nothing.
    const DeployReport again = restoreSystem(profile, planRestore(profile, options), options);
    QVERIFY2(again.ok, qPrintable(again.toText()));
    QVERIFY(doneSubjects(again, "create").isEmpty());
    QCOMPARE(master().slaveManagers().size(), 2);
}

void TestDeploySlaves::startAndStopFollowTheOrderAcrossProcesses()
{
    const Profile::RtsProfile profile = spreadSystem();
    const TargetOptions options = target();
    QVERIFY2(restoreSystem(profile, planRestore(profile, options), options).ok, "restore");
    const RestorePlan plan = planRestore(profile, options);
    Corba::LifeCycleState srcWhenMidSent = Corba::LifeCycleState::Unknown;
    DeployControl control;
    control.progress = [&](const DeployStep &step) {
        if (step.action == "activate" && step.subject == "Mid0.0"
            && step.status == StepStatus::Running)
            srcWhenMidSent = live("Src0").state();
    };
    const DeployReport started = startSystem(profile, plan, control);
    QVERIFY2(started.ok, qPrintable(started.toText()));
    QCOMPARE(doneSubjects(started, "activate"), QStringList({"Sink0.0", "Src0.0", "Mid0.0"}));
    QCOMPARE(srcWhenMidSent, Corba::LifeCycleState::Active);
    for (const char *name : {"Src0", "Mid0", "Sink0"})
        QCOMPARE(live(name).state(), Corba::LifeCycleState::Active);

    const DeployReport stopped = stopSystem(profile, plan);
    QVERIFY2(stopped.ok, qPrintable(stopped.toText()));
    QCOMPARE(doneSubjects(stopped, "deactivate"), QStringList({"Src0.0", "Mid0.0", "Sink0.0"}));
    for (const char *name : {"Src0", "Mid0", "Sink0"})
        QCOMPARE(live(name).state(), Corba::LifeCycleState::Inactive);
}

// Sink0 already runs on a slave started by name (manager_name); Mid0 goes to hostB's address.
void TestDeploySlaves::findsComponentsOnANamedSlave()
{
    master().createComponent("ConsoleOut?instance_name=Sink0&manager_name=namedslave");
    QCOMPARE(master().slaveManagers().size(), 1);
    Profile::RtsProfile profile = spreadSystem();
    profile.component("Sink0")->pathUri = m_live->namingServer() + "/namedslave.host_cxt/Sink0.rtc";
    const TargetOptions options = target();
    const RestorePlan plan = planRestore(profile, options);
    QCOMPARE(plan.component("Sink0")->kind, MappingKind::Existing);
    QCOMPARE(plan.component("Mid0")->kind, MappingKind::Create);
    const DeployReport report = restoreSystem(profile, plan, options);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(doneSubjects(report, "create"), QStringList({"Src0", "Mid0"}));
    checkSpread({"Mid0", "Sink0"});
    QVERIFY(live("Sink0").path().contains("/namedslave.host_cxt/"));
}

// Both slaves are up when hostC's dies, as the connection is being made: everything done is undone
// where it still can be, and the dead slave's component says why it was not.
void TestDeploySlaves::slaveKilledMidRestoreRollsBackTheOthers()
{
    const Profile::RtsProfile profile = spreadSystem();
    const TargetOptions options = target();
    qint64 killed = 0;
    DeployControl control;
    control.progress = [&](const DeployStep &step) {
        if (step.action != "connect" || step.status != StepStatus::Running || killed)
            return;
        const QString sinkHost = hostingManagers().value("Sink0");
        if (sinkHost.isEmpty() || sinkHost == "master")
            return;
        killed = Corba::propertyValue(Corba::ManagerProxy(sinkHost, "slave").profile(), "pid")
                     .toLongLong();
        if (killed > 0)
            ::kill(pid_t(killed), SIGKILL);
    };
    const DeployReport report
        = restoreSystem(profile, planRestore(profile, options), options, control);
    QVERIFY(killed > 0);
    QVERIFY(!report.ok);
    // The connection (between the master and hostB) is made; the next step on Sink0 fails.
    QVERIFY2(report.error.contains("Sink0.rtc"), qPrintable(report.toText()));
    QCOMPARE(report.stepsWith(StepStatus::RolledBack).size(), 4);
    QCOMPARE(stepMessage(report, "connect", "conn-src-mid"), QString("undone"));
    QCOMPARE(stepMessage(report, "create", "Src0"), QString("undone"));
    QCOMPARE(stepMessage(report, "create", "Mid0"), QString("undone"));
    QVERIFY2(stepMessage(report, "create", "Sink0").startsWith("undo failed"),
             qPrintable(report.toText()));
    QTRY_VERIFY(liveInstances().isEmpty());
    // hostB's slave survived its component's removal and still answers.
    QTRY_COMPARE(master().slaveManagers().size(), 1);
    QVERIFY(Corba::ManagerProxy(master().slaveManagers().first(), "slave").components().isEmpty());
}

// hostB's slave dies with Mid0, and Src0 keeps its connector to the dead port: restoring again
// creates Mid0 on a new slave and connects it in place of the broken connector.
void TestDeploySlaves::restoresAgainAfterASlaveDied()
{
    const Profile::RtsProfile profile = spreadSystem();
    const TargetOptions options = target();
    QVERIFY(restoreSystem(profile, planRestore(profile, options), options).ok);
    const QString midHost = hostingManagers().value("Mid0");
    QVERIFY(!midHost.isEmpty() && midHost != "master");
    const qint64 pid
        = Corba::propertyValue(Corba::ManagerProxy(midHost, "slave").profile(), "pid").toLongLong();
    QVERIFY(pid > 0);
    const auto connected = live("Src0").port("out").connectors;
    QCOMPARE(connected.size(), size_t(1));
    QVERIFY(!Corba::PortConnection::hasEndGone(connected.front()));
    QCOMPARE(::kill(pid_t(pid), SIGKILL), 0);
    QTRY_COMPARE(master().slaveManagers().size(), 1);
    const auto broken = live("Src0").port("out").connectors;
    QCOMPARE(broken.size(), size_t(1));
    QCOMPARE(broken.front().id, QString("conn-src-mid"));
    // The end that has gone keeps the name read while it answered (a port's reference is its
    // own), and is found gone by asking it.
    QCOMPARE(broken.front().ports, QStringList({"Src0.out", "Mid0.in"}));
    QCOMPARE(broken.front().portIors, connected.front().portIors);
    QVERIFY(Corba::PortConnection::hasEndGone(broken.front()));

    const DeployReport again = restoreSystem(profile, planRestore(profile, options), options);
    QVERIFY2(again.ok, qPrintable(again.toText()));
    QCOMPARE(doneSubjects(again, "create"), QStringList({"Mid0"}));
    QCOMPARE(stepMessage(again, "connect", "conn-src-mid"),
             QString("Src0.out -> Mid0.in (replaced a broken connector)"));
    checkSpread({"Mid0", "Sink0"});
    const auto connectors = live("Src0").port("out").connectors;
    QCOMPARE(connectors.size(), size_t(1));
    QCOMPARE(connectors.front().ports, QStringList({"Src0.out", "Mid0.in"}));
    QCOMPARE(live("Mid0").port("in").connectors.front().id, QString("conn-src-mid"));
}

void TestDeploySlaves::connectIgnoresAConnectorToAGonePort()
{
    const Profile::RtsProfile profile = spreadSystem();
    const TargetOptions options = target();
    QVERIFY(restoreSystem(profile, planRestore(profile, options), options).ok);
    const QString midHost = hostingManagers().value("Mid0");
    const qint64 pid
        = Corba::propertyValue(Corba::ManagerProxy(midHost, "slave").profile(), "pid").toLongLong();
    QVERIFY(pid > 0);
    QCOMPARE(::kill(pid_t(pid), SIGKILL), 0);
    QTRY_COMPARE(master().slaveManagers().size(), 1);
    // A new Mid0 in the master: its port has the name of the one that has gone, not its reference.
    master().createComponent("ConsoleOut?instance_name=Mid0");
    const Corba::PortInfo source = live("Src0").port("out");
    QCOMPARE(source.connectors.size(), size_t(1));
    QCOMPARE(source.connectors.front().ports, QStringList({"Src0.out", "Mid0.in"}));
    Corba::ConnectionRequest request;
    request.noDuplicates = true;
    const Corba::PortInfo mid = live("Mid0").port("in");
    Corba::PortConnection::connect({source, mid}, request, "Src0");
    const Corba::PortInfo connected = live("Src0").port("out");
    QCOMPARE(connected.connectors.size(), size_t(2));
    // The connector to the live port is one.
    bool refused = false;
    try {
        Corba::PortConnection::connect({connected, mid}, request, "Src0");
    } catch (const Corba::Error &e) {
        refused = e.kind() == Corba::Error::Kind::Refused;
    }
    QVERIFY(refused);
}

void TestDeploySlaves::cryoRestoreCryoKeepsTheSpread()
{
    const TargetOptions options = target();
    QVERIFY(restoreSystem(spreadSystem(), planRestore(spreadSystem(), options), options).ok);
    CryoOptions cryo;
    cryo.name = "Spread";
    cryo.paths = {"/" + m_live->namingServer()};
    DeployReport report;
    Profile::RtsProfile first = cryoSystem(cryo, &report);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(first.components.size(), 3);

    // Each saved slave host is given an address of its own on the fresh system.
    const QString firstServer = m_live->namingServer();
    cleanup();
    init();
    TargetOptions fresh = target();
    fresh.hostManagers.clear();
    const QRegularExpression slaveHost(QStringLiteral("/(manager_\\d+)\\.host_cxt/"));
    for (const auto &component : first.components) {
        const QString host = slaveHost.match(component.pathUri).captured(1);
        if (!host.isEmpty())
            fresh.hostManagers.insert(host,
                                      QStringLiteral("127.0.0.1:%1").arg(LiveTest::freePort()));
    }
    QCOMPARE(fresh.hostManagers.size(), 2);
    const DeployReport restored = restoreSystem(first, planRestore(first, fresh), fresh);
    QVERIFY2(restored.ok, qPrintable(restored.toText()));
    checkSpread({"Mid0", "Sink0"});
    cryo.paths = {"/" + m_live->namingServer()};
    Profile::RtsProfile second = cryoSystem(cryo, &report);
    QVERIFY2(report.ok, qPrintable(report.toText()));

    // What may differ: dates, IORs, the name server's address and the slaves' process ids.
    auto normalise = [&](Profile::RtsProfile &profile, const QString &server) {
        profile.creationDate.clear();
        profile.updateDate.clear();
        for (auto &component : profile.components) {
            component.properties.clear();
            component.pathUri.replace(server, "NS").replace(slaveHost, "/slave.host_cxt/");
        }
        for (auto &connector : profile.dataPortConnectors) {
            for (auto *end : {&connector.source, &connector.target}) {
                for (auto &property : end->properties)
                    property.value = property.value->replace(server, "NS")
                                         .replace(slaveHost, "/slave.host_cxt/");
            }
        }
    };
    normalise(first, firstServer);
    normalise(second, m_live->namingServer());
    QCOMPARE(first.component("Mid0")->pathUri, QString("NS/slave.host_cxt/Mid0.rtc"));
    QCOMPARE(first.component("Src0")->pathUri, QString("NS/manager.host_cxt/Src0.rtc"));
    QCOMPARE(second.components.size(), first.components.size());
    for (int i = 0; i < first.components.size(); ++i)
        QVERIFY2(first.components.at(i) == second.components.at(i),
                 qPrintable(first.components.at(i).instanceName));
    QVERIFY(first.dataPortConnectors == second.dataPortConnectors);
    QVERIFY(first == second);
}

QTEST_GUILESS_MAIN(TestDeploySlaves)
#include "tst_deployslaves.moc"
