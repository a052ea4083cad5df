// SPDX-License-Identifier: MIT
// Renders the pictures the documentation shows from the running application, under any Qt
// platform (offscreen in CI), so that they show what the program shows today:
//
//   docscreenshots OUTPUT_DIR LANGUAGE
//
// writes builder-LANGUAGE.png (the tour's component in the Builder), systemeditor-LANGUAGE.png (the
// bundled ConsoleInOut system), planview-LANGUAGE.png (the planner's tutorial robot in the Plan
// view), online-LANGUAGE.png (the ConsoleInOut system running on a live rtmanager, its OutPort in
// the Port Monitor) and userguide-LANGUAGE.png (Help → User Guide). LANGUAGE is en or ja.
// Settings go to a temporary folder; the user's are not read or changed.
#include "restorer.h"
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
#include <QMainWindow>
#include <QStatusBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

namespace {

bool save(QWidget *widget, const QDir &output, const QString &name, const QString &language)
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

/**
 * Opens the planner's tutorial system (tests/data/planner/robot.xml) with its Plan view planned
 * on the tutorial's two nodes from a facts file.
 */
bool showPlanView(Studio::MainWindow &window)
{
    const QDir data(QStringLiteral(RTSTUDIO_SOURCE_DIR "/tests/data/planner"));
    // Lanes below the diagram want the room of a larger window.
    window.resize(1400, 900);
    if (!window.openFiles({data.filePath(QStringLiteral("robot.xml"))}))
        return false;
    Studio::RtsEditor *editor = nullptr;
    for (Studio::RtsEditor *candidate : window.findChildren<Studio::RtsEditor *>()) {
        if (candidate->document()->filePath().endsWith(QLatin1String("robot.xml")))
            editor = candidate;
    }
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
 * Starts a name server and an rtmanager on free loopback ports, restores the bundled ConsoleInOut
 * system there, opens it online, starts it and watches ConsoleIn0's OutPort in the Port Monitor.
 */
bool showOnline(Studio::MainWindow &window, LiveTest::LiveSystem &live, const QString &systemFile)
{
    QString error;
    const quint16 managerPort = LiveTest::freePort();
    if (!live.startNameServer(&error)
        || !live.startHostManager(QStringLiteral(RTMANAGER_PATH), managerPort, QStringLiteral("robot"), {}, &error)) {
        std::fprintf(stderr, "docscreenshots: %s\n", qPrintable(error));
        return false;
    }
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(systemFile, &diagnostics);
    if (!loaded || !loaded->rts)
        return false;
    Deploy::TargetOptions target;
    target.nameServers = {live.namingServer()};
    target.manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(managerPort);
    target.create = true;
    const Deploy::DeployReport restored
        = Deploy::restoreSystem(*loaded->rts, Deploy::planRestore(*loaded->rts, target), target);
    if (!restored.ok) {
        std::fprintf(stderr, "docscreenshots: %s\n", qPrintable(restored.toText()));
        return false;
    }
    window.showPerspective(Studio::Perspective::Id::SystemEditor);
    SystemEditor::NameServiceView *names = window.onlineDocks()->nameService();
    QSignalSpy refreshed(names, &SystemEditor::NameServiceView::serverRefreshed);
    if (!names->addServer(live.namingServer()) || !refreshed.wait(15000) || !window.openFiles({systemFile}))
        return false;
    window.findChild<QAction *>(QStringLiteral("actionOpenOnline"))->trigger();
    auto *online = qobject_cast<Studio::OnlineDocument *>(window.activeDocument());
    if (!online || !online->diagram())
        return false;
    SystemEditor::OnlineDiagram *diagram = online->diagram();
    const int components = int(loaded->rts->components.size());
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

    const QDir examples(QStringLiteral(RTSTUDIO_SOURCE_DIR "/resources/examples"));
    Studio::MainWindow window;
    window.resize(1200, 760);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return 1;
    bool ok = window.openFiles({examples.filePath(QStringLiteral("tour/Doubler.xml"))})
        && save(&window, output, QStringLiteral("builder"), language)
        && window.openFiles({examples.filePath(QStringLiteral("ConsoleInOut/ConsoleInOut.xml"))})
        && save(&window, output, QStringLiteral("systemeditor"), language)
        && showPlanView(window) && save(&window, output, QStringLiteral("planview"), language);
    LiveTest::LiveSystem live;
    window.resize(1400, 900);
    ok = ok && showOnline(window, live, examples.filePath(QStringLiteral("ConsoleInOut/ConsoleInOut.xml")))
        && save(&window, output, QStringLiteral("online"), language);
    window.showUserGuide(QStringLiteral("getting-started.md"));
    Studio::UserGuide *guide = window.userGuide();
    ok = ok && guide && QTest::qWaitForWindowExposed(guide) && save(guide, output, QStringLiteral("userguide"), language);
    if (!ok)
        std::fprintf(stderr, "docscreenshots: an example did not open or a picture was not written\n");
    return ok ? 0 : 1;
}
