// SPDX-License-Identifier: MIT
// The application gives every component editor its Generate: the editor a component document
// opens in owns a GenerateController over the document's model, and what Generate ends with is
// listed in the main window's Problems panel (refusals with the element, written files with
// their paths) with a status message instead of a summary box.
#include "basicpage.h"
#include "componenteditor.h"
#include "document.h"
#include "editorfactory.h"
#include "generatecontroller.h"
#include "generateoptionsdialog.h"
#include "mainwindow.h"
#include "modalguard.h"
#include "perspective.h"
#include "problemspanel.h"
#include "rtcdocument.h"
#include "rtsdocument.h"

#include <QApplication>
#include <QDockWidget>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

class TestBuilderGenerateApp : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void componentEditorsCanGenerate();
    void refusedGenerateListsProblems();
    void generatedFilesAreListed();

private:
    Builder::ComponentEditor *openCounter(Studio::MainWindow *window);

    QTemporaryDir m_settingsDir;
};

void TestBuilderGenerateApp::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_buildergenerateapp"));
}

void TestBuilderGenerateApp::componentEditorsCanGenerate()
{
    Studio::RtcDocument document(Profile::RtcProfile::createDefault());
    std::unique_ptr<QWidget> widget(Studio::createEditor(&document));
    auto *editor = qobject_cast<Builder::ComponentEditor *>(widget.get());
    QVERIFY(editor);
    const QList<Builder::GenerateController *> controllers
        = editor->findChildren<Builder::GenerateController *>();
    QCOMPARE(controllers.size(), 1);
    QVERIFY(!editor->reportsGeneration()); // alone, Generate shows its summary box
    // Deleting the editor takes its controller along (no dangling prompts).
    QPointer<Builder::GenerateController> controller(controllers.at(0));
    widget.reset();
    QVERIFY(controller.isNull());
}

Builder::ComponentEditor *TestBuilderGenerateApp::openCounter(Studio::MainWindow *window)
{
    if (!window->openFiles({RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/buildergenerate/Counter.xml")}))
        return nullptr;
    Studio::Perspective *builder = window->perspective(Studio::Perspective::Id::Builder);
    return qobject_cast<Builder::ComponentEditor *>(builder->editor(window->activeDocument()));
}

void TestBuilderGenerateApp::refusedGenerateListsProblems()
{
    Studio::MainWindow window;
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Builder::ComponentEditor *editor = openCounter(&window);
    QVERIFY(editor);
    QVERIFY(editor->reportsGeneration());
    auto port = std::get<Profile::RtcDataPort>(editor->model()->item(Builder::Part::DataPort, 0));
    port.name = QStringLiteral("my port");
    editor->model()->setItem(Builder::Part::DataPort, 0, port);

    Studio::ProblemsPanel *panel = window.problemsPanel();
    QVERIFY(window.problemsDock()->isHidden());
    QTest::mouseClick(editor->basicPage()->generateButton(), Qt::LeftButton);
    QVERIFY(window.problemsDock()->isVisible());
    QVERIFY(panel->count() >= 1);
    QVERIFY2(panel->summary().startsWith(QStringLiteral("Generate refused")),
             qPrintable(panel->summary()));
    bool named = false;
    for (int row = 0; row < panel->count(); ++row)
        named = named || panel->location(row).contains(QStringLiteral("my port"));
    QVERIFY(named);
    QCOMPARE(window.statusBar()->currentMessage(), panel->summary());
}

void TestBuilderGenerateApp::generatedFilesAreListed()
{
    Studio::MainWindow window;
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Builder::ComponentEditor *editor = openCounter(&window);
    QVERIFY(editor);
    QTemporaryDir out;
    QVERIFY(out.isValid());
    // The output folder is asked in a modal dialog: answer it once it is up.
    bool answered = false;
    const GuiTest::ModalGuard::Expected expected([&](QWidget *modal) {
        auto *dialog = qobject_cast<Builder::GenerateOptionsDialog *>(modal);
        QVERIFY(dialog);
        dialog->folderEdit()->setText(out.path());
        dialog->accept();
        answered = true;
    });
    QTest::mouseClick(editor->basicPage()->generateButton(), Qt::LeftButton);
    QVERIFY(answered);
    // No summary box is left open: the result is in the panel and the status bar.
    QVERIFY(!QApplication::activeModalWidget());
    Studio::ProblemsPanel *panel = window.problemsPanel();
    QVERIFY2(panel->summary().startsWith(QStringLiteral("Generated into")),
             qPrintable(panel->summary()));
    QCOMPARE(window.statusBar()->currentMessage(), panel->summary());
    QVERIFY(panel->count() > 3);
    QStringList rows;
    for (int row = 0; row < panel->count(); ++row)
        rows << panel->text(row);
    QVERIFY2(rows.join('\n').contains(out.filePath(QStringLiteral("Counter.py"))),
             qPrintable(rows.join('\n')));
    QVERIFY(rows.join('\n').contains(QStringLiteral("created")));
    QVERIFY(window.problemsDock()->isHidden()); // success does not push the panel up

    // A row naming a profile opens it as a document.
    int rtcXml = -1;
    for (int row = 0; row < panel->count(); ++row) {
        if (panel->text(row).contains(QStringLiteral("RTC.xml")))
            rtcXml = row;
    }
    QVERIFY(rtcXml >= 0);
    QSignalSpy requested(panel, &Studio::ProblemsPanel::profileRequested);
    panel->activate(rtcXml);
    QCOMPARE(requested.count(), 1);
    QCOMPARE(requested.at(0).at(0).toString(), out.filePath(QStringLiteral("RTC.xml")));
    QCOMPARE(window.activeDocument()->filePath(), out.filePath(QStringLiteral("RTC.xml")));
}

QTEST_MAIN(TestBuilderGenerateApp)
#include "tst_buildergenerateapp.moc"
