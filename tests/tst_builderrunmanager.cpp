// SPDX-License-Identifier: MIT
// The Builder's Run in Manager against real rtmanager processes: the module is loaded and the
// component created on a worker thread (the GUI keeps turning, also while a manager hangs), the
// outcome reaches the Problems panel and the status bar, and failures name the manager and the
// module. Also the Problems panel's viewer, which opens a row's file at its line.
#include "buildcontroller.h"
#include "componenteditor.h"
#include "generatecontroller.h"
#include "livesystem.h"
#include "mainwindow.h"
#include "managerproxy.h"
#include "modulerun.h"
#include "orb.h"
#include "perspective.h"
#include "problemspanel.h"
#include "runcontroller.h"
#include "runmanagerdialog.h"
#include "sourceviewer.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTimer>
#include <QToolBar>
#include <QTreeWidget>

#include <csignal>

using Builder::ModuleRunRequest;
using Builder::ModuleRunResult;
using Builder::RunController;

class TestBuilderRunManager : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void parsesManagerAddresses_data();
    void parsesManagerAddresses();
    void actionFollowsTheBuiltModule();
    void createsTheComponentInTheManager();
    void reportsRefusedModules();
    void unreachableManagerIsNamedQuickly();
    void hungManagerTimesOutWithoutBlocking();
    void editorRunsThroughTheChooser();
    void problemsRowOpensFileAtLine();

private:
    QProcess *startManager(quint16 *port, QString *error);
    QString address(quint16 port) const { return QStringLiteral("127.0.0.1:%1").arg(port); }
    QStringList instances(quint16 port) const;
    static ModuleRunRequest testModule(const QString &address);
    static ModuleRunResult runAndWait(RunController &controller, const ModuleRunRequest &request);

    LiveTest::LiveSystem m_live;
    QTemporaryDir m_settingsDir;
    quint16 m_port = 0;
};

namespace {

const QString testModulePath = MANAGER_TEST_MODULE_DIR + QStringLiteral("/ManagerTestModule.so");

} // namespace

void TestBuilderRunManager::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_builderrunmanager"));
    QString error;
    QVERIFY2(startManager(&m_port, &error), qPrintable(error));
}

void TestBuilderRunManager::init()
{
    QSettings().clear();
}

QProcess *TestBuilderRunManager::startManager(quint16 *port, QString *error)
{
    *port = LiveTest::freePort();
    // No name server: Run in Manager talks to the manager directly.
    return m_live.startManager(RTMANAGER_PATH, *port,
                               {QStringLiteral("naming.enable=NO")}, error);
}

QStringList TestBuilderRunManager::instances(quint16 port) const
{
    QStringList names;
    const Corba::ManagerProxy manager(QString::fromUtf8(LiveTest::managerLocation(port)),
                                      address(port));
    for (const Corba::ComponentInfo &info : manager.componentProfiles())
        names << info.instanceName;
    return names;
}

ModuleRunRequest TestBuilderRunManager::testModule(const QString &address)
{
    return {address, testModulePath, QStringLiteral("ManagerTestModuleInit"),
            QStringLiteral("ModuleCounter")};
}

ModuleRunResult TestBuilderRunManager::runAndWait(RunController &controller,
                                                  const ModuleRunRequest &request)
{
    QSignalSpy finished(&controller, &RunController::runFinished);
    if (!controller.runModule(request) || !finished.wait(controller.timeout() + 5000))
        return {};
    return finished.at(0).at(0).value<ModuleRunResult>();
}

void TestBuilderRunManager::parsesManagerAddresses_data()
{
    QTest::addColumn<QString>("address");
    QTest::addColumn<QString>("location");
    QTest::newRow("host:port") << "localhost:2810"
                               << "corbaloc:iiop:localhost:2810/manager";
    QTest::newRow("default port") << "robot1"
                                  << "corbaloc:iiop:robot1:2810/manager";
    QTest::newRow("spaces") << " 10.0.0.5:2811 "
                            << "corbaloc:iiop:10.0.0.5:2811/manager";
    QTest::newRow("corbaloc") << "corbaloc::h:1/mgr"
                              << "corbaloc:iiop:h:1/mgr";
    QTest::newRow("empty") << ""
                           << "";
    QTest::newRow("bad port") << "host:port"
                              << "";
}

void TestBuilderRunManager::parsesManagerAddresses()
{
    QFETCH(QString, address);
    QFETCH(QString, location);
    QCOMPARE(Builder::ModuleRun::managerLocation(address), location);
}

void TestBuilderRunManager::actionFollowsTheBuiltModule()
{
    QTemporaryDir project;
    QVERIFY(project.isValid());
    QString name = QStringLiteral("Counter");
    RunController controller([&] { return project.path(); }, [&] { return name; });
    QCOMPARE(controller.modulePath(), project.filePath(QStringLiteral("build/src/Counter.so")));
    QVERIFY(!controller.runAction()->isEnabled());

    QVERIFY(QDir(project.path()).mkpath(QStringLiteral("build/src")));
    QVERIFY(QFile::copy(testModulePath, controller.modulePath()));
    controller.updateActions();
    QVERIFY(controller.runAction()->isEnabled());

    // Renaming the component points at a module that was not built.
    name = QStringLiteral("Renamed");
    controller.updateActions();
    QVERIFY(!controller.runAction()->isEnabled());
    QSignalSpy reported(&controller, &RunController::reported);
    QVERIFY(!controller.runInManager(address(m_port)));
    QCOMPARE(reported.size(), 1);
    const auto outcome = reported.at(0).at(0).value<Builder::GenerateOutcome>();
    QVERIFY2(outcome.summary.contains(QStringLiteral("Renamed.so")), qPrintable(outcome.summary));
}

void TestBuilderRunManager::createsTheComponentInTheManager()
{
    // Over no project: runModule() is what is driven here.
    RunController controller({}, {});
    QSignalSpy reported(&controller, &RunController::reported);
    const ModuleRunResult first = runAndWait(controller, testModule(address(m_port)));
    QVERIFY2(first.ok, qPrintable(first.error));
    QVERIFY(!first.alreadyLoaded);
    QCOMPARE(first.instanceName, QStringLiteral("ModuleCounter0"));
    QTRY_VERIFY_WITH_TIMEOUT(instances(m_port).contains(QStringLiteral("ModuleCounter0")), 5000);
    QCOMPARE(reported.size(), 1);
    const auto outcome = reported.at(0).at(0).value<Builder::GenerateOutcome>();
    QVERIFY(outcome.succeeded);
    QCOMPARE(outcome.summary,
             QStringLiteral("Created ModuleCounter0 in manager %1.").arg(address(m_port)));

    // The second run finds the module loaded and creates one more instance.
    const ModuleRunResult second = runAndWait(controller, testModule(address(m_port)));
    QVERIFY2(second.ok, qPrintable(second.error));
    QVERIFY(second.alreadyLoaded);
    QCOMPARE(second.instanceName, QStringLiteral("ModuleCounter1"));
    QTRY_VERIFY_WITH_TIMEOUT(instances(m_port).contains(QStringLiteral("ModuleCounter1")), 5000);
    // The address used is offered first next time.
    QCOMPARE(RunController::managerAddress(), address(m_port));
    QCOMPARE(RunController::recentManagerAddresses().first(), address(m_port));
}

void TestBuilderRunManager::reportsRefusedModules()
{
    RunController controller({}, {});
    ModuleRunRequest request = testModule(address(m_port));
    request.initFunction = QStringLiteral("NoSuchInit");
    // Copied, so that no earlier run has it loaded.
    QTemporaryDir dir;
    request.modulePath = dir.filePath(QStringLiteral("Other.so"));
    QVERIFY(QFile::copy(testModulePath, request.modulePath));
    const ModuleRunResult refused = runAndWait(controller, request);
    QVERIFY(!refused.ok);
    QVERIFY2(refused.error.contains(QStringLiteral("load_module refused")),
             qPrintable(refused.error));
    QVERIFY2(refused.error.contains(QStringLiteral("NoSuchInit")), qPrintable(refused.error));
    QVERIFY2(refused.error.contains(address(m_port)), qPrintable(refused.error));
    QVERIFY2(refused.error.contains(QStringLiteral("Other.so")), qPrintable(refused.error));

    request = testModule(address(m_port));
    request.typeName = QStringLiteral("NoSuchType");
    const ModuleRunResult notCreated = runAndWait(controller, request);
    QVERIFY(!notCreated.ok);
    QVERIFY2(notCreated.error.contains(QStringLiteral("create_component failed")),
             qPrintable(notCreated.error));
    QVERIFY2(notCreated.error.contains(QStringLiteral("NoSuchType")), qPrintable(notCreated.error));
}

void TestBuilderRunManager::unreachableManagerIsNamedQuickly()
{
    RunController controller({}, {});
    controller.setTimeout(5000);
    const QString nobody = address(LiveTest::freePort());
    QSignalSpy reported(&controller, &RunController::reported);
    QElapsedTimer clock;
    clock.start();
    const ModuleRunResult result = runAndWait(controller, testModule(nobody));
    QVERIFY(clock.elapsed() < controller.timeout());
    QVERIFY(!result.ok);
    QVERIFY2(result.error.contains(QStringLiteral("manager %1 unreachable").arg(nobody)),
             qPrintable(result.error));
    QVERIFY2(result.error.contains(QStringLiteral("ManagerTestModule.so")),
             qPrintable(result.error));
    QCOMPARE(reported.size(), 1);
    const auto outcome = reported.at(0).at(0).value<Builder::GenerateOutcome>();
    QVERIFY(!outcome.succeeded);
    QCOMPARE(outcome.diagnostics.size(), 1);
    QCOMPARE(outcome.diagnostics.first().object, QStringLiteral("manager %1").arg(nobody));
    QVERIFY(controller.runAction() && !controller.isRunning());
}

void TestBuilderRunManager::hungManagerTimesOutWithoutBlocking()
{
    quint16 port = 0;
    QString error;
    QProcess *hung = startManager(&port, &error);
    QVERIFY2(hung, qPrintable(error));
    ::kill(pid_t(hung->processId()), SIGSTOP);
    QVERIFY(LiveTest::waitUntilStopped(hung->processId()));

    RunController controller({}, {});
    controller.setTimeout(1500);
    int ticks = 0;
    QTimer ticker;
    ticker.setInterval(20);
    connect(&ticker, &QTimer::timeout, this, [&ticks] { ++ticks; });
    ticker.start();
    QSignalSpy finished(&controller, &RunController::runFinished);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(controller.runModule(testModule(address(port))));
    // Starting a run returns at once; a second one waits for the first.
    QVERIFY(clock.elapsed() < 500);
    QVERIFY(controller.isRunning());
    QVERIFY(!controller.runModule(testModule(address(port))));
    QVERIFY(finished.wait(controller.timeout() + 5000));
    const qint64 elapsed = clock.elapsed();
    ::kill(pid_t(hung->processId()), SIGCONT);
    m_live.stop(hung);

    const auto result = finished.at(0).at(0).value<ModuleRunResult>();
    QVERIFY(!result.ok);
    QVERIFY2(result.error.contains(QStringLiteral("manager %1 did not answer").arg(address(port))),
             qPrintable(result.error));
    QVERIFY2(elapsed >= controller.timeout() - 100 && elapsed < controller.timeout() + 3000,
             qPrintable(QString::number(elapsed)));
    // The event loop kept turning the whole time (20 ms ticks over at least 1.5 s).
    QVERIFY2(ticks >= 30, qPrintable(QString::number(ticks)));
    QVERIFY(!controller.isRunning());
}

void TestBuilderRunManager::editorRunsThroughTheChooser()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(
        window.openFiles({RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/buildergenerate/Counter.xml")}));
    Studio::Perspective *builder = window.perspective(Studio::Perspective::Id::Builder);
    auto *editor
        = qobject_cast<Builder::ComponentEditor *>(builder->editor(window.activeDocument()));
    QVERIFY(editor);
    const auto runs = editor->findChildren<RunController *>();
    const auto builds = editor->findChildren<Builder::BuildController *>();
    const auto generates = editor->findChildren<Builder::GenerateController *>();
    QCOMPARE(runs.size(), 1);
    QCOMPARE(builds.size(), 1);
    QCOMPARE(generates.size(), 1);
    RunController *run = runs.first();
    // Right after Build on the editor's tool bar, off while nothing was built.
    const QList<QAction *> actions = editor->toolBar()->actions();
    QCOMPARE(actions.indexOf(run->runAction()), actions.indexOf(builds.first()->buildAction()) + 1);
    QVERIFY(!run->runAction()->isEnabled());

    // Built: the module is where the generated CMake project puts it. The test module has no
    // CounterInit, so the manager refuses it, which names the init function.
    QTemporaryDir project;
    QVERIFY(QDir(project.path()).mkpath(QStringLiteral("build/src")));
    generates.first()->setOutputFolder(project.path());
    QVERIFY(QFile::copy(testModulePath, project.filePath(QStringLiteral("build/src/Counter.so"))));
    run->updateActions();
    QVERIFY(run->runAction()->isEnabled());

    run->runAction()->trigger();
    Builder::RunManagerDialog *dialog = run->dialog();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QVERIFY(!dialog->isModal());
    QCOMPARE(dialog->address(), QStringLiteral("localhost:2810"));
    dialog->setAddress(QStringLiteral("not a host:x"));
    QVERIFY(!dialog->runButton()->isEnabled());
    dialog->setAddress(address(m_port));
    QVERIFY(dialog->runButton()->isEnabled());
    QSignalSpy finished(run, &RunController::runFinished);
    // The action is off while the run lasts; a refusal can come back before the next look at it.
    bool seenDisabled = false;
    QObject watcher; // ends the connection before seenDisabled goes
    connect(run->runAction(), &QAction::changed, &watcher,
            [&seenDisabled, run] { seenDisabled = seenDisabled || !run->runAction()->isEnabled(); });
    QTest::mouseClick(dialog->runButton(), Qt::LeftButton);
    QTRY_VERIFY(!run->dialog());
    QVERIFY(finished.count() > 0 || finished.wait(run->timeout() + 5000));
    QVERIFY(seenDisabled);
    QVERIFY(run->runAction()->isEnabled());

    const QString status = window.statusBar()->currentMessage();
    QVERIFY2(status.contains(QStringLiteral("load_module refused")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("CounterInit")), qPrintable(status));
    Studio::ProblemsPanel *problems = window.problemsPanel();
    QCOMPARE(problems->count(), 1);
    QVERIFY(problems->text(0).contains(QStringLiteral("Counter.so")));
    QCOMPARE(problems->location(0), QStringLiteral("manager %1").arg(address(m_port)));
    QCOMPARE(RunController::managerAddress(), address(m_port));
}

void TestBuilderRunManager::problemsRowOpensFileAtLine()
{
    Studio::ProblemsPanel panel;
    panel.resize(900, 300);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const QString source = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builderrun/BrokenCounter.cpp");
    Profile::Diagnostics diagnostics;
    diagnostics << Profile::Diagnostic::warning(source, 6, 5, QStringLiteral("unused variable"))
                << Profile::Diagnostic::error(source, 14, 21,
                                              QStringLiteral("'undeclaredValue' was not declared"));
    panel.setDiagnostics(QStringLiteral("Build failed"), diagnostics);
    Builder::SourceViewer *viewer = panel.sourceViewer();
    QVERIFY(viewer);
    QVERIFY(!viewer->isVisible());

    // Double-clicking the row, as a user does.
    auto *list = panel.findChild<QTreeWidget *>(QStringLiteral("problemsList"));
    QVERIFY(list);
    QSignalSpy activated(&panel, &Studio::ProblemsPanel::diagnosticActivated);
    const QRect row = list->visualItemRect(list->topLevelItem(1));
    QVERIFY(row.isValid());
    // QTest's double click lacks the press before it that a real one has.
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, row.center());
    QTest::mouseDClick(list->viewport(), Qt::LeftButton, {}, row.center());
    QTRY_COMPARE(activated.size(), 1);
    QVERIFY(viewer->isVisible());
    QCOMPARE(viewer->filePath(), source);
    QCOMPARE(viewer->currentLine(), 14);
    const QTextCursor cursor = viewer->editor()->textCursor();
    QCOMPARE(cursor.block().text().trimmed(), QStringLiteral("return counted + undeclaredValue;"));
    QCOMPARE(cursor.positionInBlock(), 20);
    QCOMPARE(viewer->editor()->extraSelections().size(), 1);
    QCOMPARE(viewer->editor()->extraSelections().first().cursor.blockNumber(), 13);
    QVERIFY(viewer->editor()->isReadOnly());

    // Another row moves the same viewer.
    panel.activate(0);
    QCOMPARE(viewer->currentLine(), 6);
    QCOMPARE(viewer->editor()->extraSelections().first().cursor.blockNumber(), 5);

    // Rows without a file leave it as it is; Close hides it.
    panel.setDiagnostics(QStringLiteral("x"), {Profile::Diagnostic::error({}, 0, 0, "no file")});
    panel.activate(0);
    QCOMPARE(viewer->currentLine(), 6);
    auto *close = viewer->findChild<QWidget *>(QStringLiteral("closeSource"));
    QVERIFY(close);
    // Laid out once the viewer has been shown.
    QTRY_VERIFY(close->isVisible() && close->width() > 0);
    QTest::mouseClick(close, Qt::LeftButton);
    QVERIFY(!viewer->isVisible());
}

QTEST_MAIN(TestBuilderRunManager)
#include "tst_builderrunmanager.moc"
