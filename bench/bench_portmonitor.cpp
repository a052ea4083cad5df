// SPDX-License-Identifier: MIT
// bench_portmonitor: the Port Monitor watching the ten OutPorts of a real rtmanager's SeqOut
// written at 1 kHz, shown on screen (offscreen platform) for BENCH_PORTMONITOR_SECONDS (default
// 10) s: samples a second that reach the view per port, the longest stall of the GUI thread's
// event loop (target < 50 ms) and this process's CPU (all threads). Prints a table; timing never
// fails the build.
#include "componentproxy.h"
#include "cputime.h"
#include "livesystem.h"
#include "namingbrowser.h"
#include "portmonitor.h"
#include "rtpath.h"
#include "stallmeter.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTextStream>
#include <QTimer>

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QTextStream out(stdout);
    const int seconds = qEnvironmentVariableIntValue("BENCH_PORTMONITOR_SECONDS") > 0
        ? qEnvironmentVariableIntValue("BENCH_PORTMONITOR_SECONDS")
        : 10;

    LiveTest::LiveSystem live;
    QString error;
    if (!live.startNameServer(&error)
        || !live.startHostManager(QStringLiteral(RTMANAGER_PATH), LiveTest::freePort(), QStringLiteral("bench"),
                                  {"manager.components.precreate=SeqOut?exec_cxt.periodic.rate=1000"}, &error)) {
        out << "bench_portmonitor: " << error << Qt::endl;
        return 1;
    }
    const auto path = Corba::RtPath::parse(QStringLiteral("/%1/bench.host_cxt/SeqOut0.rtc").arg(live.namingServer()));
    const Corba::ComponentProxy seqOut(Corba::NamingBrowser::resolve(*path), path->toString());
    seqOut.activate(0);

    SystemEditor::PortMonitor monitor;
    monitor.resize(1200, 400);
    monitor.show();
    QStringList keys;
    for (const Corba::PortInfo &port : seqOut.ports()) {
        if (port.isDataOut()) {
            monitor.watch(seqOut.path(), port);
            keys.append(seqOut.path() + QLatin1Char(':') + port.shortName());
        }
    }
    // Warm-up: every connector made and samples flowing.
    QElapsedTimer warmUp;
    warmUp.start();
    while (warmUp.elapsed() < 5000
           && std::any_of(keys.cbegin(), keys.cend(), [&](const QString &k) { return monitor.received(k) == 0; }))
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);

    QHash<QString, quint64> before;
    for (const QString &key : keys)
        before.insert(key, monitor.received(key));
    const LiveTest::StallMeter stalls;
    const double cpuBefore = processCpuSeconds();
    QElapsedTimer wall;
    wall.start();
    QEventLoop loop;
    // The plot follows each port in turn, as a user clicking through them.
    int shown = 0;
    QTimer cycle;
    QObject::connect(&cycle, &QTimer::timeout, [&] { monitor.setCurrent(keys.value(++shown % keys.size())); });
    cycle.start(1000);
    QTimer::singleShot(seconds * 1000, &loop, &QEventLoop::quit);
    loop.exec();
    const double elapsed = wall.elapsed() / 1000.0;
    const double cpu = processCpuSeconds() - cpuBefore;

    out << "Port Monitor: SeqOut's " << keys.size() << " OutPorts written at 1 kHz, " << seconds
        << " s, plot and table of one port at a time\n\n";
    out << QStringLiteral("| %1 | %2 |\n").arg("port", -40).arg("samples/s", 10);
    out << "|" << QString(42, '-') << "|" << QString(12, '-') << "|\n";
    double total = 0;
    for (const QString &key : keys) {
        const double rate = double(monitor.received(key) - before.value(key)) / elapsed;
        total += rate;
        out << QStringLiteral("| %1 | %2 |\n").arg(key.section('/', -1), -40).arg(rate, 10, 'f', 0);
    }
    out << "\nsamples/s in all " << QString::number(total, 'f', 0) << ", longest GUI stall "
        << stalls.worstMs() << " ms (target < 50), CPU " << QString::number(100.0 * cpu / elapsed, 'f', 1)
        << " % of one core\n";
    return 0;
}
