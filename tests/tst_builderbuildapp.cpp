// SPDX-License-Identifier: MIT
// The Builder's Build in the application: a component editor's Build action builds the folder
// its Generate wrote (here replaced by a tiny fixture project), prints into the editor's build
// output panel, and lists what the compiler found in the main window's Problems panel, without
// any dialog.
#include "basicpage.h"
#include "buildcontroller.h"
#include "buildoutputpanel.h"
#include "componenteditor.h"
#include "document.h"
#include "generatecontroller.h"
#include "mainwindow.h"
#include "perspective.h"
#include "problemspanel.h"
#include "projectbuilder.h"
#include "tst_builderbuildsupport.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>

class TestBuilderBuildApp : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void buildNeedsGeneratedProject();
    void buildListsCompileErrors();
    void buildSucceeds();
    void cancelFromOutputPanel();
    void sdkPrefixIsRemembered();
    void openedFromGeneratedProject();

private:
    struct Opened
    {
        Builder::ComponentEditor *editor = nullptr;
        Builder::BuildController *build = nullptr;
        Builder::GenerateController *generate = nullptr;
    };
    /// Opens @p profile (the Counter fixture by default) in the Builder of @p window.
    Opened openCounter(Studio::MainWindow *window,
                       const QString &profile = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/buildergenerate/Counter.xml"));
    /// Generates nothing: points the component's output folder at a copy of fixture `name`.
    bool useFixture(const Opened &opened, const QString &name, const QTemporaryDir &dir);

    QTemporaryDir m_settingsDir;
};

namespace {

constexpr int buildTimeoutMs = 120000;

} // namespace

void TestBuilderBuildApp::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_builderbuildapp"));
}

void TestBuilderBuildApp::init()
{
    QSettings().clear();
}

TestBuilderBuildApp::Opened TestBuilderBuildApp::openCounter(Studio::MainWindow *window, const QString &profile)
{
    Opened opened;
    if (!window->openFiles({profile}))
        return opened;
    Studio::Perspective *builder = window->perspective(Studio::Perspective::Id::Builder);
    opened.editor
        = qobject_cast<Builder::ComponentEditor *>(builder->editor(window->activeDocument()));
    if (!opened.editor)
        return opened;
    const auto builds = opened.editor->findChildren<Builder::BuildController *>();
    const auto generates = opened.editor->findChildren<Builder::GenerateController *>();
    if (builds.size() == 1 && generates.size() == 1) {
        opened.build = builds.first();
        opened.generate = generates.first();
    }
    return opened;
}

bool TestBuilderBuildApp::useFixture(const Opened &opened, const QString &name,
                                     const QTemporaryDir &dir)
{
    if (!dir.isValid() || !BuildFixture::copy(name, dir.path()))
        return false;
    opened.generate->setOutputFolder(dir.path());
    opened.build->updateActions();
    return true;
}

void TestBuilderBuildApp::buildNeedsGeneratedProject()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const Opened opened = openCounter(&window);
    QVERIFY(opened.build);
    QAction *build = opened.build->buildAction();
    // On the editor's tool bar, next to its settings, and off until something was generated.
    QVERIFY(opened.editor->toolBar()->isVisible());
    QVERIFY(opened.editor->toolBar()->actions().contains(build));
    QVERIFY(opened.editor->toolBar()->actions().contains(opened.build->settingsAction()));
    QVERIFY(!build->isEnabled());
    QVERIFY(!opened.build->cancelAction()->isEnabled());
    QVERIFY(opened.editor->buildOutputPanel()->isHidden());

    // A folder without a generated project does not enable it either.
    QTemporaryDir empty;
    opened.generate->setOutputFolder(empty.path());
    opened.build->updateActions();
    QVERIFY(!build->isEnabled());
    // Asked anyway (from code), it says why in the Problems panel, without a dialog.
    QVERIFY(!opened.build->build());
    QVERIFY2(window.problemsPanel()->summary().contains(empty.path()),
             qPrintable(window.problemsPanel()->summary()));
    QVERIFY(window.problemsPanel()->text(0).contains(QStringLiteral("no CMakeLists.txt")));

    // Generate writing the C++ project enables it.
    QTemporaryDir project;
    QVERIFY(useFixture(opened, QStringLiteral("ok"), project));
    opened.build->buildAction()->setEnabled(false);
    emit opened.generate->generated(Codegen::WriteReport());
    QVERIFY(build->isEnabled());
}

void TestBuilderBuildApp::buildListsCompileErrors()
{
    Studio::MainWindow window;
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const Opened opened = openCounter(&window);
    QVERIFY(opened.build);
    QTemporaryDir project;
    QVERIFY(useFixture(opened, QStringLiteral("broken"), project));
    QVERIFY(opened.build->buildAction()->isEnabled());
    QVERIFY(window.problemsDock()->isHidden());

    Builder::BuildOutputPanel *panel = opened.editor->buildOutputPanel();
    QSignalSpy reported(opened.editor, &Builder::ComponentEditor::generationReported);
    opened.build->buildAction()->trigger();
    // It runs in the background: the window stays responsive and the build can be cancelled.
    QVERIFY(opened.build->isRunning());
    QVERIFY(!opened.build->buildAction()->isEnabled());
    QVERIFY(opened.build->cancelAction()->isEnabled());
    QVERIFY(panel->isVisible());
    QVERIFY(panel->isRunning());
    QVERIFY(reported.wait(buildTimeoutMs));
    QVERIFY(!opened.build->isRunning());
    QVERIFY(opened.build->buildAction()->isEnabled());

    // The output panel got the tools' output, the error among it.
    QVERIFY(panel->text().contains(QStringLiteral("cmake")));
    QVERIFY2(panel->text().contains(QStringLiteral("undeclaredName")), qPrintable(panel->text()));
    QVERIFY(!panel->isRunning());
    QVERIFY(panel->status().contains(project.path()));

    // The Problems panel lists the error with file and line, and comes up.
    Studio::ProblemsPanel *problems = window.problemsPanel();
    QVERIFY(window.problemsDock()->isVisible());
    QVERIFY2(problems->summary().contains(project.path()), qPrintable(problems->summary()));
    QCOMPARE(window.statusBar()->currentMessage(), problems->summary());
    int errorRow = -1;
    for (int row = 0; row < problems->count(); ++row) {
        if (problems->text(row).startsWith(project.filePath(QStringLiteral("src/broken.cpp:6:")))
            && problems->text(row).contains(QStringLiteral(": error: ")))
            errorRow = row;
    }
    QVERIFY2(errorRow >= 0, qPrintable(problems->text(0)));
    QCOMPARE(problems->location(errorRow).section(QLatin1Char(':'), 0, 1),
             QStringLiteral("broken.cpp:6"));
    QVERIFY(!QApplication::activeModalWidget());
}

void TestBuilderBuildApp::buildSucceeds()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const Opened opened = openCounter(&window);
    QVERIFY(opened.build);
    QTemporaryDir project;
    QVERIFY(useFixture(opened, QStringLiteral("ok"), project));
    QSignalSpy reported(opened.editor, &Builder::ComponentEditor::generationReported);
    // Ctrl+B in the editor builds too.
    opened.editor->basicPage()->setFocus();
    QTest::keyClick(opened.editor, Qt::Key_B, Qt::ControlModifier);
    QVERIFY(opened.build->isRunning());
    QVERIFY(reported.wait(buildTimeoutMs));
    const auto outcome = reported.at(0).at(0).value<Builder::GenerateOutcome>();
    QVERIFY(outcome.succeeded);
    QVERIFY(outcome.summary.contains(project.path()));
    QVERIFY(QFileInfo(project.filePath(QStringLiteral("build/hello"))).isExecutable());
    Builder::BuildOutputPanel *panel = opened.editor->buildOutputPanel();
    QVERIFY(panel->text().contains(QStringLiteral("Built target hello")));
    QCOMPARE(panel->progressBar()->value(), panel->progressBar()->maximum());
    QCOMPARE(window.problemsPanel()->summary(), outcome.summary);
    QVERIFY(window.problemsDock()->isHidden()); // success does not push the panel up
}

void TestBuilderBuildApp::cancelFromOutputPanel()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const Opened opened = openCounter(&window);
    QVERIFY(opened.build);
    QTemporaryDir project;
    QVERIFY(useFixture(opened, QStringLiteral("slow"), project));
    QSignalSpy reported(opened.editor, &Builder::ComponentEditor::generationReported);
    opened.build->buildAction()->trigger();
    Builder::BuildOutputPanel *panel = opened.editor->buildOutputPanel();
    QTRY_VERIFY_WITH_TIMEOUT(panel->text().contains(QStringLiteral("Waiting a long time")),
                             buildTimeoutMs);
    QVERIFY(panel->cancelButton()->isEnabled());
    QTest::mouseClick(panel->cancelButton(), Qt::LeftButton);
    QVERIFY(reported.count() == 1 || reported.wait(10000));
    const auto outcome = reported.at(0).at(0).value<Builder::GenerateOutcome>();
    QVERIFY(!outcome.succeeded);
    QVERIFY(outcome.summary.contains(QStringLiteral("cancelled")));
    QVERIFY(!opened.build->isRunning());
    QVERIFY(!panel->cancelButton()->isEnabled());
}

void TestBuilderBuildApp::sdkPrefixIsRemembered()
{
    QCOMPARE(Builder::BuildController::sdkPrefix(), Codegen::ProjectBuilder::defaultSdkPrefix());
    QVERIFY(!Codegen::ProjectBuilder::defaultSdkPrefix().isEmpty());
    Builder::BuildController::setSdkPrefix(QStringLiteral("/opt/openrtm"));
    Builder::BuildController::setBuildType(QStringLiteral("Debug"));
    QCOMPARE(QSettings().value(QStringLiteral("builder/build/sdkPrefix")).toString(),
             QStringLiteral("/opt/openrtm"));
    QCOMPARE(Builder::BuildController::sdkPrefix(), QStringLiteral("/opt/openrtm"));
    QCOMPARE(Builder::BuildController::buildType(), QStringLiteral("Debug"));
    // An empty prefix is a choice too (CMake searches the system), not the default.
    Builder::BuildController::setSdkPrefix(QString());
    QCOMPARE(Builder::BuildController::sdkPrefix(), QString());
    Builder::BuildController::resetSdkPrefix();
    QCOMPARE(Builder::BuildController::sdkPrefix(), Codegen::ProjectBuilder::defaultSdkPrefix());

    // The build passes them to CMake.
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const Opened opened = openCounter(&window);
    QVERIFY(opened.build);
    QTemporaryDir project;
    QVERIFY(useFixture(opened, QStringLiteral("ok"), project));
    Builder::BuildController::setSdkPrefix(project.path());
    QSignalSpy reported(opened.editor, &Builder::ComponentEditor::generationReported);
    opened.build->buildAction()->trigger();
    QVERIFY(reported.wait(buildTimeoutMs));
    const QString text = opened.editor->buildOutputPanel()->text();
    QVERIFY(text.contains(QStringLiteral("-DCMAKE_PREFIX_PATH=") + project.path()));
    QVERIFY(text.contains(QStringLiteral("-DCMAKE_BUILD_TYPE=Debug")));
}

void TestBuilderBuildApp::openedFromGeneratedProject()
{
    // The RTC.xml a generated project keeps: Build works on its folder without a Generate first.
    QTemporaryDir project;
    QVERIFY(project.isValid() && BuildFixture::copy(QStringLiteral("ok"), project.path()));
    const QString profile = project.filePath(QStringLiteral("RTC.xml"));
    QVERIFY(QFile::copy(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/buildergenerate/Counter.xml"), profile));
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const Opened opened = openCounter(&window, profile);
    QVERIFY(opened.build);
    opened.build->updateActions();
    QVERIFY(opened.build->buildAction()->isEnabled());
    QCOMPARE(QDir(opened.build->projectFolder()).canonicalPath(), QDir(project.path()).canonicalPath());
}

QTEST_MAIN(TestBuilderBuildApp)
#include "tst_builderbuildapp.moc"
