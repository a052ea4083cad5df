// SPDX-License-Identifier: MIT
// The deployment engine against real omniNames and rtmanager processes: restore (mapping by
// instance name, --create, rollback), teardown, start/stop order, cryo round trip and drift.
#include "componentproxy.h"
#include "cryo.h"
#include "drift.h"
#include "livesystem.h"
#include "managerproxy.h"
#include "namingbrowser.h"
#include "orb.h"
#include "portconnection.h"
#include "profileio.h"
#include "restorer.h"
#include "rtsprofile.h"
#include "sequencerunner.h"
#include "tst_deploysupport.h"

#include <QtTest>

#include <atomic>
#include <csignal>

#include <memory>

using namespace Deploy;
using namespace DeployTest;

class TestDeploy : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void restoresBundledExamples_data();
    void restoresBundledExamples();
    void dryRunPlanChangesNothing();
    void teardownReadsAgainWhatChangedSincePlanning();
    void restoreCreatesFromNothing();
    void configurationAndRates();
    void failedRestoreRollsBack();
    void cancelledRestoreRollsBack();
    void slaveKilledMidRestoreRollsBack();
    void conformanceSystemsFailCleanly_data();
    void conformanceSystemsFailCleanly();
    void startAndStopFollowDeclaredOrder();
    void syncTimeoutCancelsThePlan();
    void waitTimesCountFromThePlanStart();
    void precedingWaitsForItsComponents();
    void cancelEndsEveryWait();
    void cryoRestoreCryoGivesTheSameSystem();
    void diffListsDrift();
    void diffReadsAgainWhatChangedSincePlanning();

private:
    TargetOptions target(bool create) const;
    Corba::ComponentProxy live(const QString &instance) const;
    QStringList liveInstances() const;
    DeployReport restore(const Profile::RtsProfile &profile, bool create);

    std::unique_ptr<LiveTest::LiveSystem> m_live;
    quint16 m_managerPort = 0;
};

void TestDeploy::initTestCase()
{
    // Creating a component on a new slave starts a process: allow for it.
    Corba::Orb::setCallTimeout(20000);
}

void TestDeploy::init()
{
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(startManager(*m_live, "deployhost.host_cxt/%n.rtc", "deployhost.host_cxt/%n.mgr",
                          &m_managerPort, &error),
             qPrintable(error));
}

void TestDeploy::cleanup()
{
    m_live.reset();
}

TargetOptions TestDeploy::target(bool create) const
{
    TargetOptions options;
    options.nameServers = {m_live->namingServer()};
    options.manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_managerPort);
    options.create = create;
    return options;
}

Corba::ComponentProxy TestDeploy::live(const QString &instance) const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/deployhost.host_cxt/%2.rtc").arg(m_live->namingServer(), instance));
    return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString());
}

QStringList TestDeploy::liveInstances() const
{
    return DeployTest::liveInstances(m_live->namingServer());
}

DeployReport TestDeploy::restore(const Profile::RtsProfile &profile, bool create)
{
    const TargetOptions options = target(create);
    return restoreSystem(profile, planRestore(profile, options), options);
}

void TestDeploy::restoresBundledExamples_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("ConsoleInOut") << "ConsoleInOut/ConsoleInOut.xml";
    QTest::newRow("SeqIO") << "SeqIO/SeqIO.xml";
}

// The examples' pathUri values are offline RTCs/x.xml files: components are found by instance name.
void TestDeploy::restoresBundledExamples()
{
    QFETCH(QString, file);
    const Profile::RtsProfile profile
        = loadSystem((RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/")) + file);
    const Corba::ManagerProxy manager(ComponentMapper::resolveManager(target(false).manager),
                                      QStringLiteral("manager"));
    for (const auto &component : profile.components)
        manager.createComponent(ComponentMapper::typeNameOf(component.id)
                                + QStringLiteral("?instance_name=") + component.instanceName);

    const RestorePlan plan = planRestore(profile, target(false));
    for (const ComponentMapping &mapping : plan.components)
        QCOMPARE(mapping.kind, MappingKind::Existing);
    const DeployReport report = restoreSystem(profile, plan, target(false));
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(doneSubjects(report, "connect").size(), profile.dataPortConnectors.size());
    for (const auto &connector : profile.dataPortConnectors) {
        const Corba::PortInfo port
            = live(connector.source.instanceName).port(connector.source.portName.section('.', 1));
        QCOMPARE(port.connectors.size(), size_t(1));
        QCOMPARE(port.connectors.front().id, connector.connectorId);
        QCOMPARE(
            Corba::propertyValue(port.connectors.front().properties, "dataport.subscription_type"),
            connector.subscriptionType.value_or("new"));
        QVERIFY(!Corba::propertyValue(port.connectors.front().properties,
                                      "dataport.corba_cdr.inport_ior")
                     .startsWith("IOR:0000stale"));
    }
    // A second restore finds everything done.
    const DeployReport again
        = restoreSystem(profile, planRestore(profile, target(false)), target(false));
    QVERIFY2(again.ok, qPrintable(again.toText()));
    QVERIFY(doneSubjects(again, "connect").isEmpty());

    const DeployReport teardown = teardownSystem(planRestore(profile, target(false)));
    QVERIFY2(teardown.ok, qPrintable(teardown.toText()));
    QCOMPARE(doneSubjects(teardown, "disconnect").size(), profile.dataPortConnectors.size());
    for (const auto &connector : profile.dataPortConnectors)
        QVERIFY(live(connector.source.instanceName)
                    .port(connector.source.portName.section('.', 1))
                    .connectors.empty());
}

// Teardown starts from the ports the plan read and reads them again where they no longer hold.
void TestDeploy::teardownReadsAgainWhatChangedSincePlanning()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    QVERIFY(!profile.dataPortConnectors.isEmpty());
    QVERIFY2(restoreSystem(profile, planRestore(profile, target(true)), target(true)).ok, "restore");
    QVERIFY2(teardownSystem(planRestore(profile, target(false))).ok, "teardown");
    // Planned while the components were there unconnected: each connector made since is found
    // when its component is read again.
    const RestorePlan unconnected = planRestore(profile, target(false));
    QVERIFY2(restoreSystem(profile, unconnected, target(false)).ok, "restore");
    DeployReport report = teardownSystem(unconnected);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(doneSubjects(report, "disconnect").size(), profile.dataPortConnectors.size());

    // Planned while connected; one connector removed behind the plan's back is skipped, the
    // others are disconnected.
    QVERIFY2(restoreSystem(profile, planRestore(profile, target(false)), target(false)).ok, "restore");
    const RestorePlan connected = planRestore(profile, target(false));
    const auto &gone = profile.dataPortConnectors.front();
    const Corba::PortInfo port = live(gone.source.instanceName).port(gone.source.portName.section('.', 1));
    Corba::PortConnection::disconnect(port, gone.connectorId, gone.source.instanceName);
    report = teardownSystem(connected);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(doneSubjects(report, "disconnect").size(), profile.dataPortConnectors.size() - 1);
    bool skipped = false;
    for (const DeployStep &step : report.steps) {
        if (step.subject == gone.connectorId)
            skipped = step.status == StepStatus::Skipped && step.message == "not connected";
    }
    QVERIFY2(skipped, qPrintable(report.toText()));
    for (const auto &connector : profile.dataPortConnectors)
        QVERIFY(live(connector.source.instanceName)
                    .port(connector.source.portName.section('.', 1))
                    .connectors.empty());
}

void TestDeploy::dryRunPlanChangesNothing()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    const RestorePlan missing = planRestore(profile, target(false));
    QCOMPARE(missing.missingRequired().size(), 3);
    const RestorePlan plan = planRestore(profile, target(true));
    QVERIFY(plan.missingRequired().isEmpty());
    const QString text = plan.toText();
    QVERIFY2(text.contains("component Src0 create (ConsoleIn?instance_name=Src0"
                           "&exec_cxt.periodic.rate=200)"),
             qPrintable(text));
    QVERIFY2(text.contains("connect conn-src-mid Src0.out -> Mid0.in"), qPrintable(text));
    QVERIFY(liveInstances().isEmpty());
    // Without --create a missing required component fails before anything is done.
    const DeployReport report = restoreSystem(profile, missing, target(false));
    QVERIFY(!report.ok);
    QVERIFY2(report.error.startsWith("find Src0"), qPrintable(report.error));
    QVERIFY(doneSubjects(report, "connect").isEmpty());
}

void TestDeploy::restoreCreatesFromNothing()
{
    const Profile::RtsProfile profile
        = loadSystem(RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/" "ConsoleInOut.xml"));
    QList<DeployStep> progress;
    DeployControl control;
    control.progress = [&](const DeployStep &step) { progress.append(step); };
    const TargetOptions options = target(true);
    const DeployReport report
        = restoreSystem(profile, planRestore(profile, options), options, control);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(doneSubjects(report, "create"), QStringList({"ConsoleIn0", "ConsoleOut0"}));
    QCOMPARE(liveInstances(), QStringList({"ConsoleIn0", "ConsoleOut0"}));
    // Every step was announced running, then finished.
    QCOMPARE(progress.first().status, StepStatus::Running);
    QCOMPARE(progress.size(), report.steps.size() * 2);
    const auto ecs = live("ConsoleIn0").executionContexts();
    QCOMPARE(ecs.front().rate, 1000.0);
    QCOMPARE(live("ConsoleIn0").port("out").connectors.front().id,
             profile.dataPortConnectors.front().connectorId);
}

void TestDeploy::configurationAndRates()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("configured.xml"));
    const DeployReport report = restore(profile, true);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    // The optional component of an unknown type fails without failing the restore.
    const DeployStep *optional = findStep(report, "create", "Opt0");
    QVERIFY(optional);
    QCOMPARE(optional->status, StepStatus::Failed);
    const Corba::ComponentProxy conf = live("Conf0");
    QCOMPARE(conf.activeConfigurationSet(), QString("mode0"));
    QCOMPARE(conf.parameter("default", "int_param0"), QString("7"));
    QCOMPARE(conf.parameter("mode0", "str_param0"), QString("restored"));
    QCOMPARE(conf.parameter("mode0", "int_param1"), QString("98765"));
    QCOMPARE(conf.parameter("extra", "int_param0"), QString("42"));
    QCOMPARE(conf.executionContexts().front().rate, 50.0);

    // A rate changed afterwards is set back by the next restore.
    conf.setRate(20.0);
    const DeployReport again = restore(profile, false);
    QVERIFY2(again.ok, qPrintable(again.toText()));
    QCOMPARE(doneSubjects(again, "rate"), QStringList({"Conf0.0"}));
    QCOMPARE(conf.executionContexts().front().rate, 50.0);
}

void TestDeploy::failedRestoreRollsBack()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("broken.xml"));
    const DeployReport report = restore(profile, true);
    QVERIFY(!report.ok);
    QVERIFY2(report.error.startsWith("connect conn-bad"), qPrintable(report.error));
    QVERIFY2(report.error.contains("nosuchport"), qPrintable(report.error));
    const QList<DeployStep> undone = report.stepsWith(StepStatus::RolledBack);
    QStringList subjects;
    for (const DeployStep &step : undone)
        subjects.append(step.action + ' ' + step.subject);
    QCOMPARE(subjects, QStringList({"create Src0", "create Sink0", "connect conn-good"}));
    QTRY_VERIFY(liveInstances().isEmpty());
}

void TestDeploy::cancelledRestoreRollsBack()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    std::atomic_bool cancel {false};
    DeployControl control;
    control.cancel = &cancel;
    // Cancel as soon as the connection is made: the restore must undo it and the creations.
    control.progress = [&](const DeployStep &step) {
        if (step.action == "connect" && step.status == StepStatus::Done)
            cancel = true;
    };
    const TargetOptions options = target(true);
    const DeployReport report
        = restoreSystem(profile, planRestore(profile, options), options, control);
    QVERIFY(!report.ok);
    QVERIFY(report.cancelled);
    QCOMPARE(report.stepsWith(StepStatus::RolledBack).size(), 4);
    QTRY_VERIFY(liveInstances().isEmpty());
}

// Mid0 and Sink0 are saved under another host, whose manager the master starts as a slave; the
// slave dies just before the connection is made.
void TestDeploy::slaveKilledMidRestoreRollsBack()
{
    Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    for (const char *name : {"Mid0", "Sink0"})
        profile.component(name)->pathUri
            = QStringLiteral("%1/hostB.host_cxt/%2.rtc").arg(m_live->namingServer(), name);
    TargetOptions options = target(true);
    options.hostManagers.insert("hostB", QStringLiteral("127.0.0.1:%1").arg(LiveTest::freePort()));
    const RestorePlan plan = planRestore(profile, options);
    QVERIFY2(plan.component("Mid0")->createArgument.contains("&manager_address=127.0.0.1:"),
             qPrintable(plan.toText()));
    const Corba::ManagerProxy master(ComponentMapper::resolveManager(options.manager), "master");
    qint64 killed = 0;
    DeployControl control;
    control.progress = [&](const DeployStep &step) {
        if (step.action != "connect" || step.status != StepStatus::Running)
            return;
        const QStringList slaves = master.slaveManagers();
        if (slaves.size() != 1)
            return;
        killed = Corba::propertyValue(Corba::ManagerProxy(slaves.first(), "slave").profile(), "pid")
                     .toLongLong();
        if (killed > 0)
            ::kill(pid_t(killed), SIGKILL);
    };
    const DeployReport report = restoreSystem(profile, plan, options, control);
    QVERIFY(killed > 0);
    QVERIFY(!report.ok);
    QVERIFY2(report.error.startsWith("connect conn-src-mid"), qPrintable(report.toText()));
    const QList<DeployStep> undone = report.stepsWith(StepStatus::RolledBack);
    QCOMPARE(undone.size(), 3);
    // The master's component is undone; the slave's died with it and say so.
    const DeployStep *src = findStep(report, "create", "Src0");
    QCOMPARE(src->message, QString("undone"));
    QVERIFY2(findStep(report, "create", "Mid0")->message.startsWith("undo failed"),
             qPrintable(report.toText()));
    QTRY_VERIFY(liveInstances().isEmpty());
}

void TestDeploy::conformanceSystemsFailCleanly_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("openrtp") << "openrtp_test.xml";
    QTest::newRow("rtsprofile xml") << "rtsprofile_rtsystem.xml";
    QTest::newRow("rtsprofile yaml") << "rtsprofile_rtsystem.yaml";
}

// The OpenRTP/rtsprofile samples use component types no manager here provides: the plan says so,
// and a restore with --create fails on the first required creation, leaving nothing behind.
void TestDeploy::conformanceSystemsFailCleanly()
{
    QFETCH(QString, file);
    const QString path = (RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/rts/")) + file;
    if (!QFileInfo::exists(path))
        QSKIP("conformance folder absent");
    const Profile::RtsProfile profile = loadSystem(path);
    const RestorePlan plan = planRestore(profile, target(false));
    QCOMPARE(plan.components.size(), profile.components.size());
    for (const ComponentMapping &mapping : plan.components)
        QCOMPARE(mapping.kind, MappingKind::Missing);
    const bool anyRequired = std::any_of(profile.components.begin(), profile.components.end(),
                                         [](const auto &c) { return c.isRequiredValue(); });
    const DeployReport report = restore(profile, true);
    // Optional components' failures are reported but not fatal.
    QCOMPARE(report.ok, !anyRequired);
    QVERIFY(!report.stepsWith(StepStatus::Failed).isEmpty());
    if (anyRequired)
        QVERIFY2(report.error.startsWith("create "), qPrintable(report.toText()));
    QVERIFY(doneSubjects(report, "connect").isEmpty());
    QTRY_VERIFY(liveInstances().isEmpty());
}

void TestDeploy::startAndStopFollowDeclaredOrder()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    QVERIFY2(restore(profile, true).ok, "restore");
    const RestorePlan plan = planRestore(profile, target(false));
    // When Mid0 (SYNC on Src0) is sent, Src0 must already be active.
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
    const DeployStep *sink = findStep(started, "activate", "Sink0.0");
    const DeployStep *src = findStep(started, "activate", "Src0.0");
    const DeployStep *wait = findStep(started, "wait", "Src0");
    QVERIFY(sink && src && wait);
    QVERIFY2(src->elapsedMs >= 300, qPrintable(started.toText()));
    for (const char *name : {"Src0", "Mid0", "Sink0"})
        QCOMPARE(live(name).state(), Corba::LifeCycleState::Active);
    // Starting again finds everything active.
    const DeployReport again = startSystem(profile, plan);
    QVERIFY(again.ok);
    QCOMPARE(again.stepsWith(StepStatus::Skipped).size(), 3);

    const DeployReport stopped = stopSystem(profile, plan);
    QVERIFY2(stopped.ok, qPrintable(stopped.toText()));
    QCOMPARE(doneSubjects(stopped, "deactivate"), QStringList({"Src0.0", "Mid0.0", "Sink0.0"}));
    const DeployStep *last = findStep(stopped, "deactivate", "Sink0.0");
    QVERIFY(last->elapsedMs >= 100);
    for (const char *name : {"Src0", "Mid0", "Sink0"})
        QCOMPARE(live(name).state(), Corba::LifeCycleState::Inactive);
}

// Mid0 waits (SYNC, 200 ms) for Src0, which would only be activated after 1.5 s: the timeout
// cancels the plan, Src0's wait included; Sink0, named by no target, was activated at once.
void TestDeploy::syncTimeoutCancelsThePlan()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("synctimeout.xml"));
    QVERIFY2(restore(profile, true).ok, "restore");
    QElapsedTimer timer;
    timer.start();
    const DeployReport report = startSystem(profile, planRestore(profile, target(false)));
    const qint64 elapsed = timer.elapsed();
    QVERIFY(!report.ok);
    QVERIFY2(report.error.contains("Mid0")
                 && report.error.contains("Src0 did not activate within 200 ms"),
             qPrintable(report.toText()));
    QVERIFY2(elapsed >= 200 && elapsed < 1500, qPrintable(QString::number(elapsed)));
    QCOMPARE(doneSubjects(report, "activate"), QStringList({"Sink0.0"}));
    QCOMPARE(stepMessage(report, "wait", "Src0"), QStringLiteral("cancelled"));
    QCOMPARE(live("Src0").state(), Corba::LifeCycleState::Inactive);
    QCOMPARE(live("Mid0").state(), Corba::LifeCycleState::Inactive);
    QCOMPARE(live("Sink0").state(), Corba::LifeCycleState::Active);
}

// Slow0 waits 600 ms, Fast0 (later in the sequence) 200 ms: both count from the plan's start and
// wait side by side, so Fast0 goes first and the plan takes 600 ms, not 800. Free0, which no
// target names, is activated at once.
void TestDeploy::waitTimesCountFromThePlanStart()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("waits.xml"));
    QVERIFY2(restore(profile, true).ok, "restore");
    const RestorePlan plan = planRestore(profile, target(false));
    QElapsedTimer timer;
    timer.start();
    const DeployReport started = startSystem(profile, plan);
    const qint64 elapsed = timer.elapsed();
    QVERIFY2(started.ok, qPrintable(started.toText()));
    QCOMPARE(doneSubjects(started, "activate"), QStringList({"Free0.0", "Fast0.0", "Slow0.0"}));
    const DeployStep *free = findStep(started, "activate", "Free0.0");
    const DeployStep *fast = findStep(started, "activate", "Fast0.0");
    const DeployStep *slow = findStep(started, "activate", "Slow0.0");
    QVERIFY(free && fast && slow);
    const QString times = started.toText() + QStringLiteral("\nwhole plan: %1 ms").arg(elapsed);
    QVERIFY2(free->elapsedMs < 200, qPrintable(times));
    QVERIFY2(fast->elapsedMs >= 200 && fast->elapsedMs < 600, qPrintable(times));
    QVERIFY2(slow->elapsedMs >= 600, qPrintable(times));
    // One after the other the waits would take 800 ms.
    QVERIFY2(elapsed < 600 + 190, qPrintable(times));
    for (const char *name : {"Slow0", "Fast0", "Free0"})
        QCOMPARE(live(name).state(), Corba::LifeCycleState::Active);

    // Stopping: Fast0 after 400 ms, Slow0 after 100 ms, Free0 at once.
    const DeployReport stopped = stopSystem(profile, plan);
    QVERIFY2(stopped.ok, qPrintable(stopped.toText()));
    QCOMPARE(doneSubjects(stopped, "deactivate"), QStringList({"Free0.0", "Slow0.0", "Fast0.0"}));
    QVERIFY2(findStep(stopped, "deactivate", "Fast0.0")->elapsedMs < 400 + 190,
             qPrintable(stopped.toText()));
}

// Late0 comes last in the sequence and waits 300 ms; Follower0 (NO_SYNC) goes right after Late0's
// activation was sent, Waiter0 (SYNC) once Late0 is active. Stopping, First0 (ASYNC) waits for
// Late0's deactivation to be sent.
void TestDeploy::precedingWaitsForItsComponents()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("preceding.xml"));
    QVERIFY2(restore(profile, true).ok, "restore");
    const RestorePlan plan = planRestore(profile, target(false));
    QStringList done;
    QStringList doneBeforeFollower;
    Corba::LifeCycleState lateWhenWaiterSent = Corba::LifeCycleState::Unknown;
    DeployControl control;
    control.progress = [&](const DeployStep &step) {
        if (step.action != "activate")
            return;
        if (step.status == StepStatus::Done)
            done.append(step.subject);
        if (step.status != StepStatus::Running)
            return;
        if (step.subject == "Follower0.0")
            doneBeforeFollower = done;
        if (step.subject == "Waiter0.0")
            lateWhenWaiterSent = live("Late0").state();
    };
    const DeployReport started = startSystem(profile, plan, control);
    QVERIFY2(started.ok, qPrintable(started.toText()));
    QVERIFY2(doneBeforeFollower.contains("Late0.0"), qPrintable(started.toText()));
    QCOMPARE(stepMessage(started, "wait", "Follower0"), QStringLiteral("after Late0 was sent"));
    QCOMPARE(lateWhenWaiterSent, Corba::LifeCycleState::Active);
    QCOMPARE(stepMessage(started, "wait", "Waiter0"), QStringLiteral("after Late0"));
    const QStringList activated = doneSubjects(started, "activate");
    QCOMPARE(activated.size(), 5);
    // First0 and Free0 are immediate: before the actions that wait for time or state.
    QCOMPARE(activated.mid(0, 2), QStringList({"First0.0", "Free0.0"}));
    QVERIFY(findStep(started, "activate", "Late0.0")->elapsedMs >= 300);
    for (const char *name : {"First0", "Follower0", "Waiter0", "Late0", "Free0"})
        QCOMPARE(live(name).state(), Corba::LifeCycleState::Active);

    const DeployReport stopped = stopSystem(profile, plan);
    QVERIFY2(stopped.ok, qPrintable(stopped.toText()));
    const QStringList deactivated = doneSubjects(stopped, "deactivate");
    QCOMPARE(deactivated.size(), 5);
    QVERIFY2(deactivated.indexOf("Late0.0") < deactivated.indexOf("First0.0"),
             qPrintable(stopped.toText()));
    QVERIFY(findStep(stopped, "deactivate", "First0.0")->elapsedMs >= 200);
    QCOMPARE(stepMessage(stopped, "wait", "First0"), QStringLiteral("after Late0 was sent"));
}

// The caller's cancel, once the immediate actions are sent, ends the waits at once.
void TestDeploy::cancelEndsEveryWait()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("waits.xml"));
    QVERIFY2(restore(profile, true).ok, "restore");
    std::atomic_bool cancel {false};
    DeployControl control;
    control.cancel = &cancel;
    control.progress = [&](const DeployStep &step) {
        if (step.action == "activate" && step.subject == "Free0.0"
            && step.status == StepStatus::Done)
            cancel = true;
    };
    QElapsedTimer timer;
    timer.start();
    const DeployReport report = startSystem(profile, planRestore(profile, target(false)), control);
    const qint64 elapsed = timer.elapsed();
    QVERIFY(!report.ok);
    QVERIFY(report.cancelled);
    QVERIFY2(elapsed < 200, qPrintable(report.toText()));
    QCOMPARE(doneSubjects(report, "activate"), QStringList({"Free0.0"}));
    QCOMPARE(stepMessage(report, "wait", "Slow0"), QStringLiteral("cancelled"));
    QCOMPARE(stepMessage(report, "wait", "Fast0"), QStringLiteral("cancelled"));
    QCOMPARE(live("Slow0").state(), Corba::LifeCycleState::Inactive);
    QCOMPARE(live("Fast0").state(), Corba::LifeCycleState::Inactive);
}

void TestDeploy::cryoRestoreCryoGivesTheSameSystem()
{
    QVERIFY(restore(loadSystem(dataFile("ordered.xml")), true).ok);
    QVERIFY(restore(loadSystem(dataFile("configured.xml")), true).ok);
    CryoOptions options;
    options.name = "Frozen";
    options.vendor = "Test";
    options.paths = {"/" + m_live->namingServer()};
    DeployReport report;
    Profile::RtsProfile first = cryoSystem(options, &report);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    QCOMPARE(first.id, QString("RTSystem:Test:Frozen:1.0"));
    QCOMPARE(first.components.size(), 4);
    QCOMPARE(first.dataPortConnectors.size(), 1);
    const auto &connector = first.dataPortConnectors.front();
    QCOMPARE(connector.connectorId, QString("conn-src-mid"));
    QCOMPARE(connector.source.instanceName, QString("Src0"));
    QCOMPARE(Profile::rtsPropertyValue(connector.properties, "dataport.inport.buffer.length"),
             std::optional<QString>("16"));
    for (const auto &property : connector.properties)
        QVERIFY2(!isIorKey(property.name), qPrintable(property.name));
    const Profile::RtsComponent *conf = first.component("Conf0");
    QVERIFY(conf);
    QCOMPARE(conf->activeConfigurationSet, std::optional<QString>("mode0"));
    QVERIFY(std::any_of(conf->configurationSets.begin(), conf->configurationSets.end(),
                        [](const auto &set) { return set.id == "__widget__"; }));

    // Written and read back, then restored onto a fresh system and saved again: the same.
    Profile::Diagnostics diagnostics;
    const auto reread = Profile::loadProfileData(
        Profile::serializeRtsProfile(first, Profile::FileFormat::Xml), "frozen.xml", &diagnostics);
    QVERIFY(reread && reread->rts);
    const QString firstServer = m_live->namingServer();
    cleanup();
    init();
    QVERIFY(liveInstances().isEmpty());
    options.paths = {"/" + m_live->namingServer()};
    const DeployReport restored = restore(*reread->rts, true);
    QVERIFY2(restored.ok, qPrintable(restored.toText()));
    Profile::RtsProfile second = cryoSystem(options, &report);
    QVERIFY2(report.ok, qPrintable(report.toText()));
    // What may differ: dates, the IORs and the name server's address of each run.
    auto normalise = [](Profile::RtsProfile &profile, const QString &server) {
        profile.creationDate.clear();
        profile.updateDate.clear();
        for (auto &component : profile.components) {
            component.properties.clear();
            component.pathUri.replace(server, "NS");
        }
        for (auto &connector : profile.dataPortConnectors) {
            for (auto *end : {&connector.source, &connector.target}) {
                for (auto &property : end->properties)
                    property.value = property.value->replace(server, "NS");
            }
        }
    };
    normalise(first, firstServer);
    normalise(second, m_live->namingServer());
    QCOMPARE(second.components.size(), first.components.size());
    for (int i = 0; i < first.components.size(); ++i)
        QVERIFY2(first.components.at(i) == second.components.at(i),
                 qPrintable(first.components.at(i).instanceName));
    QVERIFY(first.dataPortConnectors == second.dataPortConnectors);
    QVERIFY(first == second);
}

void TestDeploy::diffListsDrift()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    const Profile::RtsProfile configured = loadSystem(dataFile("configured.xml"));
    QVERIFY(restore(profile, true).ok);
    QVERIFY(restore(configured, true).ok);
    QVERIFY(diffSystem(profile, planRestore(profile, target(false))).isEmpty());
    QVERIFY(teardownSystem(planRestore(profile, target(false))).ok);
    live("Sink0").exit();
    QTRY_VERIFY(!liveInstances().contains("Sink0"));
    QStringList lines;
    for (const DriftItem &item : diffSystem(profile, planRestore(profile, target(false))))
        lines.append(item.toString());
    QCOMPARE(lines.size(), 2);
    QVERIFY2(lines.at(0).startsWith("missing component Sink0"), qPrintable(lines.at(0)));
    QCOMPARE(lines.at(1), QString("missing connector conn-src-mid: saved 'Src0.out -> Mid0.in'"));

    live("Conf0").setParameter("default", "int_param0", "8");
    live("Conf0").activateConfigurationSet("default");
    lines.clear();
    for (const DriftItem &item : diffSystem(configured, planRestore(configured, target(false))))
        lines.append(item.toString());
    QCOMPARE(lines,
             QStringList({"configuration Conf0.default.int_param0: saved '7', live '8'",
                          "active set Conf0: saved 'mode0', live 'default'",
                          "missing component Opt0: saved 'RTC:AIST:example:NoSuchType:2.0.0', "
                          "live 'no live component named Opt0'"}));
}

void TestDeploy::diffReadsAgainWhatChangedSincePlanning()
{
    const Profile::RtsProfile profile = loadSystem(dataFile("ordered.xml"));
    QVERIFY(!profile.dataPortConnectors.isEmpty());
    QVERIFY(restore(profile, true).ok);
    QVERIFY2(teardownSystem(planRestore(profile, target(false))).ok, "teardown");
    // Planned while unconnected: the plan's ports lack every connector, which the comparison finds
    // by reading those components again.
    const RestorePlan unconnected = planRestore(profile, target(false));
    QCOMPARE(diffSystem(profile, unconnected).size(), profile.dataPortConnectors.size());
    QVERIFY2(restoreSystem(profile, unconnected, target(false)).ok, "restore");
    QStringList lines;
    for (const DriftItem &item : diffSystem(profile, unconnected))
        lines.append(item.toString());
    QVERIFY2(lines.isEmpty(), qPrintable(lines.join('\n')));
}

QTEST_GUILESS_MAIN(TestDeploy)
#include "tst_deploy.moc"
