// SPDX-License-Identifier: MIT
#include "componentitem.h"
#include "componentproxy.h"
#include "configurationview.h"
#include "connectoritem.h"
#include "documentcontroller.h"
#include "executioncontextmodel.h"
#include "executioncontextview.h"
#include "livesystem.h"
#include "mainwindow.h"
#include "managerview.h"
#include "nameservicemodel.h"
#include "nameserviceview.h"
#include "namingbrowser.h"
#include "onlinediagram.h"
#include "onlinedocks.h"
#include "onlinedocument.h"
#include "onlineicons.h"
#include "orb.h"
#include "perspective.h"
#include "portconnection.h"
#include "profileio.h"
#include "restoredialog.h"
#include "rtsdocument.h"
#include "systemmodel.h"
#include "systemscene.h"
#include "tst_deploysupport.h"

#include <QAction>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QElapsedTimer>
#include <QGraphicsView>
#include <QLabel>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QToolBar>

#include <QSettings>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>
#include <QTreeView>
#include <memory>

using namespace Studio;

namespace {

// The part of the scene the diagram's view shows now.
QRectF visibleSceneRect(const SystemEditor::OnlineDiagram *diagram)
{
    const QGraphicsView *view = diagram->view();
    return view->viewportTransform().inverted().mapRect(QRectF(view->viewport()->rect()));
}

// Whether the whole of the component is on screen (not cut off, not scrolled away).
bool showsWhole(const SystemEditor::OnlineDiagram *diagram, const QString &instanceName)
{
    const SystemEditor::ComponentItem *item = diagram->scene()->componentItem(instanceName);
    return item && visibleSceneRect(diagram).contains(item->sceneBoundingRect());
}

// Clicks the toolbar button of the online tab's action `name` (e.g. Start All), as a user does.
void clickToolButton(SystemEditor::OnlineDiagram *diagram, const char *name)
{
    auto *action = diagram->findChild<QAction *>(QLatin1String(name));
    auto *toolbar = diagram->findChild<QToolBar *>();
    QVERIFY(action && toolbar);
    QWidget *button = toolbar->widgetForAction(action);
    QVERIFY(button && button->isVisible());
    QTest::mouseClick(button, Qt::LeftButton);
}

/**
 * The steps of a start / stop plan as an online tab reports them, from a click on its toolbar
 * on: each with the engine's time since the plan's start and the time the test saw it since the
 * click.
 */
class PlanRun
{
public:
    void click(SystemEditor::OnlineDiagram *diagram, const char *name)
    {
        QObject::connect(diagram, &SystemEditor::OnlineDiagram::planStep, &m_context,
                         [this](const Deploy::DeployStep &step) {
                             m_steps.append(step);
                             m_seenMs.append(m_clock.elapsed());
                         });
        m_clock.start();
        clickToolButton(diagram, name);
    }

    /// The subjects of the `action` steps done, in the order the tab reported them.
    QStringList done(const QString &action) const
    {
        QStringList subjects;
        for (const Deploy::DeployStep &step : m_steps) {
            if (step.action == action && step.status == Deploy::StepStatus::Done)
                subjects.append(step.subject);
        }
        return subjects;
    }
    /// The engine's time (since the plan's start) of the step `action subject` that ended.
    qint64 elapsed(const QString &action, const QString &subject) const
    {
        const qsizetype i = ended(action, subject);
        return i < 0 ? -1 : m_steps.at(i).elapsedMs;
    }
    /// When the test saw that step, since the click.
    qint64 seen(const QString &action, const QString &subject) const
    {
        const qsizetype i = ended(action, subject);
        return i < 0 ? -1 : m_seenMs.at(i);
    }
    /// The message of that step.
    QString message(const QString &action, const QString &subject) const
    {
        const qsizetype i = ended(action, subject);
        return i < 0 ? QString() : m_steps.at(i).message;
    }
    /// Every step with both times, for failure messages.
    QString text() const
    {
        QString text;
        for (qsizetype i = 0; i < m_steps.size(); ++i)
            text += QStringLiteral("%1 (engine %2 ms, seen %3 ms)\n")
                        .arg(m_steps.at(i).toString())
                        .arg(m_steps.at(i).elapsedMs)
                        .arg(m_seenMs.at(i));
        return text;
    }

private:
    qsizetype ended(const QString &action, const QString &subject) const
    {
        for (qsizetype i = 0; i < m_steps.size(); ++i) {
            const Deploy::DeployStep &step = m_steps.at(i);
            if (step.action == action && step.subject == subject
                && step.status != Deploy::StepStatus::Running)
                return i;
        }
        return -1;
    }

    QObject m_context;
    QElapsedTimer m_clock;
    QList<Deploy::DeployStep> m_steps;
    QList<qint64> m_seenMs;
};

} // namespace

// The online views as docks of the main window, driven against a real rtmanager.
class TestOnlineDocks : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void docksFollowThePerspective();
    void choosingAComponentShowsItsConfigurationAndContexts();
    void restoresASystemThroughTheOnlineMenu();
    void dragOntoTheTabActivateAndSaveTheLiveSystem();
    void startAndStopAllRunTheSystemPlan();
    void startAllShowsASyncTimeout();

private:
    void showWithServer(MainWindow &window, QSize size, const QString &server = {});
    void openPlanSystem(MainWindow &window, LiveTest::LiveSystem &live, const QString &fixture,
                        SystemEditor::OnlineDiagram **diagram);

    LiveTest::LiveSystem m_live;
};

void TestOnlineDocks::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("rtstudio-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_onlinedocks"));
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
        "naming.formats=dockhost.host_cxt/%n.rtc",
        "-o",
        "manager.naming_formats=dockhost.host_cxt/%n.mgr",
        "-o",
        "manager.components.precreate=ConfigSample,ConsoleIn,ConsoleOut"};
    QVERIFY2(
        m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error),
        qPrintable(error));
}

void TestOnlineDocks::init()
{
    // Each test adds the name server itself; one remembered by an earlier test would make that
    // addition a no-op.
    QSettings().clear();
}

// Shows `window` at `size` in the System Editor, its name-service view listing the test's server.
void TestOnlineDocks::showWithServer(MainWindow &window, QSize size, const QString &server)
{
    window.resize(size);
    window.show();
    window.showPerspective(Perspective::Id::SystemEditor);
    SystemEditor::NameServiceView *view = window.onlineDocks()->nameService();
    QSignalSpy refreshed(view, &SystemEditor::NameServiceView::serverRefreshed);
    QVERIFY(view->addServer(server.isEmpty() ? m_live.namingServer() : server));
    QVERIFY(refreshed.wait(15000));
}

void TestOnlineDocks::docksFollowThePerspective()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto *nameService = window.findChild<QDockWidget *>("nameServiceDock");
    QVERIFY(nameService);
    QVERIFY(window.findChild<QDockWidget *>("configurationDock"));
    QVERIFY(window.findChild<QDockWidget *>("executionContextDock"));
    QVERIFY(window.findChild<QDockWidget *>("managerDock"));
    QVERIFY(!window.findChild<QDockWidget *>("onlineDiagramDock")); // a tab now
    window.showPerspective(Perspective::Id::Builder);
    QVERIFY(!nameService->isVisible());
    window.showPerspective(Perspective::Id::SystemEditor);
    QVERIFY(nameService->isVisible());
    window.showPerspective(Perspective::Id::Builder);
    QVERIFY(!nameService->isVisible());
}

void TestOnlineDocks::choosingAComponentShowsItsConfigurationAndContexts()
{
    MainWindow window;
    showWithServer(window, {1300, 850});
    if (QTest::currentTestFailed())
        return;
    SystemEditor::NameServiceView *view = window.onlineDocks()->nameService();

    const QString path
        = QStringLiteral("/%1/dockhost.host_cxt/ConfigSample0.rtc").arg(m_live.namingServer());
    const QModelIndex source = view->model()->indexOfPath(path);
    QVERIFY(source.isValid());
    QSignalSpy configurationLoaded(window.onlineDocks()->configuration(),
                                   &SystemEditor::ConfigurationView::loaded);
    QSignalSpy contextsLoaded(window.onlineDocks()->executionContexts(),
                              &SystemEditor::ExecutionContextView::loaded);
    QTreeView *tree = view->treeView();
    const QModelIndex shown = view->filterModel()->mapFromSource(source);
    tree->scrollTo(shown);
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, tree->visualRect(shown).center());
    QVERIFY(configurationLoaded.wait(10000));
    QTRY_VERIFY_WITH_TIMEOUT(!contextsLoaded.isEmpty(), 10000);
    QCOMPARE(window.onlineDocks()->configuration()->componentPath(), path);
    QVERIFY(window.onlineDocks()->configuration()->shownSets().contains("mode0"));
    QCOMPARE(window.onlineDocks()->executionContexts()->model()->rowCount(), 1);
    QVERIFY(window.findChild<QDockWidget *>("configurationDock")->isVisible());

    // Choosing the manager shows it in the Manager dock.
    const QModelIndex managerIndex = view->filterModel()->mapFromSource(view->model()->indexOfPath(
        QStringLiteral("/%1/dockhost.host_cxt/manager.mgr").arg(m_live.namingServer())));
    QVERIFY(managerIndex.isValid());
    QSignalSpy managerLoaded(window.onlineDocks()->manager(), &SystemEditor::ManagerView::loaded);
    tree->setCurrentIndex(managerIndex);
    QVERIFY(managerLoaded.wait(10000));
    QVERIFY(window.onlineDocks()->manager()->types().contains("ConfigSample"));
    QVERIFY(window.findChild<QDockWidget *>("managerDock")->isVisible());
    if (!qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT").isEmpty())
        window.grab().save(qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT") + ".manager.png");
    tree->setCurrentIndex(shown);
    window.findChild<QDockWidget *>("configurationDock")->raise();

    // Double-clicking components puts them on an online diagram tab of the System Editor.
    window.findChild<QAction *>("actionNewOnlineDiagram")->trigger();
    auto *online = qobject_cast<OnlineDocument *>(window.activeDocument());
    QVERIFY(online);
    SystemEditor::OnlineDiagram *diagram = online->diagram();
    QVERIFY(diagram);
    QCOMPARE(window.perspective(Perspective::Id::SystemEditor)->editor(online),
             static_cast<QWidget *>(diagram));
    for (const char *name : {"ConsoleIn0", "ConfigSample0"}) {
        const QModelIndex index = view->filterModel()->mapFromSource(view->model()->indexOfPath(
            QStringLiteral("/%1/dockhost.host_cxt/%2.rtc").arg(m_live.namingServer(), name)));
        QSignalSpy added(diagram, &SystemEditor::OnlineDiagram::componentAdded);
        tree->scrollTo(index);
        const QPoint at = tree->visualRect(index).center();
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, at);
        QTest::mouseDClick(tree->viewport(), Qt::LeftButton, {}, at);
        QVERIFY(added.wait(10000));
    }
    QCOMPARE(diagram->model()->componentIds().size(), 2);
    QTRY_VERIFY(showsWhole(diagram, "ConsoleIn0"));
    QTRY_VERIFY(showsWhole(diagram, "ConfigSample0"));
    diagram->perform(SystemEditor::OnlineDiagram::Action::Activate, "ConsoleIn0");
    QTRY_COMPARE_WITH_TIMEOUT(diagram->bodyColor("ConsoleIn0"),
                              SystemEditor::OnlineIcons::stateColor(Corba::LifeCycleState::Active),
                              10000);
    diagram->perform(SystemEditor::OnlineDiagram::Action::Deactivate, "ConsoleIn0");
    tree->setCurrentIndex(shown);

    auto *editor = window.onlineDocks()->configuration()->findChild<QWidget *>("editor_int_param0");
    QVERIFY(editor);
    QTRY_VERIFY(editor->isVisible()); // layouts show new rows on the next event-loop turn
    const QString shot = qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT");
    if (!shot.isEmpty())
        window.grab().save(shot);
}

void TestOnlineDocks::restoresASystemThroughTheOnlineMenu()
{
    MainWindow window;
    window.show();
    auto *restore = window.findChild<QAction *>("actionRestoreSystem");
    QVERIFY(restore);
    restore->trigger(); // no system open: says so instead of opening a dialog
    QVERIFY(!window.statusBar()->currentMessage().isEmpty());
    QVERIFY(!window.findChild<SystemEditor::RestoreDialog *>("restoreDialog"));

    QSignalSpy refreshed(window.onlineDocks()->nameService(), &SystemEditor::NameServiceView::serverRefreshed);
    window.onlineDocks()->nameService()->addServer(m_live.namingServer());
    QVERIFY(refreshed.wait(15000));
    refreshed.clear();
    Profile::RtsProfile profile;
    Profile::RtsComponent in;
    in.id = QStringLiteral("RTC:AIST:example:ConsoleIn:1.0");
    in.instanceName = QStringLiteral("ConsoleIn0");
    profile.components.append(in);
    SystemEditor::RestoreDialog *dialog = window.onlineDocks()->openRestore(profile);
    QSignalSpy planned(dialog, &SystemEditor::RestoreDialog::planned);
    QVERIFY(planned.wait(15000));
    QCOMPARE(dialog->componentTable()->rowCount(), 1);
    QCOMPARE(dialog->componentTable()->item(0, 2)->text(), QStringLiteral("existing"));
    QVERIFY(dialog->componentTable()->item(0, 3)->text().contains("dockhost.host_cxt"));
    // What a restore created is in the tree at once.
    QCOMPARE(refreshed.size(), 0);
    emit dialog->restored(true);
    QVERIFY(refreshed.wait(15000));
    dialog->close();
}

void TestOnlineDocks::dragOntoTheTabActivateAndSaveTheLiveSystem()
{
    MainWindow window;
    showWithServer(window, {1400, 900});
    if (QTest::currentTestFailed())
        return;
    SystemEditor::NameServiceView *view = window.onlineDocks()->nameService();
    window.findChild<QAction *>("actionNewOnlineDiagram")->trigger();
    auto *online = qobject_cast<OnlineDocument *>(window.activeDocument());
    QVERIFY(online);
    SystemEditor::OnlineDiagram *diagram = online->diagram();

    // Drag both components from the tree (its own drag data) onto the tab.
    QModelIndexList dragged;
    for (const char *name : {"ConsoleIn0", "ConsoleOut0"})
        dragged.append(view->model()->indexOfPath(
            QStringLiteral("/%1/dockhost.host_cxt/%2.rtc").arg(m_live.namingServer(), name)));
    std::unique_ptr<QMimeData> mime(view->model()->mimeData(dragged));
    QVERIFY(mime);
    QWidget *viewport = diagram->view()->viewport();
    const QPoint at(80, 80);
    QDragEnterEvent enter(at, Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &enter);
    QVERIFY(enter.isAccepted());
    QSignalSpy added(diagram, &SystemEditor::OnlineDiagram::componentAdded);
    QDropEvent drop(at, Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &drop);
    QTRY_COMPARE_WITH_TIMEOUT(added.size(), 2, 10000);
    // The fresh tab is fitted to what was dropped: both components are on screen, whole.
    QTRY_VERIFY(showsWhole(diagram, "ConsoleIn0"));
    QTRY_VERIFY(showsWhole(diagram, "ConsoleOut0"));
    QVERIFY(diagram->view()->transform().m11() <= 1.0);

    // Activate All from the Online menu acts on the tab.
    const QColor active = SystemEditor::OnlineIcons::stateColor(Corba::LifeCycleState::Active);
    window.findChild<QAction *>("menuActionActivateAll")->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(diagram->bodyColor("ConsoleOut0"), active, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(diagram->bodyColor("ConsoleIn0"), active, 10000);

    // Connected live, moved on the diagram, then saved: the file has both.
    QSignalSpy connected(diagram, &SystemEditor::OnlineDiagram::connectionFinished);
    // In the live port's own spelling of the data type, as the connector dialog proposes it.
    const auto out = diagram->model()->port("ConsoleIn0", "ConsoleIn0.out");
    QVERIFY(out && out->dataType.contains("TimedLong"));
    diagram->connectLive("ConsoleIn0.out", "ConsoleOut0.in",
                         SystemEditor::ConnectorSettings::defaults("out", "in", out->dataType));
    QVERIFY(connected.wait(10000));
    QVERIFY2(connected.at(0).at(0).toString().isEmpty(),
             qPrintable(connected.at(0).at(0).toString()));
    QTRY_COMPARE_WITH_TIMEOUT(diagram->model()->connectorIds().size(), 1, 10000);
    diagram->model()->moveComponent("ConsoleOut0", QPointF(520, 240));
    // Still fitted while the user has not navigated: the moved component and the connector too.
    QTRY_VERIFY(showsWhole(diagram, "ConsoleOut0"));
    const QString connector = diagram->model()->connectorIds().first();
    QTRY_VERIFY(visibleSceneRect(diagram).contains(
        diagram->scene()->connectorItem(connector)->sceneBoundingRect()));
    QVERIFY(showsWhole(diagram, "ConsoleIn0"));
    const QString shot = qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT");
    if (!shot.isEmpty())
        window.grab().save(shot + ".tab.png");
    QTemporaryDir dir;
    const QString path = dir.filePath("Live.xml");
    QSignalSpy saved(online, &OnlineDocument::liveSaved);
    QVERIFY(window.documents()->saveAs(online, path));
    QVERIFY(saved.wait(15000));
    QVERIFY2(saved.at(0).at(1).toString().isEmpty(), qPrintable(saved.at(0).at(1).toString()));

    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(path, &diagnostics);
    QVERIFY(loaded && loaded->rts);
    const Profile::RtsProfile &file = *loaded->rts;
    QCOMPARE(file.components.size(), 2);
    for (const Profile::RtsComponent &c : file.components) {
        const Profile::RtsComponent *drawn = diagram->model()->component(c.instanceName);
        QVERIFY(drawn && drawn->layout && c.layout);
        QCOMPARE(c.layout->x, drawn->layout->x);
        QCOMPARE(c.layout->y, drawn->layout->y);
    }
    QCOMPARE(file.dataPortConnectors.size(), 1);
    QCOMPARE(file.dataPortConnectors.first().connectorId, diagram->model()->connectorIds().first());
    QCOMPARE(file.dataPortConnectors.first().source.portName, QStringLiteral("ConsoleIn0.out"));
    window.findChild<QAction *>("menuActionDeactivateAll")->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(diagram->bodyColor("ConsoleIn0") != active, 10000);

    // Reopened offline, the system shows the same positions.
    QVERIFY(window.openFiles({path}));
    auto *system = qobject_cast<RtsDocument *>(window.documents()->findByPath(path));
    QVERIFY(system);
    const Profile::RtsComponent *reopened = system->model()->component("ConsoleOut0");
    QVERIFY(reopened && reopened->layout);
    QCOMPARE(reopened->layout->x, QStringLiteral("520"));
    QCOMPARE(reopened->layout->y, QStringLiteral("240"));
    QCOMPARE(system->model()->connectorIds(), diagram->model()->connectorIds());

    // Open System Online shows the saved system's live components where the file puts them.
    QCOMPARE(window.activeDocument(), static_cast<Document *>(system));
    window.findChild<QAction *>("actionOpenOnline")->trigger();
    auto *again = qobject_cast<OnlineDocument *>(window.activeDocument());
    QVERIFY(again && again != online && again->diagram());
    QTRY_COMPARE_WITH_TIMEOUT(again->diagram()->model()->componentIds().size(), 2, 15000);
    const Profile::RtsComponent *placed = again->diagram()->model()->component("ConsoleOut0");
    QVERIFY(placed && placed->layout);
    QCOMPARE(placed->layout->x, QStringLiteral("520"));
    QTRY_VERIFY(showsWhole(again->diagram(), "ConsoleIn0"));
    QTRY_VERIFY(showsWhole(again->diagram(), "ConsoleOut0"));
    QTRY_COMPARE_WITH_TIMEOUT(again->diagram()->model()->connectorIds().size(), 1, 10000);
    diagram->disconnectLive(diagram->model()->connectorIds().first());
    QTRY_COMPARE_WITH_TIMEOUT(diagram->model()->connectorIds().size(), 0, 10000);
}

// A fresh name server and manager running the components of the deployment fixture `fixture`
// (created inactive), the fixture opened in `window` and shown online (Online → Open System
// Online): `diagram` is the tab, once all its components are on it.
void TestOnlineDocks::openPlanSystem(MainWindow &window, LiveTest::LiveSystem &live,
                                     const QString &fixture, SystemEditor::OnlineDiagram **diagram)
{
    QString error;
    quint16 managerPort = 0;
    QVERIFY2(DeployTest::startManager(live, "planhost.host_cxt/%n.rtc", "planhost.host_cxt/%n.mgr",
                                      &managerPort, &error),
             qPrintable(error));
    const QString file = DeployTest::dataFile(fixture);
    const Profile::RtsProfile profile = DeployTest::loadSystem(file);
    Deploy::TargetOptions target;
    target.nameServers = {live.namingServer()};
    target.manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(managerPort);
    target.create = true;
    const Deploy::DeployReport restored
        = Deploy::restoreSystem(profile, Deploy::planRestore(profile, target), target);
    QVERIFY2(restored.ok, qPrintable(restored.toText()));
    showWithServer(window, {1300, 850}, live.namingServer());
    if (QTest::currentTestFailed())
        return;
    QVERIFY(window.openFiles({file}));
    window.findChild<QAction *>("actionOpenOnline")->trigger();
    auto *online = qobject_cast<OnlineDocument *>(window.activeDocument());
    QVERIFY(online && online->diagram());
    QTRY_COMPARE_WITH_TIMEOUT(online->diagram()->model()->componentIds().size(),
                              profile.components.size(), 15000);
    *diagram = online->diagram();
}

// waits.xml opened online: Free0 is named by no target, Fast0 waits 200 ms and Slow0 600 ms. The
// tab's Start All runs the file's Activation block (not the contexts one by one), Stop All its
// Deactivation block, and Cancel ends the waits.
void TestOnlineDocks::startAndStopAllRunTheSystemPlan()
{
    LiveTest::LiveSystem live;
    MainWindow window;
    SystemEditor::OnlineDiagram *diagram = nullptr;
    openPlanSystem(window, live, "waits.xml", &diagram);
    if (QTest::currentTestFailed())
        return;
    QVERIFY(diagram->hasSystemPlan());
    const auto state = [&](const QString &instance) {
        const auto path = Corba::RtPath::parse(
            QStringLiteral("/%1/planhost.host_cxt/%2.rtc").arg(live.namingServer(), instance));
        return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString()).state();
    };
    const QStringList components {"Free0", "Fast0", "Slow0"};
    for (const QString &name : components)
        QCOMPARE(state(name), Corba::LifeCycleState::Inactive);
    auto *bar = diagram->findChild<QProgressBar *>("batchProgress");
    auto *cancel = diagram->findChild<QPushButton *>("batchCancel");
    auto *status = diagram->findChild<QLabel *>("statusLabel");
    QVERIFY(bar && cancel && status);
    QSignalSpy finished(diagram, &SystemEditor::OnlineDiagram::allFinished);

    PlanRun start;
    start.click(diagram, "actionStartAll");
    // While it runs: a busy bar, Cancel, and the components the plan waits for.
    QVERIFY(!bar->isHidden() && !cancel->isHidden());
    QTRY_VERIFY_WITH_TIMEOUT(status->text().contains("waiting: "), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
    QVERIFY(bar->isHidden() && cancel->isHidden());
    QCOMPARE(finished.at(0).at(0).toString(), QStringLiteral("Starting the system: 3 action(s) done"));
    QCOMPARE(status->text(), QStringLiteral("Starting the system: 3 action(s) done."));
    // Free0, which waits for nothing, first; each delayed action once its wait is over, counted
    // from the plan's start (the engine's clock) and so after the click (the test's clock); the
    // two waits side by side (one after the other they would end after 800 ms).
    const QString times = start.text();
    QCOMPARE(start.done("activate"), QStringList({"Free0.0", "Fast0.0", "Slow0.0"}));
    QVERIFY2(start.elapsed("activate", "Free0.0") < 200, qPrintable(times));
    QVERIFY2(start.elapsed("activate", "Fast0.0") >= 200, qPrintable(times));
    QVERIFY2(start.elapsed("activate", "Fast0.0") < 600, qPrintable(times));
    QVERIFY2(start.elapsed("activate", "Slow0.0") >= 600, qPrintable(times));
    QVERIFY2(start.elapsed("activate", "Slow0.0") < 600 + 190, qPrintable(times));
    QVERIFY2(start.seen("activate", "Fast0.0") >= 200, qPrintable(times));
    QVERIFY2(start.seen("activate", "Slow0.0") >= 600, qPrintable(times));
    QCOMPARE(start.message("wait", "Slow0"), QStringLiteral("600 ms from the start"));
    const QColor active = SystemEditor::OnlineIcons::stateColor(Corba::LifeCycleState::Active);
    for (const QString &name : components) {
        QCOMPARE(state(name), Corba::LifeCycleState::Active);
        QTRY_COMPARE_WITH_TIMEOUT(diagram->bodyColor(name), active, 10000);
    }

    // Stop All: Free0 at once, Slow0 after 100 ms, Fast0 after 400 ms.
    PlanRun stop;
    stop.click(diagram, "actionStopAll");
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 15000);
    QCOMPARE(finished.at(1).at(0).toString(), QStringLiteral("Stopping the system: 3 action(s) done"));
    const QString stopTimes = stop.text();
    QCOMPARE(stop.done("deactivate"), QStringList({"Free0.0", "Slow0.0", "Fast0.0"}));
    QVERIFY2(stop.elapsed("deactivate", "Slow0.0") >= 100, qPrintable(stopTimes));
    QVERIFY2(stop.elapsed("deactivate", "Fast0.0") >= 400, qPrintable(stopTimes));
    QVERIFY2(stop.seen("deactivate", "Fast0.0") >= 400, qPrintable(stopTimes));
    const QColor inactive = SystemEditor::OnlineIcons::stateColor(Corba::LifeCycleState::Inactive);
    for (const QString &name : components) {
        QCOMPARE(state(name), Corba::LifeCycleState::Inactive);
        QTRY_COMPARE_WITH_TIMEOUT(diagram->bodyColor(name), inactive, 10000);
    }

    // The same system with Slow0 waiting a minute: Cancel ends its wait, nothing more is sent.
    Profile::RtsProfile patient = DeployTest::loadSystem(DeployTest::dataFile("waits.xml"));
    QVERIFY(patient.activation && patient.activation->targets.size() == 2);
    patient.activation->targets[0].waitTime->waitTime = QStringLiteral("60000");
    OnlineDocument *again = window.onlineDocks()->openOnline(patient);
    QVERIFY(again && again->diagram());
    SystemEditor::OnlineDiagram *waiting = again->diagram();
    QTRY_COMPARE_WITH_TIMEOUT(waiting->model()->componentIds().size(), 3, 15000);
    QSignalSpy cancelled(waiting, &SystemEditor::OnlineDiagram::allFinished);
    PlanRun interrupted;
    interrupted.click(waiting, "actionStartAll");
    auto *waitingStatus = waiting->findChild<QLabel *>("statusLabel");
    QTRY_VERIFY_WITH_TIMEOUT(interrupted.done("activate").size() == 2
                                 && waitingStatus->text().contains("waiting: Slow0"),
                             10000);
    if (const QString shot = qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT"); !shot.isEmpty())
        window.grab().save(shot + ".startall.png");
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(waiting->findChild<QPushButton *>("batchCancel"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(cancelled.size(), 1, 10000);
    QVERIFY2(clock.elapsed() < 5000, qPrintable(interrupted.text()));
    QCOMPARE(cancelled.at(0).at(0).toString(),
             QStringLiteral("Starting the system: cancelled after 2 action(s)"));
    QCOMPARE(interrupted.message("wait", "Slow0"), QStringLiteral("cancelled"));
    QCOMPARE(state("Slow0"), Corba::LifeCycleState::Inactive);
    QCOMPARE(state("Free0"), Corba::LifeCycleState::Active);
}

// synctimeout.xml: Mid0 waits (SYNC, 200 ms) for Src0, which the plan only activates after 1.5 s.
// Start All ends with the engine's message on the tab, no dialog; Sink0 was activated at once.
void TestOnlineDocks::startAllShowsASyncTimeout()
{
    LiveTest::LiveSystem live;
    MainWindow window;
    SystemEditor::OnlineDiagram *diagram = nullptr;
    openPlanSystem(window, live, "synctimeout.xml", &diagram);
    if (QTest::currentTestFailed())
        return;
    QSignalSpy finished(diagram, &SystemEditor::OnlineDiagram::allFinished);
    PlanRun start;
    start.click(diagram, "actionStartAll");
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
    const QString expected = QStringLiteral(
        "Starting the system failed: wait Mid0: Src0 did not activate within 200 ms of the start");
    QCOMPARE(finished.at(0).at(0).toString(), expected);
    auto *status = diagram->findChild<QLabel *>("statusLabel");
    QVERIFY(status && status->isVisible());
    QCOMPARE(status->text(), expected + '.');
    // Src0's wait of 1.5 s was cancelled with the plan.
    QCOMPARE(start.done("activate"), QStringList({"Sink0.0"}));
    QCOMPARE(start.message("wait", "Src0"), QStringLiteral("cancelled"));
    QVERIFY2(start.elapsed("wait", "Src0") < 1500, qPrintable(start.text()));
    QTRY_COMPARE_WITH_TIMEOUT(diagram->bodyColor("Sink0"),
                              SystemEditor::OnlineIcons::stateColor(Corba::LifeCycleState::Active),
                              10000);
    const QColor inactive = SystemEditor::OnlineIcons::stateColor(Corba::LifeCycleState::Inactive);
    QCOMPARE(diagram->bodyColor("Mid0"), inactive);
    QCOMPARE(diagram->bodyColor("Src0"), inactive);
}

QTEST_MAIN(TestOnlineDocks)
#include "tst_onlinedocks.moc"
