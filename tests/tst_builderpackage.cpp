// SPDX-License-Identifier: MIT
// The Builder's Package and Publish… in the application: on the editor's tool bar after Build,
// off until the project was built; Package makes the .deb in <project>/packages with what
// `rtctl package` would write; Publish… adds it to a repository made by `rtctl repo init`, and a
// second publish of the same version is refused with the reason in the Problems panel. No
// dialog opens: the repository prompt is answered by the test.
#include "buildcontroller.h"
#include "buildoutputpanel.h"
#include "componenteditor.h"
#include "generatecontroller.h"
#include "mainwindow.h"
#include "packagecontroller.h"
#include "perspective.h"
#include "problemspanel.h"
#include "rtctlrunner.h"
#include "sdkproject.h"

#include <QAction>
#include <QDir>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>

namespace {

const QString greeterFixture = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/SdkGreeter");
constexpr int packageTimeoutMs = 120000;

} // namespace

class TestBuilderPackage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void offUntilBuilt();
    void packageMakesTheDeb();
    void publishAddsToRepository();
    void publishingAVersionTwiceIsRefused();

private:
    /// The Greeter profile opened in the Builder of @p window, its output folder the built project.
    Builder::PackageController *open(Studio::MainWindow *window, const QString &projectFolder);

    QTemporaryDir m_settingsDir;
    QTemporaryDir m_work;
    QString m_project;
    QString m_repository;
};

void TestBuilderPackage::initTestCase()
{
    QVERIFY(m_settingsDir.isValid() && m_work.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_builderpackage"));
    m_project = m_work.filePath(QStringLiteral("SdkGreeter"));
    const RtctlResult generated
        = runRtctl({"gen", greeterFixture + "/RTC.xml", "--lang", "cpp", "-o", m_project, "--idl-dir",
                    greeterFixture});
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    m_repository = m_work.filePath(QStringLiteral("repo"));
    const RtctlResult init = runRtctl({"repo", "init", m_repository});
    QVERIFY2(init.code == 0, qPrintable(init.err));
}

Builder::PackageController *TestBuilderPackage::open(Studio::MainWindow *window,
                                                     const QString &projectFolder)
{
    if (!window->openFiles({m_project + QStringLiteral("/RTC.xml")}))
        return nullptr;
    Studio::Perspective *builder = window->perspective(Studio::Perspective::Id::Builder);
    auto *editor = qobject_cast<Builder::ComponentEditor *>(builder->editor(window->activeDocument()));
    if (!editor)
        return nullptr;
    const auto generates = editor->findChildren<Builder::GenerateController *>();
    const auto packages = editor->findChildren<Builder::PackageController *>();
    if (generates.size() != 1 || packages.size() != 1)
        return nullptr;
    generates.first()->setOutputFolder(projectFolder);
    packages.first()->updateActions();
    return packages.first();
}

void TestBuilderPackage::offUntilBuilt()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Builder::PackageController *controller = open(&window, m_project);
    QVERIFY(controller);
    auto *editor = qobject_cast<Builder::ComponentEditor *>(controller->parent());
    QVERIFY(editor);
    const QList<QAction *> bar = editor->toolBar()->actions();
    QVERIFY(bar.contains(controller->packageAction()));
    QVERIFY(bar.contains(controller->publishAction()));
    // Generated, not built: off, and asked from code it says why.
    QVERIFY(!controller->packageAction()->isEnabled());
    QVERIFY(!controller->publishAction()->isEnabled());
    QVERIFY(!controller->package());
    QVERIFY2(window.problemsPanel()->summary().contains(QStringLiteral("build")),
             qPrintable(window.problemsPanel()->summary()));
}

void TestBuilderPackage::packageMakesTheDeb()
{
    QString log;
    QVERIFY2(SdkTest::buildProject(m_project, RTSTUDIO_BUILD_DIR, &log), qPrintable(log));
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Builder::PackageController *controller = open(&window, m_project);
    QVERIFY(controller);
    QVERIFY(controller->packageAction()->isEnabled());
    QSignalSpy finished(controller, &Builder::PackageController::finished);
    controller->packageAction()->trigger();
    QVERIFY(controller->isRunning());
    QVERIFY(!controller->packageAction()->isEnabled());
    QVERIFY(finished.wait(packageTimeoutMs));
    QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
    const QString deb = controller->lastPackage();
    QCOMPARE(QFileInfo(deb).absolutePath(), QDir(m_project).absoluteFilePath(QStringLiteral("packages")));
    QVERIFY2(QFileInfo(deb).fileName().startsWith(QStringLiteral("rtc-rtstudiotests-test-sdkgreeter_1.0.0_")),
             qPrintable(deb));
    QVERIFY(QFileInfo::exists(deb));
    auto *editor = qobject_cast<Builder::ComponentEditor *>(controller->parent());
    QVERIFY(editor->buildOutputPanel()->text().contains(QStringLiteral("X-RTC-Types: SdkGreeter")));
    QVERIFY2(window.problemsPanel()->summary().contains(QFileInfo(deb).fileName()),
             qPrintable(window.problemsPanel()->summary()));
    QVERIFY(controller->packageAction()->isEnabled());
}

void TestBuilderPackage::publishAddsToRepository()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Builder::PackageController *controller = open(&window, m_project);
    QVERIFY(controller && controller->publishAction()->isEnabled());
    QString offered = QStringLiteral("(not asked)");
    controller->setRepositoryPrompt([this, &offered](QWidget *, const QString &current) {
        offered = current;
        return m_repository;
    });
    QSignalSpy finished(controller, &Builder::PackageController::finished);
    controller->publishAction()->trigger();
    QVERIFY(finished.wait(packageTimeoutMs));
    QCOMPARE(offered, QString()); // nothing remembered yet
    QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
    QVERIFY(finished.first().at(1).toString().contains(QStringLiteral("Published")));
    // The repository lists it, as apt and `rtctl repo list` read it.
    const RtctlResult list = runRtctl({"repo", "list", m_repository});
    QVERIFY2(list.code == 0, qPrintable(list.err));
    QVERIFY2(list.out.contains(QStringLiteral("rtc-rtstudiotests-test-sdkgreeter 1.0.0")), qPrintable(list.out));
    QCOMPARE(Builder::PackageController::repositoryFolder(), m_repository);
}

void TestBuilderPackage::publishingAVersionTwiceIsRefused()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Builder::PackageController *controller = open(&window, m_project);
    QVERIFY(controller);
    QString offered;
    controller->setRepositoryPrompt([&offered](QWidget *, const QString &current) {
        offered = current;
        return current;
    });
    QSignalSpy finished(controller, &Builder::PackageController::finished);
    controller->publishAction()->trigger();
    QVERIFY(finished.wait(packageTimeoutMs));
    QCOMPARE(offered, m_repository); // the last one is offered again
    QVERIFY(!finished.first().at(0).toBool());
    const QString message = finished.first().at(1).toString();
    QVERIFY2(message.contains(QStringLiteral("rtc-rtstudiotests-test-sdkgreeter")), qPrintable(message));
    QVERIFY2(window.problemsPanel()->summary().contains(QStringLiteral("Cannot publish")),
             qPrintable(window.problemsPanel()->summary()));
    // Cancelling the prompt does nothing.
    controller->setRepositoryPrompt([](QWidget *, const QString &) { return QString(); });
    controller->publishAction()->trigger();
    QVERIFY(!controller->isRunning());
    QCOMPARE(finished.size(), 1);
}

QTEST_MAIN(TestBuilderPackage)
#include "tst_builderpackage.moc"
