// SPDX-License-Identifier: MIT
// bench_poll: CPU used by the online pollers while they watch live components of one real
// rtmanager (BENCH_POLL_COMPONENTS, default 1,000, created through the manager) at the default
// 1 Hz: the Name Service view's state poll and the Online Diagram's state + connector poll, each
// for BENCH_POLL_SECONDS (default 10) s of wall time. CPU is this process's user + system time
// (getrusage), all threads: GUI, workers and the ORB; the GUI thread's longest stall is measured
// meanwhile. Prints a table against the targets of < 5 % of one core over the idle process (the
// same live system and stall meter with no poller) and no stall over 50 ms;
// timing never fails the build.
#include "cputime.h"
#include "livesystem.h"
#include "stallmeter.h"
#include "managerproxy.h"
#include "nameserviceview.h"
#include "namingbrowser.h"
#include "onlinediagram.h"
#include "onlinesession.h"
#include "orb.h"
#include "systemmodel.h"

#include <QApplication>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSettings>
#include <QStandardPaths>
#include <QTextStream>
#include <QTimer>


#include <cstdlib>

using namespace SystemEditor;

namespace {

constexpr int pollIntervalMs = 1000;
constexpr double targetPercent = 5.0;
constexpr qint64 targetStallMs = 50;

int componentCount()
{
    const int count = qEnvironmentVariableIntValue("BENCH_POLL_COMPONENTS");
    return count > 0 ? count : 1000;
}
const QString hostContext = QStringLiteral("pollhost.host_cxt");

int durationSeconds()
{
    const int seconds = qEnvironmentVariableIntValue("BENCH_POLL_SECONDS");
    return seconds > 0 ? seconds : 10;
}


struct Sample
{
    QString poller;
    int rounds = -1; ///< poll rounds finished while measuring; -1 when nothing polls
    double wallSeconds = 0;
    double cpu = 0;
    qint64 worstStallMs = 0;
    double percent() const { return wallSeconds > 0 ? 100.0 * cpu / wallSeconds : 0; }
};

// Runs the event loop for `seconds` and measures what the process spent meanwhile.
Sample measure(const QString &poller, int seconds, const std::function<void(int *)> &countRounds)
{
    Sample sample;
    sample.poller = poller;
    int rounds = 0;
    if (countRounds)
        countRounds(&rounds);
    QEventLoop loop;
    QTimer::singleShot(seconds * 1000, Qt::PreciseTimer, &loop, &QEventLoop::quit);
    QElapsedTimer wall;
    const double cpuBefore = processCpuSeconds();
    wall.start();
    const LiveTest::StallMeter stalls;
    loop.exec();
    sample.worstStallMs = stalls.worstMs();
    sample.cpu = processCpuSeconds() - cpuBefore;
    sample.wallSeconds = wall.elapsed() / 1000.0;
    sample.rounds = countRounds ? rounds : -1;
    return sample;
}

// Runs the event loop until `done` holds or `timeoutMs` passes, checking every 20 ms (sleeping in
// between, so the wait itself does not load the process).
bool waitFor(const std::function<bool()> &done, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    QEventLoop loop;
    QTimer check;
    QObject::connect(&check, &QTimer::timeout, &loop, [&] {
        if (done() || deadline.hasExpired())
            loop.quit();
    });
    check.start(20);
    if (!done())
        loop.exec();
    return done();
}

bool startSystem(LiveTest::LiveSystem &live, QString *error)
{
    if (!live.startNameServer(error))
        return false;
    const quint16 port = LiveTest::freePort();
    // A slow execution-context rate keeps the manager's EC threads from loading the machine;
    // the pollers ask states and ports, which do not depend on it.
    const QStringList arguments {"-d",
                                 "-o",
                                 QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(port),
                                 "-o",
                                 "corba.nameservers=" + live.namingServer(),
                                 "-o",
                                 "naming.formats=" + hostContext + "/%n.rtc",
                                 "-o",
                                 "manager.naming_formats=" + hostContext + "/%n.mgr",
                                 "-o",
                                 "exec_cxt.periodic.rate=1"};
    if (!live.startProcess(QStringLiteral(RTMANAGER_PATH), arguments, "rtmanager ready", error))
        return false;
    const auto managerPath
        = Corba::RtPath::parse(QStringLiteral("corbaloc::127.0.0.1:%1").arg(port));
    const Corba::ManagerProxy manager(Corba::NamingBrowser::resolve(*managerPath), "manager");
    for (int i = 0; i < componentCount(); ++i)
        manager.createComponent(
            QStringLiteral("%1?instance_name=Poll%2")
                .arg(i % 2 ? QStringLiteral("ConsoleOut") : QStringLiteral("ConsoleIn"))
                .arg(i));
    return true;
}

Sample benchNameService(OnlineSession &session, const QString &server, int seconds)
{
    NameServiceView view(&session, nullptr);
    view.resize(400, 800);
    view.show();
    int polls = 0;
    QObject::connect(&view, &NameServiceView::statesPolled, [&polls] { ++polls; });
    view.addServer(server);
    if (!waitFor([&] { return polls > 0; }, 60000))
        qFatal("bench_poll: the Name Service view never polled");
    return measure(QStringLiteral("Name Service view"), seconds, [&view](int *rounds) {
        QObject::connect(&view, &NameServiceView::statesPolled, [rounds] { ++*rounds; });
    });
}

Sample benchDiagram(OnlineSession &session, const QString &server, int seconds)
{
    OnlineDiagram diagram(&session);
    diagram.resize(1200, 800);
    diagram.show();
    const auto context
        = Corba::RtPath::parse(QLatin1Char('/') + server + QLatin1Char('/') + hostContext);
    int added = 0;
    for (const Corba::NamingNode &node : Corba::NamingBrowser::list(*context)) {
        if (node.type != Corba::NodeType::Component)
            continue;
        diagram.addComponent(node.path, node.ior,
                             QPointF(180.0 * (added % 40), 140.0 * (added / 40)));
        ++added;
    }
    int polls = 0;
    QObject::connect(&diagram, &OnlineDiagram::polled, [&polls] { ++polls; });
    if (!waitFor([&] { return diagram.model()->profile().components.size() == added && polls > 1; },
                 60000))
        qFatal("bench_poll: the Online Diagram never finished reading its %d components", added);
    return measure(QStringLiteral("Online Diagram"), seconds, [&diagram](int *rounds) {
        QObject::connect(&diagram, &OnlineDiagram::polled, [rounds] { ++*rounds; });
    });
}

void printTable(const QList<Sample> &samples, int seconds)
{
    QTextStream out(stdout);
    out << QStringLiteral(
               "bench_poll: %1 live components on one rtmanager, poll interval %2 ms, %3 s each\n")
               .arg(componentCount())
               .arg(pollIntervalMs)
               .arg(seconds);
    // The idle row is what the process costs with nothing polling: the stall meter's hundred
    // wake-ups a second and the ORB's own threads. What a poller adds to it is its cost.
    double idlePercent = 0;
    for (const Sample &s : samples) {
        if (s.rounds < 0)
            idlePercent = s.percent();
    }
    out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10\n")
               .arg("poller", -20)
               .arg("components", 10)
               .arg("interval", 9)
               .arg("duration", 9)
               .arg("rounds", 7)
               .arg("CPU s", 8)
               .arg("CPU %", 7)
               .arg("over idle", 9)
               .arg("stall ms", 8)
               .arg("targets", 14);
    for (const Sample &s : samples) {
        const bool polls = s.rounds >= 0;
        const double added = s.percent() - idlePercent;
        const bool met = added < targetPercent && s.worstStallMs <= targetStallMs;
        out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10\n")
                   .arg(s.poller, -20)
                   .arg(componentCount(), 10)
                   .arg(polls ? QStringLiteral("%1 ms").arg(pollIntervalMs) : QStringLiteral("-"),
                        9)
                   .arg(QStringLiteral("%1 s").arg(s.wallSeconds, 0, 'f', 1), 9)
                   .arg(polls ? QString::number(s.rounds) : QStringLiteral("-"), 7)
                   .arg(s.cpu, 8, 'f', 3)
                   .arg(QStringLiteral("%1 %").arg(s.percent(), 0, 'f', 2), 7)
                   .arg(polls ? QStringLiteral("%1 %").arg(added, 0, 'f', 2) : QStringLiteral("-"), 9)
                   .arg(s.worstStallMs, 8)
                   .arg(!polls ? QStringLiteral("-")
                         : met ? QStringLiteral("< 5 %, ≤ 50 ms")
                               : QStringLiteral("MISSED"),
                        14);
    }
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    // The pollers read their interval from QSettings: keep the user's settings out of it.
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("RTStudioBench"));
    QSettings().setValue(QStringLiteral("online/pollInterval"), pollIntervalMs);
    Corba::Orb::setCallTimeout(5000);

    LiveTest::LiveSystem live;
    QString error;
    if (!startSystem(live, &error)) {
        QTextStream(stderr) << "bench_poll: " << error << '\n';
        return 1;
    }
    const int seconds = durationSeconds();
    QList<Sample> samples;
    samples.append(measure(QStringLiteral("idle (no poller)"), seconds, {}));
    {
        OnlineSession session;
        samples.append(benchNameService(session, live.namingServer(), seconds));
    }
    {
        OnlineSession session;
        samples.append(benchDiagram(session, live.namingServer(), seconds));
    }
    printTable(samples, seconds);
    return 0;
}
