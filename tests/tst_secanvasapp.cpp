// SPDX-License-Identifier: MIT
// The System Editor in the application: the system editor tab shows the canvas, repository and
// properties over the document's model and undo stack; `rtstudio --export-diagram` renders a
// system headless with exit code 0, and fails with 1 and a message. The canvas gets most of the
// editor's width and the side tabs show whole titles; the main window's Edit menu offers the
// canvas's selection edits (Group as Composite, Decompose, …). The Plan button opens the Plan
// view below the canvas.
#include "documentloader.h"
#include "mainwindow.h"
#include "planview.h"
#include "propertiespanel.h"
#include "repositoryview.h"
#include "rtcrepository.h"
#include "rtsdocument.h"
#include "rtseditor.h"
#include "systemcanvas.h"
#include "systemmodel.h"
#include "systemscene.h"

#include <QAction>
#include <QFile>
#include <QMenu>
#include <QProcess>
#include <QSettings>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace Studio;

class TestSeCanvasApp : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void editorShowsCanvasOverTheDocument();
    void canvasGetsTheRoomAndTabsShowTitles();
    void planButtonShowsPlanBelowCanvas();
    void editMenuOffersCanvasActions();
    void repositoryRemembersItsSources();
    void exportFromCommandLine_data();
    void exportFromCommandLine();
    void helpAndVersionWithoutDisplay_data();
    void helpAndVersionWithoutDisplay();
    void exportFailuresExitWithOne_data();
    void exportFailuresExitWithOne();

private:
    QTemporaryDir m_settingsDir;
};

void TestSeCanvasApp::initTestCase()
{
    // Keep the user's settings out of the test.
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioCanvasTest"));
    QSettings().clear();
}

void TestSeCanvasApp::editorShowsCanvasOverTheDocument()
{
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> loaded
        = loadDocument(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/secanvas/system.xml"), &diagnostics);
    auto *document = qobject_cast<RtsDocument *>(loaded.get());
    QVERIFY(document);
    RtsEditor editor(document);
    editor.resize(1300, 700);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    SystemEditor::SystemScene *scene = editor.canvas()->scene();
    QCOMPARE(scene->model(), document->model());
    QCOMPARE(scene->undoStack(), document->undoStack());
    QCOMPARE(scene->componentItemCount(), 3);
    // The document's RTC profiles (resolved from pathUri) give the ports their kinds.
    QCOMPARE(document->model()->port(QStringLiteral("Filter0"), QStringLiteral("Filter0.in"))->kind,
             SystemEditor::PortKind::DataIn);
    // Selecting shows the properties; edits land on the document's undo stack.
    scene->selectComponents({QStringLiteral("Filter0")});
    QCOMPARE(editor.propertiesPanel()->shownComponent(), QStringLiteral("Filter0"));
    QVERIFY(!document->isModified());
    scene->deleteSelection();
    QCOMPARE(document->undoStack()->count(), 1);
    QVERIFY(document->isModified());
    QVERIFY(editor.propertiesPanel()->shownComponent().isEmpty());
    document->undoStack()->undo();
    QVERIFY(!document->isModified());
    QCOMPARE(scene->componentItemCount(), 3);
    QCOMPARE(editor.repositoryView()->repository(), RtsEditor::sharedRepository());
}

void TestSeCanvasApp::canvasGetsTheRoomAndTabsShowTitles()
{
    RtsDocument document(Profile::RtsProfile::createNew(QStringLiteral("V"), QStringLiteral("S"),
                                                        QStringLiteral("1")));
    RtsEditor editor(&document);
    editor.resize(1400, 800);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    // The repository/outline and properties/system tabs share one column beside the canvas.
    QVERIFY2(editor.canvas()->width() > editor.width() * 3 / 5,
             qPrintable(QString::number(editor.canvas()->width())));
    for (const char *name : {"systemEditorLeftTabs", "systemEditorRightTabs"}) {
        const auto *tabs = editor.findChild<QTabWidget *>(QLatin1String(name));
        QVERIFY(tabs);
        QVERIFY(tabs->mapTo(&editor, QPoint()).x() > editor.canvas()->width() / 2);
        const QTabBar *bar = tabs->tabBar();
        for (int i = 0; i < bar->count(); ++i) {
            const int needed = bar->fontMetrics().horizontalAdvance(bar->tabText(i));
            QVERIFY2(bar->tabRect(i).width() > needed, qPrintable(bar->tabText(i)));
            QVERIFY(bar->rect().contains(bar->tabRect(i)));
        }
    }
}

// The Plan view opens below the canvas, over the same system and undo stack.
void TestSeCanvasApp::planButtonShowsPlanBelowCanvas()
{
    RtsDocument document(Profile::RtsProfile::createNew(QStringLiteral("V"), QStringLiteral("S"),
                                                        QStringLiteral("1")));
    RtsEditor editor(&document);
    editor.resize(1400, 800);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QVERIFY(!editor.planView()->isVisible());
    auto *toggle = editor.findChild<QAction *>(QStringLiteral("actionShowPlan"));
    QVERIFY(toggle);
    toggle->trigger();
    QTRY_VERIFY(editor.planView()->isVisible());
    const QPoint planTop = editor.planView()->mapTo(&editor, QPoint());
    QVERIFY(planTop.y()
            > editor.canvas()->mapTo(&editor, QPoint()).y() + editor.canvas()->height() / 2);
    QVERIFY(editor.planView()->width() > editor.width() * 3 / 5);
    editor.showPlanView(false);
    QVERIFY(!editor.planView()->isVisible());
    QVERIFY(!toggle->isChecked());
}

namespace {

/// The Edit menu's actions as it shows them, by object name.
QHash<QString, QAction *> shownEditActions(QMenu *edit)
{
    edit->popup(QPoint(0, 0));
    QHash<QString, QAction *> shown;
    for (QAction *action : edit->actions()) {
        if (!action->objectName().isEmpty())
            shown.insert(action->objectName(), action);
    }
    edit->hide();
    return shown;
}

} // namespace

void TestSeCanvasApp::editMenuOffersCanvasActions()
{
    MainWindow window;
    auto *edit = window.findChild<QMenu *>(QStringLiteral("menuEdit"));
    QVERIFY(edit);
    QVERIFY(!shownEditActions(edit).contains(QStringLiteral("actionGroupComposite")));

    QVERIFY(window.openFiles({RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/secanvas/system.xml")}));
    auto *document = qobject_cast<RtsDocument *>(window.activeDocument());
    QVERIFY(document);
    auto *editor = window.findChild<RtsEditor *>();
    QVERIFY(editor);
    SystemEditor::SystemCanvas *canvas = editor->canvas();
    canvas->setCompositeEditor([](const SystemEditor::SystemModel &, const QStringList &) {
        return std::optional<SystemEditor::CompositeDialog::Choice>(
            {QStringLiteral("Grouping"), {}});
    });

    QHash<QString, QAction *> shown = shownEditActions(edit);
    QVERIFY(shown.contains(QStringLiteral("actionUndo")));
    QAction *group = shown.value(QStringLiteral("actionGroupComposite"));
    QAction *decompose = shown.value(QStringLiteral("actionDecompose"));
    QVERIFY(group && decompose && shown.contains(QStringLiteral("actionCopy")));
    QVERIFY(!group->isEnabled()); // nothing selected
    QVERIFY(!decompose->isEnabled());

    const QStringList before = document->model()->componentIds();
    canvas->scene()->selectComponents({QStringLiteral("Filter0"), QStringLiteral("Sink0")});
    QVERIFY(group->isEnabled());
    group->trigger();
    QCOMPARE(document->model()->componentIds().size(), before.size() + 1);
    QCOMPARE(document->undoStack()->count(), 1);

    // Select the new composite and dissolve it through the menu.
    QStringList composites = document->model()->componentIds();
    for (const QString &name : before)
        composites.removeOne(name);
    canvas->scene()->selectComponents(composites);
    shown = shownEditActions(edit);
    QVERIFY(shown.value(QStringLiteral("actionDecompose"))->isEnabled());
    shown.value(QStringLiteral("actionDecompose"))->trigger();
    QCOMPARE(document->model()->componentIds(), before);
    document->undoStack()->undo();
    document->undoStack()->undo();
    QCOMPARE(document->model()->componentIds(), before);
    QVERIFY(!document->isModified());
}

void TestSeCanvasApp::repositoryRemembersItsSources()
{
    SystemEditor::RtcRepository *repository = RtsEditor::sharedRepository();
    const QString folder = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/secanvas/RTCs");
    QVERIFY(repository->addSource(folder));
    {
        RtsDocument document(Profile::RtsProfile::createNew(QStringLiteral("V"),
                                                            QStringLiteral("S"),
                                                            QStringLiteral("1")));
        RtsEditor editor(&document);
    }
    const QStringList saved = QSettings().value(QStringLiteral("systemEditor/repositorySources"))
                                  .toStringList();
    QVERIFY2(saved.contains(folder) || saved.contains(QDir::cleanPath(folder)),
             qPrintable(saved.join(QLatin1Char(','))));
}

void TestSeCanvasApp::exportFromCommandLine_data()
{
    QTest::addColumn<QString>("output");
    QTest::newRow("png") << QStringLiteral("diagram.png");
    QTest::newRow("svg") << QStringLiteral("diagram.svg");
}

void TestSeCanvasApp::exportFromCommandLine()
{
    QFETCH(QString, output);
    QTemporaryDir dir;
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    // Headless: no display and no platform given.
    environment.remove(QStringLiteral("DISPLAY"));
    environment.remove(QStringLiteral("QT_QPA_PLATFORM"));
    process.setProcessEnvironment(environment);
    process.start(RTSTUDIO_PATH,
                  {QStringLiteral("--export-diagram"),
                   RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml"),
                   QStringLiteral("--output"), dir.filePath(output)});
    QVERIFY(process.waitForFinished(60000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 0);
    QFile file(dir.filePath(output));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.size() > 1000);
    if (output.endsWith(QLatin1String(".svg")))
        QVERIFY(file.readAll().contains("ConsoleOut0"));
}

// The usage and the version need no display either (ssh, scripts).
void TestSeCanvasApp::helpAndVersionWithoutDisplay_data()
{
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("expected");
    QTest::newRow("help") << QStringLiteral("--help") << QStringLiteral("--export-diagram");
    QTest::newRow("-h") << QStringLiteral("-h") << QStringLiteral("--run-locally");
    QTest::newRow("version") << QStringLiteral("--version") << QStringLiteral(RTSTUDIO_VERSION);
}

void TestSeCanvasApp::helpAndVersionWithoutDisplay()
{
    QFETCH(QString, option);
    QFETCH(QString, expected);
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("DISPLAY"));
    environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
    environment.remove(QStringLiteral("QT_QPA_PLATFORM"));
    process.setProcessEnvironment(environment);
    process.start(RTSTUDIO_PATH, {option});
    QVERIFY(process.waitForFinished(60000));
    const QString output = QString::fromUtf8(process.readAllStandardOutput());
    QVERIFY2(process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0,
             qPrintable(QString::fromUtf8(process.readAllStandardError())));
    QVERIFY2(output.contains(expected), qPrintable(output));
}

void TestSeCanvasApp::exportFailuresExitWithOne_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("missing file") << QStringList {QStringLiteral("--export-diagram"),
                                                  QStringLiteral("no-such-system.xml"),
                                                  QStringLiteral("--output"),
                                                  QStringLiteral("out.png")}
                                  << QStringLiteral("no-such-system.xml");
    QTest::newRow("no output") << QStringList {QStringLiteral("--export-diagram"),
                                               QStringLiteral("system.xml")}
                               << QStringLiteral("--output");
}

void TestSeCanvasApp::exportFailuresExitWithOne()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QProcess process;
    process.setWorkingDirectory(dir.path());
    process.start(RTSTUDIO_PATH, arguments);
    QVERIFY(process.waitForFinished(60000));
    QCOMPARE(process.exitCode(), 1);
    QVERIFY2(QString::fromUtf8(process.readAllStandardError()).contains(message),
             qPrintable(message));
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("out.png"))));
}

QTEST_MAIN(TestSeCanvasApp)
#include "tst_secanvasapp.moc"
