// SPDX-License-Identifier: MIT
// The System Editor on a large generated system (1,000 components, 1,500 connectors): opening it
// (load + model + scene + first paint of the view), peak memory, auto-layout and a repaint after
// a pan and after a zoom. Targets on a 2-core machine (RelWithDebInfo): open + first paint
// <= 1 s within 300 MB resident; auto-layout <= 2 s; pan/zoom repaint <= 16 ms.
#include "profileio.h"
#include "autolayout.h"
#include "benchsystem.h"
#include "systemcanvas.h"
#include "systemfile.h"
#include "systemmodel.h"
#include "systemview.h"

#include <QApplication>
#include <QFile>
#include <QImage>
#include <QPainter>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTextStream>
#include <QUndoCommand>
#include <QUndoStack>

#include <memory>

using namespace SystemEditor;

namespace {

constexpr int Components = 1000;
constexpr int Connectors = 1500;
constexpr int RepaintRuns = 7;

struct Row
{
    QString what;
    double value;
    QString unit;
    QString target;
    bool met;
};

/// Paints the view (its viewport, with scroll position and zoom) into an image.
void paintView(SystemView *view, QImage *image)
{
    image->fill(Qt::white);
    QPainter painter(image);
    view->render(&painter);
}

/// Everything an open system editor holds.
struct OpenSystem
{
    SystemModel model;
    QUndoStack stack;
    std::unique_ptr<SystemCanvas> canvas;
};

bool open(const QString &path, OpenSystem *system, QImage *image)
{
    Profile::Diagnostics diagnostics;
    std::optional<LoadedSystem> loaded = loadSystemFile(path, &diagnostics);
    if (!loaded)
        return false;
    system->model.setProfile(std::move(loaded->profile), loaded->rtcProfiles);
    system->canvas = std::make_unique<SystemCanvas>(&system->model, &system->stack);
    system->canvas->resize(image->size());
    system->canvas->show();
    paintView(system->canvas->view(), image);
    return true;
}

void printTable(QTextStream &out, const std::vector<Row> &rows)
{
    out << QStringLiteral("| %1 | %2 | %3 | %4 |\n")
               .arg(QStringLiteral("measure"), -28)
               .arg(QStringLiteral("value"), 10)
               .arg(QStringLiteral("target"), 10)
               .arg(QStringLiteral("met"), 3);
    out << "|------------------------------|------------|------------|-----|\n";
    for (const Row &row : rows) {
        out << QStringLiteral("| %1 | %2 | %3 | %4 |\n")
                   .arg(row.what, -28)
                   .arg(QStringLiteral("%1 %2").arg(row.value, 0, 'f', 1).arg(row.unit), 10)
                   .arg(row.target, 10)
                   .arg(row.met ? QStringLiteral("yes") : QStringLiteral("no"), 3);
    }
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QTextStream out(stdout);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("large.xml"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)
        || file.write(Bench::generateSystem(Components, Connectors)) < 0) {
        out << "cannot write the generated system\n";
        return 1;
    }
    file.close();

    QImage image(1280, 800, QImage::Format_ARGB32_Premultiplied);
    OpenSystem system;
    bool opened = false;
    const double openMs = Bench::timeMs([&] { opened = open(path, &system, &image); });
    if (!opened || system.model.componentIds().size() != Components) {
        out << "the generated system did not open\n";
        return 1;
    }
    const double rssMiB = double(Bench::peakRssKiB()) / 1024.0;
    // What RT Studio reads on a worker thread (the window shows progress and Cancel meanwhile);
    // building the diagram is the rest, on the GUI thread.
    const double readMs = Bench::timeMs([&] { Profile::loadProfileFile(path, nullptr); });
    SystemView *view = system.canvas->view();
    // The canvas fits a freshly opened diagram into the view; pan and zoom are measured at
    // 100 % in the middle of the diagram, where an editing user works.
    view->resetZoom();
    view->centerOn(view->sceneRect().center());

    QScrollBar *scroll = view->horizontalScrollBar();
    int step = 0;
    const double panMs = Bench::medianMs(
        [&] {
            scroll->setValue(scroll->value() + ((step++ % 2) ? -200 : 200));
            paintView(view, &image);
        },
        RepaintRuns);
    int zoomStep = 0;
    const double zoomMs = Bench::medianMs(
        [&] {
            const qreal factor = (zoomStep++ % 2) ? 1 / 1.25 : 1.25;
            view->scale(factor, factor);
            paintView(view, &image);
        },
        RepaintRuns);

    const double layoutMs = Bench::timeMs([&] {
        if (QUndoCommand *command = autoLayoutCommand(&system.model))
            system.stack.push(command);
    });
    const bool laidOut = system.stack.count() == 1;

    const std::vector<Row> rows {
        {QStringLiteral("open + first paint"), openMs, QStringLiteral("ms"),
         QStringLiteral("<= 1000"), openMs <= 1000},
        {QStringLiteral("reading it (worker thread)"), readMs, QStringLiteral("ms"), QStringLiteral("-"),
         true},
        {QStringLiteral("peak resident memory"), rssMiB, QStringLiteral("MiB"),
         QStringLiteral("<= 300"), rssMiB <= 300},
        {QStringLiteral("auto-layout (one undo step)"), layoutMs, QStringLiteral("ms"),
         QStringLiteral("<= 2000"), laidOut && layoutMs <= 2000},
        {QStringLiteral("repaint after pan"), panMs, QStringLiteral("ms"), QStringLiteral("<= 16"),
         panMs <= 16},
        {QStringLiteral("repaint after zoom"), zoomMs, QStringLiteral("ms"),
         QStringLiteral("<= 16"), zoomMs <= 16},
    };
    out << QStringLiteral("System Editor: %1 components, %2 connectors; view %3x%4; repaints "
                          "median of %5%6\n\n")
               .arg(Components)
               .arg(Connectors)
               .arg(image.width())
               .arg(image.height())
               .arg(RepaintRuns)
               .arg(laidOut ? QString() : QStringLiteral("; auto-layout FAILED"));
    printTable(out, rows);
    return 0;
}
