// SPDX-License-Identifier: MIT
// The main window, offscreen: perspectives, actions, opening, undo/redo through the menu, the
// questions asked on close and quit, failed loads and saves, recent files and settings.
#include "basicpage.h"
#include "componenteditor.h"
#include "document.h"
#include "documentcontroller.h"
#include "mainwindow.h"
#include "problemspanel.h"
#include "recentfiles.h"
#include "userprompts.h"

#include <QAction>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTimer>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <functional>

using namespace Studio;
using Id = Perspective::Id;

namespace {

/// Answers the window's questions from a script and records what it was asked and told.
class ScriptedPrompts : public UserPrompts
{
public:
    struct Shown
    {
        QString title;
        QString text;
        Profile::Diagnostics diagnostics;
    };

    QList<SaveChoice> saveChoices;
    QStringList fileNamesToOpen;
    QStringList saveFileNames;

    QStringList askedToSave;
    QStringList suggestedSavePaths;
    QList<Shown> shown;
    int aboutShown = 0;

    SaveChoice askSaveChanges(const QString &documentName) override
    {
        askedToSave << documentName;
        return saveChoices.isEmpty() ? SaveChoice::Cancel : saveChoices.takeFirst();
    }
    QStringList askOpenFileNames(const QString &) override { return fileNamesToOpen; }
    QString askSaveFileName(Profile::ProfileKind, const QString &suggestedPath) override
    {
        suggestedSavePaths << suggestedPath;
        return saveFileNames.isEmpty() ? QString() : saveFileNames.takeFirst();
    }
    void showProblems(const QString &title, const QString &text,
                      const Profile::Diagnostics &diagnostics) override
    {
        shown << Shown {title, text, diagnostics};
    }
    void showAbout() override { ++aboutShown; }
};

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/app/")) + name;
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void startsEmptyInBuilder();
    void switchesPerspectivesFromToolbar();
    void newDocumentsGoToTheirPerspective();
    void opensFilesByContentIntoPerspectives();
    void openingAnOpenFileActivatesIt();
    void undoRedoThroughEditMenu();
    void undoFollowsActivePerspective();
    void failedOpenLeavesDocumentsUntouched();
    void failedSaveKeepsDocumentOpenAndModified();
    void closingModifiedTabAsks_data();
    void closingModifiedTabAsks();
    void saveOfUntitledAsksForName();
    void quitAsksAboutEveryModifiedDocument();
    void recentFilesMenuReopensAndPrunes();
    void restoresPerspectiveAndGeometry();
    void firstStartFitsTheScreen();
    void aboutGoesThroughPrompts();
    void opensDroppedFiles();
    void slowOpenShowsProgressAndCancels();
    void slowOpenCompletes();

private:
    QAction *action(const char *name) const;
    QLineEdit *nameEdit(Document *document) const;
    QString copyFixture(const QString &name) const;

    QTemporaryDir m_settingsDir;
    std::unique_ptr<QTemporaryDir> m_scratch;
    std::unique_ptr<MainWindow> m_window;
    ScriptedPrompts *m_prompts = nullptr;
};

void TestMainWindow::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_mainwindow"));
}

void TestMainWindow::init()
{
    QSettings().clear();
    m_scratch = std::make_unique<QTemporaryDir>();
    m_window = std::make_unique<MainWindow>();
    auto prompts = std::make_unique<ScriptedPrompts>();
    m_prompts = prompts.get();
    m_window->setPrompts(std::move(prompts));
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestMainWindow::cleanup()
{
    m_window.reset();
    m_prompts = nullptr;
    m_scratch.reset();
}

QAction *TestMainWindow::action(const char *name) const
{
    return m_window->findChild<QAction *>(QLatin1String(name));
}

QLineEdit *TestMainWindow::nameEdit(Document *document) const
{
    auto *editor = qobject_cast<Builder::ComponentEditor *>(m_window->perspective(Id::Builder)->editor(document));
    return editor
        ? qobject_cast<QLineEdit *>(editor->basicPage()->editor(Builder::BasicField::Name))
        : nullptr;
}

QString TestMainWindow::copyFixture(const QString &name) const
{
    const QString target = m_scratch->filePath(name);
    QFile::copy(dataPath(name), target);
    QFile::setPermissions(target, QFile::ReadOwner | QFile::WriteOwner);
    return target;
}

void TestMainWindow::startsEmptyInBuilder()
{
    QCOMPARE(m_window->currentPerspective()->id(), Id::Builder);
    QVERIFY(action("actionPerspectiveBuilder")->isChecked());
    QVERIFY(!m_window->activeDocument());
    QVERIFY(!action("actionSave")->isEnabled());
    QVERIFY(!action("actionSaveAs")->isEnabled());
    QVERIFY(!action("actionClose")->isEnabled());
    QVERIFY(!action("actionUndo")->isEnabled());
    QVERIFY(!action("actionRedo")->isEnabled());
    QVERIFY(action("actionNewComponent")->isEnabled());
    QVERIFY(action("actionOpen")->isEnabled());
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("RT Studio")));
    QVERIFY(!m_window->windowIcon().isNull());
    QVERIFY(!action("actionSave")->icon().isNull());
    QVERIFY(!m_window->problemsDock()->isVisible());
}

void TestMainWindow::switchesPerspectivesFromToolbar()
{
    auto *toolBar = m_window->findChild<QToolBar *>(QStringLiteral("mainToolBar"));
    QVERIFY(toolBar);
    QVERIFY(toolBar->actions().contains(action("actionPerspectiveSystemEditor")));
    QWidget *button = toolBar->widgetForAction(action("actionPerspectiveSystemEditor"));
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(m_window->currentPerspective()->id(), Id::SystemEditor);
    QVERIFY(action("actionPerspectiveSystemEditor")->isChecked());
    QVERIFY(!action("actionPerspectiveBuilder")->isChecked());
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("System Editor")));

    action("actionPerspectiveBuilder")->trigger();
    QCOMPARE(m_window->currentPerspective()->id(), Id::Builder);
}

void TestMainWindow::newDocumentsGoToTheirPerspective()
{
    action("actionNewComponent")->trigger();
    QCOMPARE(m_window->currentPerspective()->id(), Id::Builder);
    QCOMPARE(m_window->perspective(Id::Builder)->documents().size(), 1);
    Document *component = m_window->activeDocument();
    QVERIFY(component);
    QCOMPARE(component->kind(), Profile::ProfileKind::Rtc);
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("New Component 1")));
    QVERIFY(action("actionSave")->isEnabled()); // untitled: Save asks for a name
    QVERIFY(action("actionClose")->isEnabled());

    action("actionNewSystem")->trigger();
    QCOMPARE(m_window->currentPerspective()->id(), Id::SystemEditor);
    QCOMPARE(m_window->perspective(Id::SystemEditor)->documents().size(), 1);
    QCOMPARE(m_window->activeDocument()->kind(), Profile::ProfileKind::Rts);
    QCOMPARE(m_window->perspective(Id::Builder)->documents().size(), 1);

    action("actionPerspectiveBuilder")->trigger();
    QCOMPARE(m_window->activeDocument(), component);
}

void TestMainWindow::opensFilesByContentIntoPerspectives()
{
    QVERIFY(m_window->openFiles({dataPath(QStringLiteral("system.yaml"))}));
    QCOMPARE(m_window->currentPerspective()->id(), Id::SystemEditor);
    QCOMPARE(m_window->activeDocument()->displayName(), QStringLiteral("system.yaml"));

    m_prompts->fileNamesToOpen = {dataPath(QStringLiteral("component.xml"))};
    action("actionOpen")->trigger();
    QCOMPARE(m_window->currentPerspective()->id(), Id::Builder);
    Document *component = m_window->activeDocument();
    QVERIFY(component);
    QCOMPARE(component->displayName(), QStringLiteral("component.xml"));
    QVERIFY(!component->isModified());
    QVERIFY(m_window->windowTitle().startsWith(QStringLiteral("component.xml[*]")));
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(nameEdit(component)->text(), QStringLiteral("RangeFilter"));
    QTabWidget *tabs = m_window->perspective(Id::Builder)->tabWidget();
    QCOMPARE(tabs->tabText(tabs->currentIndex()), QStringLiteral("component.xml"));
    QCOMPARE(m_window->documents()->recentFiles()->files().size(), 2);
    QVERIFY(m_prompts->shown.isEmpty());
}

void TestMainWindow::openingAnOpenFileActivatesIt()
{
    QVERIFY(m_window->openFiles({dataPath(QStringLiteral("component.xml"))}));
    Document *first = m_window->activeDocument();
    action("actionNewSystem")->trigger();
    QCOMPARE(m_window->currentPerspective()->id(), Id::SystemEditor);
    QVERIFY(m_window->openFiles({dataPath(QStringLiteral("component.xml"))}));
    QCOMPARE(m_window->currentPerspective()->id(), Id::Builder);
    QCOMPARE(m_window->activeDocument(), first);
    QCOMPARE(m_window->documents()->documents().size(), 2);
}

void TestMainWindow::undoRedoThroughEditMenu()
{
    QVERIFY(m_window->openFiles({copyFixture(QStringLiteral("component.xml"))}));
    Document *document = m_window->activeDocument();
    QLineEdit *name = nameEdit(document);
    QVERIFY(name);

    QMenu *editMenu = nullptr;
    for (QAction *menuAction : m_window->menuBar()->actions()) {
        if (menuAction->menu() && menuAction->menu()->actions().contains(action("actionUndo")))
            editMenu = menuAction->menu();
    }
    QVERIFY(editMenu);
    QVERIFY(editMenu->actions().contains(action("actionRedo")));

    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("Renamed"));
    QVERIFY(document->isModified());
    QVERIFY(m_window->isWindowModified());
    QVERIFY(action("actionUndo")->isEnabled());
    QVERIFY(action("actionSave")->isEnabled());
    QVERIFY(action("actionUndo")->text().contains(QStringLiteral("component name")));
    QTabWidget *tabs = m_window->perspective(Id::Builder)->tabWidget();
    QCOMPARE(tabs->tabText(tabs->currentIndex()), QStringLiteral("component.xml*"));

    action("actionUndo")->trigger();
    QCOMPARE(name->text(), QStringLiteral("RangeFilter"));
    QVERIFY(!document->isModified());
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(!action("actionUndo")->isEnabled());
    QVERIFY(!action("actionSave")->isEnabled());
    QVERIFY(action("actionRedo")->isEnabled());

    action("actionRedo")->trigger();
    QCOMPARE(name->text(), QStringLiteral("Renamed"));
    QVERIFY(m_window->isWindowModified());

    action("actionSave")->trigger();
    QVERIFY(!document->isModified());
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(readAll(document->filePath()).contains("Renamed"));
}

void TestMainWindow::undoFollowsActivePerspective()
{
    QVERIFY(m_window->openFiles({dataPath(QStringLiteral("component.xml"))}));
    QTest::keyClicks(nameEdit(m_window->activeDocument()), QStringLiteral("X"));
    QVERIFY(action("actionUndo")->isEnabled());
    action("actionPerspectiveSystemEditor")->trigger();
    QVERIFY(!m_window->activeDocument());
    QVERIFY(!action("actionUndo")->isEnabled());
    action("actionPerspectiveBuilder")->trigger();
    QVERIFY(action("actionUndo")->isEnabled());
}

void TestMainWindow::failedOpenLeavesDocumentsUntouched()
{
    QVERIFY(m_window->openFiles({dataPath(QStringLiteral("component.xml"))}));
    Document *document = m_window->activeDocument();
    QTest::keyClicks(nameEdit(document), QStringLiteral("Edit"));
    const QByteArray before = document->serialize(Profile::FileFormat::Xml);

    QVERIFY(!m_window->openFiles(
        {dataPath(QStringLiteral("broken.xml")), dataPath(QStringLiteral("not-a-profile.xml"))}));
    QCOMPARE(m_window->documents()->documents().size(), 1);
    QCOMPARE(m_window->activeDocument(), document);
    QVERIFY(document->isModified());
    QCOMPARE(document->serialize(Profile::FileFormat::Xml), before);
    QCOMPARE(document->undoStack()->count(), 1);

    QCOMPARE(m_prompts->shown.size(), 1); // one report for both files
    const ScriptedPrompts::Shown &report = m_prompts->shown.first();
    QVERIFY(report.text.contains(QStringLiteral("broken.xml")));
    QVERIFY(report.text.contains(QStringLiteral("not-a-profile.xml")));
    QVERIFY(report.diagnostics.size() >= 2);
    QVERIFY2(report.diagnostics.first().toString().contains(QStringLiteral("broken.xml:")),
             qPrintable(report.diagnostics.first().toString()));

    ProblemsPanel *problems = m_window->problemsPanel();
    QVERIFY(m_window->problemsDock()->isVisible());
    QCOMPARE(problems->count(), int(report.diagnostics.size()));
    QVERIFY(problems->text(0).contains(QStringLiteral("broken.xml:")));
    QVERIFY(m_window->problemsDock()->windowTitle().contains(QString::number(problems->count())));
}

void TestMainWindow::failedSaveKeepsDocumentOpenAndModified()
{
    const QString path = copyFixture(QStringLiteral("component.xml"));
    QVERIFY(m_window->openFiles({path}));
    Document *document = m_window->activeDocument();
    QTest::keyClicks(nameEdit(document), QStringLiteral("Edit"));
    m_prompts->saveFileNames = {m_scratch->filePath(QStringLiteral("missing/dir/RTC.xml"))};

    action("actionSaveAs")->trigger();
    QCOMPARE(m_prompts->shown.size(), 1);
    QVERIFY(m_prompts->shown.first().title.contains(QStringLiteral("Save")));
    QVERIFY(!m_prompts->shown.first().diagnostics.isEmpty());
    QCOMPARE(m_window->activeDocument(), document);
    QVERIFY(document->isModified());
    QVERIFY(m_window->isWindowModified());
    QCOMPARE(document->filePath(), path);
    QVERIFY(m_window->problemsPanel()->count() > 0);
    QVERIFY(m_window->problemsPanel()->summary().contains(QStringLiteral("RTC.xml")));
}

void TestMainWindow::closingModifiedTabAsks_data()
{
    QTest::addColumn<int>("choice");
    QTest::addColumn<bool>("closed");
    QTest::addColumn<bool>("saved");
    QTest::newRow("cancel") << int(UserPrompts::SaveChoice::Cancel) << false << false;
    QTest::newRow("discard") << int(UserPrompts::SaveChoice::Discard) << true << false;
    QTest::newRow("save") << int(UserPrompts::SaveChoice::Save) << true << true;
}

void TestMainWindow::closingModifiedTabAsks()
{
    QFETCH(int, choice);
    QFETCH(bool, closed);
    QFETCH(bool, saved);
    const QString path = copyFixture(QStringLiteral("component.xml"));
    QVERIFY(m_window->openFiles({path}));
    QTest::keyClicks(nameEdit(m_window->activeDocument()), QStringLiteral("Z"));
    m_prompts->saveChoices = {UserPrompts::SaveChoice(choice)};

    QTabBar *tabBar = m_window->perspective(Id::Builder)->tabWidget()->tabBar();
    QWidget *closeButton = tabBar->tabButton(0, QTabBar::RightSide);
    QVERIFY(closeButton);
    QTest::mouseClick(closeButton, Qt::LeftButton);

    QCOMPARE(m_prompts->askedToSave, QStringList {QStringLiteral("component.xml")});
    QCOMPARE(m_window->perspective(Id::Builder)->documents().isEmpty(), closed);
    QCOMPARE(m_window->documents()->documents().isEmpty(), closed);
    QCOMPARE(readAll(path).contains("RangeFilterZ"), saved);
    QCOMPARE(action("actionClose")->isEnabled(), !closed);
}

void TestMainWindow::saveOfUntitledAsksForName()
{
    action("actionNewComponent")->trigger();
    Document *document = m_window->activeDocument();
    const QString target = m_scratch->filePath(QStringLiteral("Mine.yaml"));
    m_prompts->saveFileNames = {target};
    action("actionSave")->trigger();
    QCOMPARE(m_prompts->suggestedSavePaths.size(), 1);
    QVERIFY(m_prompts->suggestedSavePaths.first().endsWith(QStringLiteral("RTC.xml")));
    QCOMPARE(document->filePath(), target);
    QCOMPARE(document->format(), Profile::FileFormat::Yaml);
    QVERIFY(readAll(target).contains("rtcProfile"));
    QVERIFY(m_window->windowTitle().startsWith(QStringLiteral("Mine.yaml[*]")));
    QTabWidget *tabs = m_window->perspective(Id::Builder)->tabWidget();
    QCOMPARE(tabs->tabText(tabs->currentIndex()), QStringLiteral("Mine.yaml"));
    QVERIFY(!action("actionSave")->isEnabled());
    QCOMPARE(m_window->documents()->recentFiles()->files().value(0), target);
}

void TestMainWindow::quitAsksAboutEveryModifiedDocument()
{
    QVERIFY(m_window->openFiles({dataPath(QStringLiteral("component.xml"))}));
    QTest::keyClicks(nameEdit(m_window->activeDocument()), QStringLiteral("A"));
    action("actionNewSystem")->trigger(); // unmodified: nobody asks about it
    QVERIFY(m_window->openFiles({dataPath(QStringLiteral("component.yaml"))}));
    QTest::keyClicks(nameEdit(m_window->activeDocument()), QStringLiteral("B"));

    m_prompts->saveChoices = {UserPrompts::SaveChoice::Discard, UserPrompts::SaveChoice::Cancel};
    QVERIFY(!m_window->close());
    QVERIFY(m_window->isVisible());
    QCOMPARE(m_prompts->askedToSave.size(), 2);
    QCOMPARE(m_window->documents()->documents().size(), 3); // cancel closes nothing

    m_prompts->saveChoices = {UserPrompts::SaveChoice::Discard, UserPrompts::SaveChoice::Discard};
    action("actionQuit")->trigger();
    QVERIFY(!m_window->isVisible());
    QCOMPARE(m_prompts->askedToSave.size(), 4);
    QVERIFY(m_window->documents()->documents().isEmpty());
}

void TestMainWindow::recentFilesMenuReopensAndPrunes()
{
    const QString kept = copyFixture(QStringLiteral("component.xml"));
    const QString gone = copyFixture(QStringLiteral("system.xml"));
    QVERIFY(m_window->openFiles({kept, gone}));
    QVERIFY(m_window->documents()->closeAll());
    QVERIFY(QFile::remove(gone));

    auto *menu = m_window->findChild<QMenu *>(QStringLiteral("menuRecentFiles"));
    QVERIFY(menu);
    emit menu->aboutToShow();
    QStringList entries;
    QAction *keptEntry = nullptr;
    for (QAction *entry : menu->actions()) {
        entries << entry->toolTip();
        if (entry->toolTip() == kept)
            keptEntry = entry;
    }
    QVERIFY(!entries.contains(gone));
    QCOMPARE(entries.count(kept), 1);
    QVERIFY(keptEntry);
    keptEntry->trigger();
    QCOMPARE(m_window->documents()->documents().size(), 1);
    QCOMPARE(m_window->activeDocument()->filePath(), kept);
}

void TestMainWindow::firstStartFitsTheScreen()
{
    // init() made the window with no stored geometry.
    const QRect available = m_window->screen()->availableGeometry();
    QVERIFY2(available.contains(m_window->frameGeometry()) || available.contains(m_window->geometry()),
             qPrintable(QStringLiteral("%1x%2 window on a %3x%4 screen")
                            .arg(m_window->width()).arg(m_window->height())
                            .arg(available.width()).arg(available.height())));
    QVERIFY(m_window->width() >= qMin(1200, available.width() * 9 / 10) - 1);
}

void TestMainWindow::restoresPerspectiveAndGeometry()
{
    action("actionPerspectiveSystemEditor")->trigger();
    m_window->resize(900, 640);
    QVERIFY(m_window->close());
    QSettings settings;
    QVERIFY(settings.contains(QStringLiteral("mainWindow/geometry")));
    QVERIFY(settings.contains(QStringLiteral("mainWindow/state")));

    MainWindow again;
    QCOMPARE(again.currentPerspective()->id(), Id::SystemEditor);
    QVERIFY(
        again.findChild<QAction *>(QStringLiteral("actionPerspectiveSystemEditor"))->isChecked());
    QCOMPARE(again.size(), QSize(900, 640));
}

void TestMainWindow::aboutGoesThroughPrompts()
{
    action("actionAbout")->trigger();
    QCOMPARE(m_prompts->aboutShown, 1);
}

void TestMainWindow::opensDroppedFiles()
{
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(dataPath(QStringLiteral("system.xml"))),
                  QUrl::fromLocalFile(dataPath(QStringLiteral("component.yaml")))});
    const QPoint centre = m_window->rect().center();
    QDragEnterEvent enter(centre, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(m_window.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(centre, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(m_window.get(), &drop);
    QCOMPARE(m_window->perspective(Id::SystemEditor)->documents().size(), 1);
    QCOMPARE(m_window->perspective(Id::Builder)->documents().size(), 1);
    QCOMPARE(m_window->activeDocument()->displayName(), QStringLiteral("component.yaml"));
}

namespace {

/// Runs @p step from the event loop (every 10 ms) once the opening progress is shown, then stops.
struct WhenOpeningShows
{
    QTimer timer;
    bool seen = false;

    WhenOpeningShows(QWidget *progress, const std::function<void()> &step)
    {
        timer.setInterval(10);
        QObject::connect(&timer, &QTimer::timeout, [this, progress, step] {
            if (progress->isHidden())
                return;
            seen = true;
            timer.stop();
            step();
        });
        timer.start();
    }
};

} // namespace

void TestMainWindow::slowOpenShowsProgressAndCancels()
{
    // A file read slowly: a pipe that gives its bytes when the test decides.
    const QString pipe = m_scratch->filePath(QStringLiteral("slow.xml"));
    QVERIFY(mkfifo(QFile::encodeName(pipe).constData(), 0600) == 0);
    auto *progress = m_window->findChild<QWidget *>(QStringLiteral("openingProgress"));
    auto *cancel = m_window->findChild<QPushButton *>(QStringLiteral("cancelOpening"));
    QVERIFY(progress && cancel);
    QVERIFY(progress->isHidden());
    auto *newSystem = m_window->findChild<QToolBar *>()->widgetForAction(action("actionNewSystem"));
    QVERIFY(newSystem);

    QString label;
    int documentsMeanwhile = -1;
    WhenOpeningShows step(progress, [&] {
        label = progress->findChild<QLabel *>()->text();
        // The window takes no other input while it waits: no shortcut, no tool button.
        QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier);
        QTest::mouseClick(newSystem, Qt::LeftButton);
        documentsMeanwhile = int(m_window->documents()->documents().size());
        QTest::mouseClick(cancel, Qt::LeftButton);
    });
    QSignalSpy messages(m_window->documents(), &DocumentController::statusMessage);
    QVERIFY(!m_window->openFiles({pipe}));
    QVERIFY(step.seen);
    QCOMPARE(label, QStringLiteral("Opening slow.xml…"));
    QCOMPARE(documentsMeanwhile, 0);
    QVERIFY(progress->isHidden());
    QVERIFY(m_window->documents()->documents().isEmpty());
    QVERIFY(m_prompts->shown.isEmpty()); // cancelled is not failed
    QCOMPARE(messages.count(), 1);
    QCOMPARE(messages.first().first().toString(), QStringLiteral("Opening slow.xml was cancelled"));
    // Input reaches the window again.
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier);
    QCOMPARE(m_window->documents()->documents().size(), 1);
    // The reader still waits on the pipe: let it finish.
    const int fd = ::open(QFile::encodeName(pipe).constData(), O_WRONLY);
    QVERIFY(fd >= 0);
    ::close(fd);
}

void TestMainWindow::slowOpenCompletes()
{
    const QString pipe = m_scratch->filePath(QStringLiteral("arriving.xml"));
    QVERIFY(mkfifo(QFile::encodeName(pipe).constData(), 0600) == 0);
    auto *progress = m_window->findChild<QWidget *>(QStringLiteral("openingProgress"));
    QVERIFY(progress);
    const QByteArray system = readAll(dataPath(QStringLiteral("system.xml")));
    QVERIFY(!system.isEmpty());
    bool written = false;
    WhenOpeningShows step(progress, [&] {
        const int fd = ::open(QFile::encodeName(pipe).constData(), O_WRONLY);
        written = fd >= 0 && ::write(fd, system.constData(), size_t(system.size())) == system.size();
        ::close(fd);
    });
    QVERIFY(m_window->openFiles({pipe}));
    QVERIFY(step.seen);
    QVERIFY(written);
    QVERIFY(progress->isHidden());
    QCOMPARE(m_window->perspective(Id::SystemEditor)->documents().size(), 1);
    QCOMPARE(m_window->activeDocument()->displayName(), QStringLiteral("arriving.xml"));
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
