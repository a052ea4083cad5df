// SPDX-License-Identifier: MIT
#include "componentitem.h"
#include "componentproxy.h"
#include "connectordialog.h"
#include "corbaerror.h"
#include "livesystem.h"
#include "nameservicemodel.h"
#include "namingbrowser.h"
#include "onlinediagram.h"
#include "onlineicons.h"
#include "onlinesession.h"
#include "orb.h"
#include "portconnection.h"
#include "portitem.h"
#include "stoppedprocess.h"
#include "systemmodel.h"
#include "systemscene.h"

#include <QDropEvent>
#include <QElapsedTimer>
#include <QGraphicsView>
#include <QLabel>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QScopeGuard>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>
#include <QWheelEvent>

#include <atomic>
#include <memory>

using namespace SystemEditor;
using Corba::LifeCycleState;

namespace {

} // namespace

// The online diagram against components running in a real rtmanager.
class TestOnlineDiagram : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void dropsLiveComponentsWithStateColours();
    void stateColoursKeepTextReadable();
    void activateTurnsTheComponentGreen();
    void actionOnAllShowsProgressAndCancels();
    void startAndStopAllWithoutASystemActOnEachContext();
    void closingTheTabEndsARunningPlan();
    void drawsLiveConnectors();
    void portRefreshScalesWithSize();
    void keepsTheDiagramInViewUntilTheUserNavigates();
    void connectsLiveByDraggingThroughTheDialog();
    void stoppedManagerTurnsBlackWithoutStallingTheGui();
    void killedManagerRecoversOnTheNextPoll();
    void sessionEndsWithinACallTimeoutWhileCallsHang();

private:
    Corba::ComponentProxy component(const QString &instance) const;
    void dropOnto(OnlineDiagram &diagram, const QStringList &instances);
    void waitForPoll(OnlineDiagram &diagram);
    void pollUntil(OnlineDiagram &diagram, const std::function<bool()> &done);
    static bool shown(const OnlineDiagram &diagram, const QString &instance);

    LiveTest::LiveSystem m_live;
    QProcess *m_manager = nullptr;
};

void TestOnlineDiagram::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("rtstudio-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_onlinediagram"));
    QSettings().clear();
    Corba::Orb::setCallTimeout(3000);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList arguments {
        "-d",
        "-o",
        QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(LiveTest::freePort()),
        "-o",
        "corba.nameservers=" + m_live.namingServer(),
        "-o",
        "naming.formats=diahost.host_cxt/%n.rtc",
        "-o",
        "manager.naming_formats=diahost.host_cxt/%n.mgr",
        "-o",
        "manager.components.precreate=ConsoleIn,ConsoleOut"};
    m_manager
        = m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error);
    QVERIFY2(m_manager, qPrintable(error));
}

Corba::ComponentProxy TestOnlineDiagram::component(const QString &instance) const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/diahost.host_cxt/%2.rtc").arg(m_live.namingServer(), instance));
    return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString());
}

void TestOnlineDiagram::dropOnto(OnlineDiagram &diagram, const QStringList &instances)
{
    QStringList lines;
    for (const QString &instance : instances) {
        const Corba::ComponentProxy proxy = component(instance);
        lines.append(proxy.path() + '\t' + proxy.ior());
    }
    QMimeData mime;
    mime.setData(NameServiceModel::componentMimeType(), lines.join('\n').toUtf8());
    QWidget *viewport = diagram.view()->viewport();
    const QPointF at(60, 60);
    QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &enter);
    QVERIFY(enter.isAccepted());
    QSignalSpy added(&diagram, &OnlineDiagram::componentAdded);
    QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &drop);
    QVERIFY(drop.isAccepted());
    QTRY_COMPARE_WITH_TIMEOUT(added.size(), instances.size(), 10000);
}

void TestOnlineDiagram::waitForPoll(OnlineDiagram &diagram)
{
    QSignalSpy polled(&diagram, &OnlineDiagram::polled);
    diagram.poll();
    QVERIFY(polled.wait(10000));
}

// Polls at most one round more than the port refresh period (the first round may have started
// before the change it should see), stopping early once `done` holds.
void TestOnlineDiagram::pollUntil(OnlineDiagram &diagram, const std::function<bool()> &done)
{
    for (int round = 0; round <= diagram.portRefreshRounds() && !done(); ++round)
        waitForPoll(diagram);
}

// Whether the view shows the whole of the component.
bool TestOnlineDiagram::shown(const OnlineDiagram &diagram, const QString &instance)
{
    const ComponentItem *item = diagram.scene()->componentItem(instance);
    const QGraphicsView *view = diagram.view();
    const QRectF visible
        = view->viewportTransform().inverted().mapRect(QRectF(view->viewport()->rect()));
    return item && visible.contains(item->sceneBoundingRect());
}

// Every fill a component gets, offline or in any state (black when it does not answer), keeps its
// name, type and port labels readable: WCAG's 4.5:1 for normal text.
void TestOnlineDiagram::stateColoursKeepTextReadable()
{
    QList<QColor> fills {ComponentAppearance().bodyColor};
    for (const LifeCycleState state :
         {LifeCycleState::Created, LifeCycleState::Inactive, LifeCycleState::Active,
          LifeCycleState::Error, LifeCycleState::Unknown})
        fills << OnlineIcons::stateColor(state);
    for (const QColor &fill : std::as_const(fills)) {
        const BodyTextColours text = BodyTextColours::on(fill);
        for (const QColor &colour : {text.title, text.type, text.portLabel})
            QVERIFY2(contrastRatio(fill, colour) >= 4.5,
                     qPrintable(QStringLiteral("%1 on %2: %3")
                                    .arg(colour.name(), fill.name())
                                    .arg(contrastRatio(fill, colour))));
    }
    QCOMPARE(BodyTextColours::on(Qt::black).title, QColor(Qt::white));
    QCOMPARE(qRound(contrastRatio(Qt::black, Qt::white)), 21);
}

void TestOnlineDiagram::dropsLiveComponentsWithStateColours()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    QCOMPARE(diagram.pollInterval(), 1000);
    dropOnto(diagram, {"ConsoleIn0", "ConsoleOut0"});
    QCOMPARE(diagram.model()->componentIds().size(), 2);
    QCOMPARE(diagram.scene()->componentItemCount(), 2);
    QTRY_COMPARE_WITH_TIMEOUT(int(diagram.state("ConsoleIn0")), int(LifeCycleState::Inactive),
                              10000);
    QTRY_COMPARE(diagram.bodyColor("ConsoleIn0"),
                 OnlineIcons::stateColor(LifeCycleState::Inactive));
    QVERIFY(diagram.model()->port("ConsoleIn0", "ConsoleIn0.out").has_value());
    QCOMPARE(diagram.model()->port("ConsoleIn0", "ConsoleIn0.out")->kind, PortKind::DataOut);
    const Corba::ComponentProxy again0 = component("ConsoleIn0");
    diagram.addComponent(again0.path(), again0.ior(), {300, 300}); // dropped again: not added twice
    QTRY_COMPARE_WITH_TIMEOUT(session.pendingCalls(), 0, 10000);
    QCOMPARE(diagram.model()->componentIds().size(), 2);

    diagram.setPollInterval(250);
    QCOMPARE(diagram.pollInterval(), 250);
    OnlineDiagram again(&session);
    QCOMPARE(again.pollInterval(), 250); // remembered
    again.setPollInterval(1000);
}

void TestOnlineDiagram::activateTurnsTheComponentGreen()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    dropOnto(diagram, {"ConsoleOut0"});
    QSignalSpy finished(&diagram, &OnlineDiagram::actionFinished);
    diagram.perform(OnlineDiagram::Action::Activate, "ConsoleOut0");
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(1).toString(), QString());
    QTRY_COMPARE_WITH_TIMEOUT(diagram.bodyColor("ConsoleOut0"),
                              OnlineIcons::stateColor(LifeCycleState::Active), 10000);
    QCOMPARE(component("ConsoleOut0").state(), LifeCycleState::Active);
    // Redrawn from the model (moved, its size changed, undone), it keeps its state's colour at
    // once, not the offline fill until the next poll.
    const QPointF at = diagram.model()->layout("ConsoleOut0").position;
    diagram.model()->moveComponent("ConsoleOut0", at + QPointF(40, 20));
    QCOMPARE(diagram.bodyColor("ConsoleOut0"), OnlineIcons::stateColor(LifeCycleState::Active));
    diagram.model()->moveComponent("ConsoleOut0", at);
    QCOMPARE(diagram.bodyColor("ConsoleOut0"), OnlineIcons::stateColor(LifeCycleState::Active));
    diagram.performAll(OnlineDiagram::Action::Deactivate);
    QTRY_COMPARE_WITH_TIMEOUT(diagram.bodyColor("ConsoleOut0"),
                              OnlineIcons::stateColor(LifeCycleState::Inactive), 10000);
}

void TestOnlineDiagram::actionOnAllShowsProgressAndCancels()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    dropOnto(diagram, {"ConsoleIn0", "ConsoleOut0"});
    // The other tests expect the peer's components inactive, whatever happens here.
    const auto deactivate = qScopeGuard([this] {
        for (const char *name : {"ConsoleIn0", "ConsoleOut0"}) {
            try {
                if (component(name).state() == LifeCycleState::Active)
                    component(name).deactivate(0);
            } catch (const Corba::Error &) {
            }
        }
    });
    auto *bar = diagram.findChild<QProgressBar *>("batchProgress");
    auto *cancel = diagram.findChild<QPushButton *>("batchCancel");
    QVERIFY(bar && cancel && bar->isHidden());

    QSignalSpy finished(&diagram, &OnlineDiagram::allFinished);
    diagram.performAll(OnlineDiagram::Action::Activate);
    QVERIFY(!bar->isHidden() && !cancel->isHidden());
    QCOMPARE(bar->maximum(), 2);
    QVERIFY(finished.wait(10000));
    QVERIFY(bar->isHidden() && cancel->isHidden());
    QCOMPARE(finished.at(0).at(0).toString(), QString("Activating: 2 of 2 component(s) done"));
    QTRY_COMPARE_WITH_TIMEOUT(component("ConsoleIn0").state(), LifeCycleState::Active, 10000);

    // Cancelled while the calls cannot be answered (their manager stopped): the calls not yet made
    // are skipped, and the summary says so.
    {
        const LiveTest::StoppedProcess stopped(m_manager, 5000, 3000);
        QVERIFY(stopped.isStopped());
        diagram.performAll(OnlineDiagram::Action::Deactivate);
        QTest::mouseClick(cancel, Qt::LeftButton);
    }
    QVERIFY(finished.wait(10000));
    const QString summary = finished.at(1).at(0).toString();
    QVERIFY2(summary.startsWith("Deactivating: ") && summary.contains("cancelled"), qPrintable(summary));
    diagram.performAll(OnlineDiagram::Action::Deactivate);
    QVERIFY(finished.wait(10000));
    QTRY_COMPARE_WITH_TIMEOUT(component("ConsoleIn0").state(), LifeCycleState::Inactive, 10000);
}

// A diagram that shows no saved system has no plan: Stop All and Start All stop and start every
// component's context, one call each.
void TestOnlineDiagram::startAndStopAllWithoutASystemActOnEachContext()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    dropOnto(diagram, {"ConsoleIn0", "ConsoleOut0"});
    QVERIFY(!diagram.hasSystemPlan());
    const QStringList names {"ConsoleIn0", "ConsoleOut0"};
    const auto running = [&](const QString &name) {
        const auto contexts = component(name).executionContexts();
        return !contexts.empty() && contexts.front().running;
    };
    // The other tests expect the contexts running, whatever happens here.
    const auto restart = qScopeGuard([&] {
        for (const QString &name : names) {
            try {
                if (!running(name))
                    component(name).startContext();
            } catch (const Corba::Error &) {
            }
        }
    });
    for (const QString &name : names)
        QVERIFY(running(name));
    QSignalSpy finished(&diagram, &OnlineDiagram::allFinished);
    diagram.performAll(OnlineDiagram::Action::Stop);
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(0).toString(), QString("Stopping: 2 of 2 component(s) done"));
    for (const QString &name : names)
        QVERIFY(!running(name));
    diagram.performAll(OnlineDiagram::Action::Start);
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(1).at(0).toString(), QString("Starting: 2 of 2 component(s) done"));
    for (const QString &name : names)
        QVERIFY(running(name));
}

// A diagram given a saved system runs its plan on Start All; closed while the plan waits (here a
// minute for ConsoleOut0), it cancels the plan, so the deployment worker is free again at once.
void TestOnlineDiagram::closingTheTabEndsARunningPlan()
{
    Profile::RtsProfile profile;
    profile.id = QStringLiteral("RTSystem:test:patient:1.0");
    for (const char *type : {"ConsoleIn", "ConsoleOut"}) {
        Profile::RtsComponent c;
        c.id = QStringLiteral("RTC:AIST:example:%1:1.0").arg(type);
        c.instanceName = QLatin1String(type) + QLatin1Char('0');
        profile.components.append(c);
    }
    Profile::RtsCondition slow;
    slow.sequence = QStringLiteral("0");
    slow.targetComponent.componentId = profile.components[1].id;
    slow.targetComponent.instanceName = QStringLiteral("ConsoleOut0");
    slow.targetComponent.id = QStringLiteral("0");
    slow.waitTime = Profile::RtsWaitTime {};
    slow.waitTime->waitTime = QStringLiteral("60000");
    profile.activation = Profile::RtsMessageSequence {};
    profile.activation->targets.append(slow);
    Deploy::TargetOptions options;
    options.nameServers = {m_live.namingServer()};
    const auto deactivate = qScopeGuard([this] {
        try {
            if (component("ConsoleIn0").state() == LifeCycleState::Active)
                component("ConsoleIn0").deactivate(0);
        } catch (const Corba::Error &) {
        }
    });

    OnlineSession session;
    auto diagram = std::make_unique<OnlineDiagram>(&session);
    dropOnto(*diagram, {"ConsoleIn0", "ConsoleOut0"});
    diagram->setSystem(profile, options);
    QVERIFY(diagram->hasSystemPlan());
    QStringList steps;
    connect(diagram.get(), &OnlineDiagram::planStep, this,
            [&](const Deploy::DeployStep &step) { steps.append(step.toString()); });
    diagram->performAll(OnlineDiagram::Action::Start);
    QTRY_VERIFY2_WITH_TIMEOUT(steps.contains("done activate ConsoleIn0.0")
                                  && steps.contains("running wait ConsoleOut0"),
                              qPrintable(steps.join('\n')), 10000);
    diagram.reset();
    QElapsedTimer clock;
    clock.start();
    bool answered = false;
    QObject context;
    session.submit(
        OnlineSession::deploymentHost(), [] { return QVariant(); }, &context,
        [&](const OnlineResult &) { answered = true; });
    QTRY_VERIFY_WITH_TIMEOUT(answered, 10000);
    QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed())));
    QCOMPARE(component("ConsoleOut0").state(), LifeCycleState::Inactive);
}

void TestOnlineDiagram::drawsLiveConnectors()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    dropOnto(diagram, {"ConsoleIn0", "ConsoleOut0"});
    const Corba::PortInfo out = component("ConsoleIn0").port("out");
    const Corba::PortInfo in = component("ConsoleOut0").port("in");
    Corba::ConnectionRequest request;
    request.id = QStringLiteral("live-connector-1");
    // Made elsewhere: the diagram reads ports only every few rounds, so it shows up within as
    // many polls (a connector this diagram makes is read at once, see the dragging test).
    const int reads = diagram.portReads();
    QSignalSpy rounds(&diagram, &OnlineDiagram::polled);
    const Corba::ConnectorInfo made = Corba::PortConnection::connect({out, in}, request, "test");
    pollUntil(diagram, [&] { return diagram.model()->connector(made.id).has_value(); });
    QCOMPARE(diagram.model()->connectorIds(), QStringList {made.id});
    QCOMPARE(diagram.scene()->connectorItemCount(), 1);
    Corba::PortConnection::disconnect(out, made.id, "test");
    pollUntil(diagram, [&] { return diagram.model()->connectorIds().isEmpty(); });
    QVERIFY(diagram.model()->connectorIds().isEmpty());
    QCOMPARE(diagram.scene()->connectorItemCount(), 0);
    // Each of the two components read its ports in at most one round of portRefreshRounds()
    // (one more round may have started and not yet finished), never in every round.
    const int started = int(rounds.size()) + 1;
    const int period = diagram.portRefreshRounds();
    QCOMPARE(period, 3);
    const int allowed = 2 * ((started + period - 1) / period);
    QVERIFY2(diagram.portReads() - reads <= allowed,
             qPrintable(QStringLiteral("%1 port reads in %2 rounds")
                            .arg(diagram.portReads() - reads)
                            .arg(started)));
    QVERIFY(diagram.portReads() > reads);
}

void TestOnlineDiagram::portRefreshScalesWithSize()
{
    // Up to 300 components every third round; beyond, about 100 components' ports a round.
    QCOMPARE(OnlineDiagram::portRefreshRounds(1), 3);
    QCOMPARE(OnlineDiagram::portRefreshRounds(300), 3);
    QCOMPARE(OnlineDiagram::portRefreshRounds(301), 4);
    QCOMPARE(OnlineDiagram::portRefreshRounds(1000), 10);
    for (const int components : {301, 1000, 5000})
        QVERIFY(components / OnlineDiagram::portRefreshRounds(components) <= 100);
}

void TestOnlineDiagram::keepsTheDiagramInViewUntilTheUserNavigates()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    diagram.resize(420, 320);
    diagram.show();
    QVERIFY(QTest::qWaitForWindowExposed(&diagram));
    const Corba::ComponentProxy in = component("ConsoleIn0");
    const Corba::ComponentProxy out = component("ConsoleOut0");
    QSignalSpy added(&diagram, &OnlineDiagram::componentAdded);
    diagram.addComponent(in.path(), in.ior(), {40, 40});
    diagram.addComponent(out.path(), out.ior(), {900, 700});
    QTRY_COMPARE_WITH_TIMEOUT(added.size(), 2, 10000);
    // Fresh: the whole diagram is fitted (zoomed out, as it is larger than the view).
    QTRY_VERIFY(shown(diagram, "ConsoleIn0") && shown(diagram, "ConsoleOut0"));
    QVERIFY(diagram.view()->transform().m11() < 1.0);

    // Once the user scrolls, the view stays where it is until a component is added, which is
    // then scrolled into view at the zoom the user has.
    QWidget *viewport = diagram.view()->viewport();
    const QPointF at(viewport->rect().center());
    QWheelEvent wheel(at, viewport->mapToGlobal(at), {}, {0, -120}, Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(viewport, &wheel);
    const qreal zoom = diagram.view()->transform().m11();
    diagram.resize(400, 300);
    QCOMPARE(diagram.view()->transform().m11(), zoom);
    diagram.model()->removeComponent("ConsoleOut0");
    diagram.addComponent(out.path(), out.ior(), {1800, 1400});
    QTRY_COMPARE_WITH_TIMEOUT(added.size(), 3, 10000);
    QTRY_VERIFY(shown(diagram, "ConsoleOut0"));
    QCOMPARE(diagram.view()->transform().m11(), zoom);
}

void TestOnlineDiagram::connectsLiveByDraggingThroughTheDialog()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    diagram.resize(900, 600);
    diagram.show();
    QVERIFY(QTest::qWaitForWindowExposed(&diagram));
    dropOnto(diagram, {"ConsoleIn0", "ConsoleOut0"});
    waitForPoll(diagram);
    // Place them apart so that the drag from out to in is unambiguous.
    diagram.model()->moveComponent("ConsoleIn0", {0, 0});
    diagram.model()->moveComponent("ConsoleOut0", {400, 0});
    QTRY_VERIFY(diagram.scene()->portItem({"ConsoleOut0", "ConsoleOut0.in"}) != nullptr);

    const ConnectorDialog::Choices choices = diagram.choicesFor("ConsoleIn0.out", "ConsoleOut0.in");
    QVERIFY(choices.interfaceTypes.contains("corba_cdr"));
    QVERIFY(choices.dataflowTypes.contains("push"));
    // The OutPort also lists OpenRTM's other names (block, nonblock) and the InPort takes any:
    // the dialog offers the types it knows.
    QCOMPARE(choices.subscriptionTypes, QStringList({"flush", "new", "periodic"}));
    ConnectorSettings asked;
    diagram.setConnectorEditor(
        [&](const ConnectorSettings &proposed, const ConnectorDialog::Choices &offered) {
            asked = proposed;
            if (!qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT").isEmpty()) {
                ConnectorDialog dialog(proposed, offered);
                dialog.grab().save(qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT")
                                   + ".connector.png");
            }
            ConnectorSettings chosen = proposed;
            chosen.subscriptionType = QStringLiteral("new");
            return std::optional<ConnectorSettings>(chosen);
        });
    QGraphicsView *view = diagram.view();
    auto centre = [&](const ConnectorEnd &end) {
        const PortItem *item = diagram.scene()->portItem(end);
        return view->mapFromScene(item->sceneBoundingRect().center());
    };
    const QPoint from = centre({"ConsoleIn0", "ConsoleIn0.out"});
    const QPoint to = centre({"ConsoleOut0", "ConsoleOut0.in"});
    QSignalSpy finished(&diagram, &OnlineDiagram::connectionFinished);
    QTest::mousePress(view->viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(view->viewport(), (from + to) / 2);
    QTest::mouseMove(view->viewport(), to);
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, to);
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(0).toString(), QString());
    // The dialog is pre-filled with the live port's own data type spelling.
    QCOMPARE(
        asked.dataType,
        Corba::propertyValue(component("ConsoleIn0").port("out").properties, "dataport.data_type"));
    QVERIFY(asked.dataType.contains("TimedLong"));
    // Its own connection is read back at once, not after portRefreshRounds() rounds of 1 s.
    QTRY_COMPARE_WITH_TIMEOUT(diagram.model()->connectorIds().size(), 1, 2000);
    const std::vector<Corba::ConnectorInfo> live = component("ConsoleIn0").port("out").connectors;
    QCOMPARE(int(live.size()), 1);
    QCOMPARE(Corba::propertyValue(live.front().properties, "dataport.subscription_type"),
             QStringLiteral("new"));

    QSignalSpy disconnected(&diagram, &OnlineDiagram::connectionFinished);
    diagram.disconnectLive(diagram.model()->connectorIds().first());
    QVERIFY(disconnected.wait(10000));
    QCOMPARE(disconnected.at(0).at(0).toString(), QString());
    QTRY_VERIFY_WITH_TIMEOUT(diagram.model()->connectorIds().isEmpty(), 2000);
    QVERIFY(component("ConsoleIn0").port("out").connectors.empty());
}

void TestOnlineDiagram::stoppedManagerTurnsBlackWithoutStallingTheGui()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    dropOnto(diagram, {"ConsoleIn0"});
    waitForPoll(diagram);
    QCOMPARE(diagram.bodyColor("ConsoleIn0"), OnlineIcons::stateColor(LifeCycleState::Inactive));

    const LiveTest::StoppedProcess stopped(m_manager, 500, 3000);
    QVERIFY(stopped.isStopped());
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0;
    qint64 worstGap = 0;
    QTimer ticker;
    ticker.setInterval(10);
    connect(&ticker, &QTimer::timeout, this, [&] {
        worstGap = std::max(worstGap, clock.elapsed() - last);
        last = clock.elapsed();
    });
    ticker.start();
    // A round already under way when the manager stopped may still report its last state; the
    // next one cannot.
    diagram.poll();
    QTRY_COMPARE_WITH_TIMEOUT(diagram.state("ConsoleIn0"), LifeCycleState::Unknown, 10000);
    ticker.stop();
    QVERIFY2(worstGap < 100, qPrintable(QString::number(worstGap)));
    QCOMPARE(diagram.bodyColor("ConsoleIn0"), OnlineIcons::stateColor(LifeCycleState::Unknown));
    QVERIFY(diagram.unreachableComponents().contains("ConsoleIn0"));
    QVERIFY(diagram.findChild<QLabel *>("statusLabel")->text().contains("ConsoleIn0"));
}

void TestOnlineDiagram::killedManagerRecoversOnTheNextPoll()
{
    // A manager of its own, killed while the diagram polls it and started again.
    const QStringList arguments {"-d", "-o", QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(LiveTest::freePort()),
                                 "-o", "corba.nameservers=" + m_live.namingServer(), "-o",
                                 "naming.formats=diahost.host_cxt/%n.rtc", "-o",
                                 "manager.naming_formats=diahost.host_cxt/revenant.mgr", "-o",
                                 "manager.components.precreate=ConsoleIn?instance_name=Revenant"};
    QString error;
    QProcess *manager = m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error);
    QVERIFY2(manager, qPrintable(error));
    OnlineSession session;
    OnlineDiagram diagram(&session);
    dropOnto(diagram, {"Revenant"});
    waitForPoll(diagram);
    QCOMPARE(diagram.state("Revenant"), LifeCycleState::Inactive);
    const QString firstIor = component("Revenant").ior();

    manager->kill();
    QVERIFY(manager->waitForFinished(10000));
    pollUntil(diagram, [&] { return diagram.state("Revenant") == LifeCycleState::Unknown; });
    QCOMPARE(diagram.state("Revenant"), LifeCycleState::Unknown);
    QCOMPARE(diagram.unreachableComponents(), QStringList {"Revenant"});
    // One line in the diagram's status, no dialog (the modal guard fails the test on any).
    QCOMPARE(diagram.findChild<QLabel *>("statusLabel")->text(), QStringLiteral("Unreachable: Revenant"));
    waitForPoll(diagram);
    QCOMPARE(diagram.unreachableComponents(), QStringList {"Revenant"});

    // Back under a new reference: the next rounds find it through the name server.
    manager = m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error);
    QVERIFY2(manager, qPrintable(error));
    QVERIFY(component("Revenant").ior() != firstIor);
    pollUntil(diagram, [&] { return diagram.state("Revenant") == LifeCycleState::Inactive; });
    QCOMPARE(diagram.state("Revenant"), LifeCycleState::Inactive);
    QVERIFY(diagram.unreachableComponents().isEmpty());
    QVERIFY(diagram.findChild<QLabel *>("statusLabel")->text().isEmpty());
}

void TestOnlineDiagram::sessionEndsWithinACallTimeoutWhileCallsHang()
{
    // Quitting while a worker runs calls against a hung manager (a restore makes one call after
    // another): the session ends within about one call timeout, without destroying a running
    // thread (which aborts the program); the worker finishes on its own later.
    const Corba::ComponentProxy proxy = component("ConsoleIn0");
    const LiveTest::StoppedProcess stopped(m_manager, 500, 3000);
    QVERIFY(stopped.isStopped());

    auto done = std::make_shared<std::atomic_int>(0);
    auto *session = new OnlineSession;
    QObject context;
    session->submit(
        QStringLiteral("hung"),
        [proxy, done] {
            done->store(-1); // started
            for (int i = 0; i < 10; ++i) {
                try {
                    proxy.state();
                } catch (const Corba::Error &) {
                }
            }
            done->store(1);
            return QVariant();
        },
        &context, [](const OnlineResult &) {});
    QTRY_COMPARE_WITH_TIMEOUT(done->load(), -1, 10000);
    QElapsedTimer clock;
    clock.start();
    delete session;
    QVERIFY2(clock.elapsed() < 500 + 1000 + 500, qPrintable(QString::number(clock.elapsed())));
    QCOMPARE(done->load(), -1);
    // The abandoned worker ends when its last call has timed out (a state read is a few calls).
    QTRY_COMPARE_WITH_TIMEOUT(done->load(), 1, 30000);
}

QTEST_MAIN(TestOnlineDiagram)
#include "tst_onlinediagram.moc"
