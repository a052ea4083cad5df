// SPDX-License-Identifier: MIT
// Renders the pictures the documentation shows from the running application, under any Qt
// platform (offscreen in CI), so that they show what the program shows today:
//
//   docscreenshots OUTPUT_DIR LANGUAGE
//
// writes, LANGUAGE being en or ja:
//   builder-LANGUAGE.png       the tour's component in the Builder
//   generate-LANGUAGE.png      its Generate options dialog
//   regenerate-LANGUAGE.png    Generate's question about a generated file the user changed
//   systemeditor-LANGUAGE.png  the bundled ConsoleInOut system
//   connector-LANGUAGE.png     the connector dialog between its two data ports
//   planview-LANGUAGE.png      the planner's tutorial robot in the Plan view
//   restore-LANGUAGE.png       the Restore dialog's dry run of ConsoleInOut on a live rtmanager
//   online-LANGUAGE.png        that system running, its OutPort in the Port Monitor
//   portmonitor-LANGUAGE.png   the Port Monitor alone
//   userguide-LANGUAGE.png     Help → User Guide
// The dialogs are opened the way a user opens them (a button, a drop on a port, a menu command);
// each is answered once it is pictured. Settings go to a temporary folder; the user's are not
// read or changed.
#include "restorer.h"
#include "connectordialog.h"
#include "connectionrules.h"
#include "generateoptionsdialog.h"
#include "modalguard.h"
#include "regenerationdialog.h"
#include "restoredialog.h"
#include "systemscene.h"
#include "systemview.h"
#include "livesystem.h"
#include "mainwindow.h"
#include "nameserviceview.h"
#include "onlinediagram.h"
#include "onlinedocks.h"
#include "onlinedocument.h"
#include "onlineicons.h"
#include "portmonitor.h"
#include "perspective.h"
#include "planview.h"
#include "profileio.h"
#include "rtsdocument.h"
#include "rtseditor.h"
#include "systemcanvas.h"
#include "systemmodel.h"
#include "uilanguage.h"
#include "userguide.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLineEdit>
#include <QLockFile>
#include <QMainWindow>
#include <QPushButton>
#include <QTableWidget>
#include <QStatusBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace {

/// Where the pictures go, named NAME-LANGUAGE.png.
struct Pictures
{
    QDir output;
    QString language;

    bool save(QWidget *widget, const QString &name) const
    {
        // "Opened /path/…" would put this machine's folders into the pictures.
        if (auto *window = qobject_cast<QMainWindow *>(widget))
            window->statusBar()->clearMessage();
        QApplication::processEvents();
        const QString path = output.filePath(QStringLiteral("%1-%2.png").arg(name, language));
        if (widget->grab().save(path))
            return true;
        std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
        return false;
    }

    /// Saves a dialog once the window system shows it, at the size it opens with.
    bool saveDialog(QWidget *dialog, const QString &name) const
    {
        return QTest::qWaitForWindowExposed(dialog) && save(dialog, name);
    }
};

/**
 * Runs @p trigger, which opens the modal dialogs @p answers answer in that order (the modal
 * guard fails the program on any other); true when each opened.
 */
bool answerModals(const std::function<void()> &trigger, const QList<GuiTest::ModalGuard::Answer> &answers)
{
    std::vector<std::unique_ptr<GuiTest::ModalGuard::Expected>> expected;
    for (const GuiTest::ModalGuard::Answer &answer : answers)
        expected.push_back(std::make_unique<GuiTest::ModalGuard::Expected>(answer));
    trigger();
    return std::all_of(expected.begin(), expected.end(), [](const auto &e) { return e->seen(); });
}

Studio::RtsEditor *editorOf(const Studio::MainWindow &window, const QString &fileName)
{
    for (Studio::RtsEditor *candidate : window.findChildren<Studio::RtsEditor *>()) {
        if (QFileInfo(candidate->document()->filePath()).fileName() == fileName)
            return candidate;
    }
    return nullptr;
}

/**
 * The Builder's Generate as the tour does it: the options dialog, the project folder typed in;
 * then, after the user wrote onExecute's code, Generate again and its question about that file.
 */
bool showGenerateDialogs(Studio::MainWindow &window, const Pictures &pictures, const QDir &project)
{
    auto *generate = window.findChild<QPushButton *>(QStringLiteral("generateButton"));
    if (!generate)
        return false;
    bool saved = true;
    const auto options = [&](bool picture) {
        return [&, picture](QWidget *dialog) {
            auto *optionsDialog = static_cast<Builder::GenerateOptionsDialog *>(dialog);
            optionsDialog->folderEdit()->setText(project.path());
            if (picture)
                saved = pictures.saveDialog(dialog, QStringLiteral("generate")) && saved;
            optionsDialog->accept();
        };
    };
    if (!answerModals([&] { generate->click(); }, {options(true)}))
        return false;
    // The user's code in onExecute, as getting-started.md's step 3 asks for.
    QFile source(project.filePath(QStringLiteral("src/Doubler.cpp")));
    if (!source.open(QIODevice::ReadWrite))
        return false;
    QByteArray text = source.readAll();
    const QByteArray execute = "::onExecute(RTC::UniqueId /*ec_id*/)\n{\n";
    const qsizetype body = text.indexOf(execute);
    if (body < 0)
        return false;
    text.insert(body + execute.size(),
                "  if (m_inIn.isNew())\n  {\n    m_inIn.read();\n    m_out.data = 2 * m_in.data;\n"
                "    m_outOut.write();\n  }\n");
    if (!source.resize(0) || source.write(text) != text.size())
        return false;
    source.close();
    const auto merge = [&](QWidget *dialog) {
        saved = pictures.saveDialog(dialog, QStringLiteral("regenerate")) && saved;
        static_cast<Builder::RegenerationDialog *>(dialog)->button(Codegen::FileDecision::Merge)->click();
    };
    return answerModals([&] { generate->click(); }, {options(false), merge}) && saved;
}

/**
 * showGenerateDialogs() into a fixed folder, not a random one: the Generate dialog shows it, and
 * its picture should not change with every run. Runs at the same time (both languages, other
 * checkouts) take turns through a lock file.
 */
bool generateInFixedFolder(Studio::MainWindow &window, const Pictures &pictures)
{
    QLockFile lock(QDir::temp().filePath(QStringLiteral("rtstudio-docs.lock")));
    if (!lock.tryLock(120000))
        return false;
    QDir project(QDir::temp().filePath(QStringLiteral("rtstudio-docs/Doubler")));
    project.removeRecursively();
    const bool shown = showGenerateDialogs(window, pictures, project);
    project.removeRecursively();
    return shown;
}

/// The connector dialog as a drop of ConsoleIn0's OutPort on ConsoleOut0's InPort opens it.
bool showConnectorDialog(const Studio::MainWindow &window, const Pictures &pictures)
{
    Studio::RtsEditor *editor = editorOf(window, QStringLiteral("ConsoleInOut.xml"));
    if (!editor)
        return false;
    SystemEditor::SystemScene *scene = editor->canvas()->scene();
    const SystemEditor::ConnectionCheck check = SystemEditor::ConnectionRules::check(
        *scene->model(), {QStringLiteral("ConsoleIn0"), QStringLiteral("ConsoleIn0.out")},
        {QStringLiteral("ConsoleOut0"), QStringLiteral("ConsoleOut0.in")});
    if (!check)
        return false;
    bool saved = false;
    const auto cancel = [&](QWidget *dialog) {
        saved = pictures.saveDialog(dialog, QStringLiteral("connector"));
        static_cast<QDialog *>(dialog)->reject();
    };
    return answerModals([&] { emit scene->connectRequested(check); }, {cancel}) && saved;
}

/**
 * Opens the planner's tutorial system (tests/data/planner/robot.xml) with its Plan view planned
 * on the tutorial's two nodes from a facts file.
 */
bool showPlanView(Studio::MainWindow &window)
{
    const QDir data(RTSTUDIO_SOURCE_DIR + QStringLiteral("/tests/data/planner"));
    // Lanes below the diagram want the room of a larger window.
    window.resize(1400, 900);
    if (!window.openFiles({data.filePath(QStringLiteral("robot.xml"))}))
        return false;
    Studio::RtsEditor *editor = editorOf(window, QStringLiteral("robot.xml"));
    Profile::Diagnostics diagnostics;
    const auto viewer = Profile::loadProfileFile(
        data.filePath(QStringLiteral("profiles/Viewer.xml")), &diagnostics);
    if (!editor || !viewer || !viewer->rtc)
        return false;
    // The tutorial finds the viewer's RTC profile with --profiles; here the model is told.
    editor->document()->model()->setRtcProfile(QStringLiteral("Viewer0"), *viewer->rtc);
    // The file has no layout: laid out, the diagram above the plan shows the same system.
    editor->canvas()->action(QStringLiteral("actionAutoLayout"))->trigger();
    editor->showPlanView(true);
    QApplication::processEvents();
    editor->canvas()->action(QStringLiteral("actionZoomFit"))->trigger();
    SystemEditor::PlanView *plan = editor->planView();
    QSignalSpy planned(plan, &SystemEditor::PlanView::planChanged);
    return plan->openFactsFile(data.filePath(QStringLiteral("robot-nodes.yaml")))
        && planned.wait(30000) && plan->plan().feasible;
}

/**
 * Online → Restore System on Live Managers… on @p systemFile, creating its components through
 * @p manager: the dialog's dry run is pictured, then Restore.
 */
bool restoreThroughDialog(Studio::MainWindow &window, const Pictures &pictures, const QString &systemFile,
                          const QString &manager)
{
    if (!window.openFiles({systemFile}))
        return false;
    window.findChild<QAction *>(QStringLiteral("actionRestoreSystem"))->trigger();
    auto *dialog = window.findChild<SystemEditor::RestoreDialog *>(QStringLiteral("restoreDialog"));
    if (!dialog)
        return false;
    dialog->setManagers({manager});
    dialog->setCreateMissing(true, manager);
    auto *restore = dialog->findChild<QPushButton *>(QStringLiteral("restoreButton"));
    // The dialog plans as it opens and again for the manager: the second plan creates.
    const auto creates = [&] {
        const QList<Deploy::ComponentMapping> &mapped = dialog->currentPlan().components;
        return restore->isEnabled() && !mapped.isEmpty()
            && std::all_of(mapped.begin(), mapped.end(),
                           [](const auto &m) { return m.kind == Deploy::MappingKind::Create; });
    };
    if (!QTest::qWaitFor(creates, 20000))
        return false;
    dialog->findChild<QPushButton *>(QStringLiteral("dryRunButton"))->click();
    if (!pictures.saveDialog(dialog, QStringLiteral("restore")))
        return false;
    QSignalSpy restored(dialog, &SystemEditor::RestoreDialog::restored);
    QSignalSpy listed(window.onlineDocks()->nameService(), &SystemEditor::NameServiceView::serverRefreshed);
    restore->click();
    if (!restored.wait(30000) || !restored.at(0).at(0).toBool()) {
        std::fprintf(stderr, "docscreenshots: %s\n", qPrintable(dialog->report().toText()));
        return false;
    }
    dialog->close();
    // The Name Service view lists what the restore created.
    return listed.wait(15000);
}

QDockWidget *dockOf(const Studio::MainWindow &window, const QWidget *view)
{
    for (QDockWidget *dock : window.onlineDocks()->docks()) {
        if (dock->widget() == view)
            return dock;
    }
    return nullptr;
}

/// The Port Monitor's dock alone, for its own section, taller than beside the diagram.
bool savePortMonitor(Studio::MainWindow &window, const Pictures &pictures)
{
    QDockWidget *const dock = dockOf(window, window.onlineDocks()->portMonitor());
    if (!dock)
        return false;
    // The diagram above keeps its minimum height: the window grows for the taller dock.
    window.resize(window.width(), window.height() + 160);
    QApplication::processEvents();
    window.resizeDocks({dock}, {340}, Qt::Vertical);
    return QTest::qWaitFor([&] { return dock->height() >= 300; }, 5000)
        && pictures.save(dock, QStringLiteral("portmonitor"));
}

/**
 * Starts a name server and an rtmanager on free loopback ports, restores the bundled ConsoleInOut
 * system there, opens it online, starts it and watches ConsoleIn0's OutPort in the Port Monitor.
 */
bool showOnline(Studio::MainWindow &window, const Pictures &pictures, LiveTest::LiveSystem &live,
                const QString &systemFile)
{
    QString error;
    const quint16 managerPort = LiveTest::freePort();
    if (!live.startNameServer(&error)
        || !live.startHostManager(RTMANAGER_PATH, managerPort, QStringLiteral("robot"), {}, &error)) {
        std::fprintf(stderr, "docscreenshots: %s\n", qPrintable(error));
        return false;
    }
    window.showPerspective(Studio::Perspective::Id::SystemEditor);
    SystemEditor::NameServiceView *names = window.onlineDocks()->nameService();
    // Wide enough for the components below the manager with their states, in either language.
    if (QDockWidget *dock = dockOf(window, names))
        window.resizeDocks({dock}, {340}, Qt::Horizontal);
    QSignalSpy refreshed(names, &SystemEditor::NameServiceView::serverRefreshed);
    if (!names->addServer(live.namingServer()) || !refreshed.wait(15000)
        || !restoreThroughDialog(window, pictures, systemFile,
                                 QStringLiteral("corbaloc::127.0.0.1:%1").arg(managerPort)))
        return false;
    window.findChild<QAction *>(QStringLiteral("actionOpenOnline"))->trigger();
    auto *online = qobject_cast<Studio::OnlineDocument *>(window.activeDocument());
    if (!online || !online->diagram())
        return false;
    SystemEditor::OnlineDiagram *diagram = online->diagram();
    const Studio::RtsEditor *system = editorOf(window, QFileInfo(systemFile).fileName());
    if (!system)
        return false;
    const int components = int(system->document()->model()->componentIds().size());
    if (!QTest::qWaitFor([&] { return diagram->model()->componentIds().size() == components; }, 15000))
        return false;
    diagram->findChild<QAction *>(QStringLiteral("actionStartAll"))->trigger();
    const QColor active = SystemEditor::OnlineIcons::stateColor(Corba::LifeCycleState::Active);
    if (!QTest::qWaitFor([&] { return diagram->bodyColor(QStringLiteral("ConsoleOut0")) == active; }, 15000))
        return false;
    diagram->monitorPort(QStringLiteral("ConsoleIn0"), QStringLiteral("out"));
    SystemEditor::PortMonitor *monitor = window.onlineDocks()->portMonitor();
    // A plot of about two seconds of samples (ConsoleIn sends a thousand a second), by when the
    // Name Service view has polled the new states too.
    return QTest::qWaitFor(
        [&] {
            const QStringList watched = monitor->watched();
            return !watched.isEmpty() && monitor->received(watched.first()) >= 1500;
        },
        30000);
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    const QStringList arguments = app.arguments();
    if (arguments.size() != 3 || (arguments.at(2) != QLatin1String("en") && arguments.at(2) != QLatin1String("ja"))) {
        std::fprintf(stderr, "usage: docscreenshots OUTPUT_DIR en|ja\n");
        return 2;
    }
    const QDir output(arguments.at(1));
    const QString language = arguments.at(2);
    if (!QDir().mkpath(output.path())) {
        std::fprintf(stderr, "cannot create %s\n", qPrintable(output.path()));
        return 1;
    }
    QTemporaryDir settings;
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());
    QString error;
    if (!Studio::UiLanguage::install(&app, language, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    // As View → Language sets it: the user guide follows the choice too.
    Studio::UiLanguage::choose(language);

    const Pictures pictures{output, language};
    const QDir examples(RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples"));
    const QString system = examples.filePath(QStringLiteral("ConsoleInOut/ConsoleInOut.xml"));
    Studio::MainWindow window;
    window.resize(1200, 760);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return 1;
    bool ok = window.openFiles({examples.filePath(QStringLiteral("tour/Doubler.xml"))})
        && pictures.save(&window, QStringLiteral("builder")) && generateInFixedFolder(window, pictures)
        && window.openFiles({system}) && pictures.save(&window, QStringLiteral("systemeditor"))
        && showConnectorDialog(window, pictures) && showPlanView(window)
        && pictures.save(&window, QStringLiteral("planview"));
    LiveTest::LiveSystem live;
    window.resize(1400, 900);
    ok = ok && showOnline(window, pictures, live, system) && pictures.save(&window, QStringLiteral("online"))
        && savePortMonitor(window, pictures);
    window.showUserGuide(QStringLiteral("getting-started.md"));
    Studio::UserGuide *guide = window.userGuide();
    ok = ok && guide && QTest::qWaitForWindowExposed(guide) && pictures.save(guide, QStringLiteral("userguide"));
    if (!ok)
        std::fprintf(stderr, "docscreenshots: an example did not open or a picture was not written\n");
    return ok ? 0 : 1;
}
