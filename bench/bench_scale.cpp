// SPDX-License-Identifier: MIT
// bench_scale: deployment at scale, against real omniNames and rtmanager processes it starts itself.
//
// 1. Creation (the deployment paper's Table 3), measured as a user does it: one `rtctl mgr` call
//    creating 10 and then 100 ConsoleIn components, naming on, in the master's own process and
//    each in a new slave process (`manager_name=manager_%p`). Per component = the call's time / N,
//    the middle of eleven calls, each in a fresh master (rtcd2: one call).
// 2. A large system: 1,000 components (ConsoleIn sources, ConsoleOut sinks) and 1,500 connectors
//    over 10 slave managers (one per host context, started by the master through
//    manager_address), registered in two name servers: restore (create + connect) + start, stop,
//    teardown, cryo and drift against the file, then the managers' memory per hosted component.
//
//    When an OpenRTM-aist 2.x prefix is known (OPENRTM_ROOT, else the one the build was configured
//    with for the interop tests), the same requests go to its rtcd2 master in the same run, as it
//    comes (modules found by searching the load path) and tuned (the module preloaded), with the
//    ratio printed; rtcd2 hosts nothing itself, so "same process" is one named slave there.
//
//    bench_scale [--components N] [--managers M]
//
// Prints a table per part and ends with one summary line. Timing never fails the build.
#include "benchlivesystem.h"
#include "cryo.h"
#include "drift.h"
#include "livesystem.h"
#include "orb.h"
#include "restorer.h"
#include "rtctlrunner.h"
#include "rtsprofile.h"
#include "sequencerunner.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTextStream>
#include <QThread>

#include <algorithm>
#include <functional>

using namespace Deploy;

namespace {

constexpr int FanOut = 3; // connectors per source: 1,000 components give 1,500 connectors

struct Options
{
    int components = 1000;
    int managers = 10;
};

Options parseOptions(const QStringList &arguments)
{
    Options options;
    for (qsizetype i = 1; i + 1 < arguments.size(); ++i) {
        if (arguments.at(i) == QLatin1String("--components"))
            options.components = qMax(2, arguments.at(i + 1).toInt() / 2 * 2);
        else if (arguments.at(i) == QLatin1String("--managers"))
            options.managers = qMax(1, arguments.at(i + 1).toInt());
    }
    return options;
}

QString hostName(int index)
{
    return QStringLiteral("scale%1").arg(index);
}

/// The master's command line: naming on (`server`s), components under `<host>.host_cxt`.
QStringList masterArguments(quint16 port, const QStringList &servers)
{
    return {"-d",
            "-o", QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(port),
            "-o", QStringLiteral("corba.nameservers=%1").arg(servers.join(QLatin1Char(','))),
            "-o", "naming.formats=%h.host_cxt/%n.rtc",
            "-o", "manager.naming_formats=%h.host_cxt/%n.mgr",
            "-o", "logger.log_level=ERROR"};
}

// --- 1. creation ---

struct Creation
{
    double elapsedMs = -1;
    QString error;
};

/// Calls per creation row, each against a fresh name server and master: the row shows the middle one.
constexpr int CreationRounds = 11;

/// One `rtctl mgr MASTER create … create …` call creating `count` components; @p sameSlave names
/// the slave that hosts them all where the master hosts none itself (rtcd2).
Creation createThroughRtctl(quint16 masterPort, int count, bool separate, const QString &sameSlave = {})
{
    QStringList arguments {QStringLiteral("mgr"), QStringLiteral("corbaloc::127.0.0.1:%1").arg(masterPort)};
    for (int i = 0; i < count; ++i) {
        QString request = QStringLiteral("ConsoleIn?instance_name=C%1").arg(i);
        if (separate)
            request += QStringLiteral("&manager_name=manager_%p");
        else if (!sameSlave.isEmpty())
            request += QStringLiteral("&manager_name=") + sameSlave;
        arguments << QStringLiteral("create") << request;
    }
    Creation result;
    QElapsedTimer timer;
    timer.start();
    const RtctlResult rtctl = runRtctl(arguments);
    result.elapsedMs = double(timer.nsecsElapsed()) / 1e6;
    if (rtctl.code != 0)
        result.error = rtctl.err.trimmed().section(QLatin1Char('\n'), -1);
    return result;
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

/// The time rtctl itself needs to start and end (a `--version` call, the middle one of five), to
/// read the figures by.
double rtctlStartMs()
{
    std::vector<double> runs;
    for (int i = 0; i < 5; ++i) {
        QElapsedTimer timer;
        timer.start();
        runRtctl({QStringLiteral("--version")});
        runs.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    return median(runs);
}

/// Every process below @p pid, deepest first. Children are listed per thread that started them
/// (slaves are started from ORB threads).
QList<qint64> descendants(qint64 pid)
{
    QList<qint64> result;
    const QDir tasks(QStringLiteral("/proc/%1/task").arg(pid));
    for (const QString &task : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile children(tasks.filePath(task + QStringLiteral("/children")));
        if (!children.open(QIODevice::ReadOnly))
            continue;
        for (const QByteArray &child : children.readAll().simplified().split(' ')) {
            if (child.isEmpty())
                continue;
            result << descendants(child.toLongLong());
            result << child.toLongLong();
        }
    }
    return result;
}

/// Waits (at most @p timeoutMs) until none of @p processes runs any more (gone or a zombie).
void waitUntilGone(const QList<qint64> &processes, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    for (const qint64 pid : processes) {
        for (;;) {
            QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
            const QByteArray text = stat.open(QIODevice::ReadOnly) ? stat.readAll() : QByteArray();
            const int close = text.lastIndexOf(')');
            if (close < 0 || text.size() <= close + 2 || text.at(close + 2) == 'Z' || deadline.hasExpired())
                break;
            QThread::msleep(1);
        }
    }
}

/// The middle of CreationRounds calls creating @p count, each in a fresh name server and master
/// (a failed call is the answer). Each round waits for the slaves of the one before to end: they
/// notice their master is gone within a tenth of a second, and would still be ending meanwhile.
Creation createInFreshMasters(int count, bool separate, QString *error)
{
    std::vector<double> calls;
    for (int round = 0; round < CreationRounds; ++round) {
        QList<qint64> started;
        {
            LiveTest::LiveSystem live;
            const quint16 port = LiveTest::freePort();
            QProcess *master = nullptr;
            if (!live.startNameServer(error)
                || !(master = live.startProcess(QStringLiteral(RTMANAGER_PATH),
                                                masterArguments(port, {live.namingServer()}), "rtmanager ready",
                                                error)))
                return {};
            const Creation c = createThroughRtctl(port, count, separate);
            if (!c.error.isEmpty())
                return c;
            calls.push_back(c.elapsedMs);
            started = descendants(master->processId());
        }
        waitUntilGone(started, 10000);
    }
    return {median(calls), QString()};
}

// --- OpenRTM-aist's rtcd2, side by side ---

QString openRtmPrefix()
{
    const QString fromEnvironment = qEnvironmentVariable("OPENRTM_ROOT");
    const QString prefix = fromEnvironment.isEmpty() ? QStringLiteral(RTSTUDIO_OPENRTM_PREFIX) : fromEnvironment;
    return QFile::exists(prefix + QStringLiteral("/bin/rtcd2")) ? prefix : QString();
}

/// An rtcd2 master on @p port with its own name server, as the interop tests configure it; with
/// @p tuned the ConsoleIn module is preloaded (slaves read the same file).
class Rtcd2Master
{
public:
    Rtcd2Master(const QString &prefix, quint16 port, bool tuned)
    {
        if (!m_live.startNameServer(&m_error))
            return;
        const QString examples = prefix + QStringLiteral("/share/openrtm-2.1/components/c++/examples/rtc");
        QStringList extra {QStringLiteral("manager.modules.load_path: ") + examples};
        if (tuned)
            extra << QStringLiteral("manager.modules.preload: ConsoleIn.so");
        m_master = m_live.startRtcdMaster(prefix, m_dir.filePath(QStringLiteral("rtc.conf")), port,
                                          QStringLiteral("bench"), extra, &m_error);
        // Listening comes before the manager object is served: wait until it answers.
        const QStringList list {QStringLiteral("mgr"), QStringLiteral("corbaloc::127.0.0.1:%1").arg(port),
                                QStringLiteral("list")};
        QElapsedTimer waited;
        waited.start();
        while (m_master && runRtctl(list).code != 0) {
            if (waited.elapsed() > 20000) {
                m_error = QStringLiteral("rtcd2 did not answer on port %1").arg(port);
                break;
            }
            QThread::msleep(10);
        }
    }
    QString error() const { return m_master ? m_error : m_error.isEmpty() ? QStringLiteral("rtcd2 did not start") : m_error; }
    bool ok() const { return m_master && m_error.isEmpty(); }

private:
    LiveTest::LiveSystem m_live;
    QTemporaryDir m_dir;
    QProcess *m_master = nullptr;
    QString m_error;
};

/// Per component ms of one creation row against rtcd2, or the reason it could not be measured.
QString rtcd2PerComponent(const QString &prefix, int count, bool separate, bool tuned, double *per)
{
    const quint16 port = LiveTest::freePort();
    Rtcd2Master master(prefix, port, tuned);
    if (!master.ok())
        return master.error();
    const Creation c = createThroughRtctl(port, count, separate, QStringLiteral("benchslave"));
    if (!c.error.isEmpty())
        return c.error;
    *per = double(c.elapsedMs) / count;
    return QString::number(*per, 'f', 2);
}

// --- 2. the large system ---

/// Sources and sinks spread round-robin over the hosts; hosts alternate between the servers.
Profile::RtsProfile largeSystem(const Options &options, const QStringList &servers)
{
    return Bench::liveSystem(QStringLiteral("Scale"), options.components / 2, FanOut,
                             [&](int k) {
                                 const int host = k % options.managers;
                                 return Bench::Placement {servers.at(host % servers.size()), hostName(host)};
                             },
                             QStringLiteral("10"), QStringLiteral("new"));
}

/// Resident memory in KiB of `pid` and every process below it.
qint64 residentKiB(qint64 pid)
{
    qint64 total = 0;
    const QList<qint64> processes = descendants(pid) << pid;
    for (const qint64 process : processes) {
        QFile status(QStringLiteral("/proc/%1/status").arg(process));
        if (!status.open(QIODevice::ReadOnly))
            continue;
        for (const QByteArray &line : status.readAll().split('\n')) {
            if (line.startsWith("VmRSS:"))
                total += line.mid(6).trimmed().split(' ').value(0).toLongLong();
        }
    }
    return total;
}

struct Phase
{
    QString name;
    qint64 ms = -1;
    QString target;
    QString result;
};

/// Part 2: the large system's phases, printed as they end, and the summary line; @p slaves gets
/// the processes the master started, for the caller to wait for once the master is stopped.
int largeSystemPhases(const Options &options, QTextStream &out, double samePer, double separatePer,
                      QList<qint64> *slaves)
{
    QString error;
    LiveTest::LiveSystem live;
    LiveTest::LiveSystem secondServer;
    const quint16 masterPort = LiveTest::freePort();
    if (!live.startNameServer(&error) || !secondServer.startNameServer(&error)) {
        out << "bench_scale: " << error << '\n';
        return 1;
    }
    const QStringList servers {live.namingServer(), secondServer.namingServer()};
    QProcess *master = live.startProcess(QStringLiteral(RTMANAGER_PATH), masterArguments(masterPort, servers),
                                         "rtmanager ready", &error);
    if (!master) {
        out << "bench_scale: " << error << '\n';
        return 1;
    }
    const Profile::RtsProfile profile = largeSystem(options, servers);
    TargetOptions target;
    target.nameServers = servers;
    target.manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(masterPort);
    for (int i = 0; i < options.managers; ++i)
        target.hostManagers.insert(hostName(i), QStringLiteral("127.0.0.1:%1").arg(LiveTest::freePort()));
    target.create = true;

    out << QStringLiteral("\nA system of %1 components and %2 connectors on %3 slave managers, two name servers\n\n")
               .arg(profile.components.size())
               .arg(profile.dataPortConnectors.size())
               .arg(options.managers);
    out << "| phase                          |      ms | goal ms | result |\n";
    out << "|--------------------------------|---------|---------|--------|\n";
    QList<Phase> phases;
    const auto run = [&](const QString &name, const QString &goal, const std::function<QString()> &step) {
        QElapsedTimer timer;
        timer.start();
        const QString result = step();
        const Phase phase {name, timer.elapsed(), goal, result};
        phases << phase;
        const bool met = result.isEmpty() && (goal == QLatin1String("-") || phase.ms <= goal.toLongLong());
        out << QStringLiteral("| %1 | %2 | %3 | %4 |\n")
                   .arg(name, -30)
                   .arg(phase.ms, 7)
                   .arg(goal, 7)
                   .arg(result.isEmpty() ? (met ? QStringLiteral("met") : QStringLiteral("slower")) : result, -6);
        out.flush();
        return result.isEmpty();
    };
    const auto reported = [](const DeployReport &report) { return report.ok ? QString() : report.error; };
    RestorePlan plan;
    bool ok = run(QStringLiteral("first restore (creates slaves)"), QStringLiteral("-"), [&] {
        plan = planRestore(profile, target);
        return reported(restoreSystem(profile, plan, target));
    });
    ok = ok && run(QStringLiteral("plan (find every component)"), QStringLiteral("-"), [&] {
             plan = planRestore(profile, target);
             return plan.missingRequired().isEmpty() ? QString() : QStringLiteral("components missing");
         });
    ok = ok && run(QStringLiteral("teardown"), QStringLiteral("1000"), [&] {
             plan = planRestore(profile, target);
             return reported(teardownSystem(plan));
         });
    ok = ok && run(QStringLiteral("restore + start"), QStringLiteral("3000"), [&] {
             plan = planRestore(profile, target);
             DeployReport report = restoreSystem(profile, plan, target);
             if (report.ok)
                 report = startSystem(profile, plan);
             return reported(report);
         });
    // As rtctl and the Drift view do it: a plan (find every component) and the comparison.
    ok = ok && run(QStringLiteral("drift (planning included)"), QStringLiteral("1000"), [&] {
             const QList<DriftItem> drift = diffSystem(profile, planRestore(profile, target));
             return drift.isEmpty() ? QString() : QStringLiteral("%1 items, first: %2").arg(drift.size()).arg(drift.first().toString());
         });
    ok = ok && run(QStringLiteral("stop"), QStringLiteral("1000"), [&] { return reported(stopSystem(profile, plan)); });
    ok = ok && run(QStringLiteral("cryo"), QStringLiteral("1000"), [&] {
             CryoOptions cryo;
             cryo.paths = {QLatin1Char('/') + servers.first()};
             DeployReport report;
             const Profile::RtsProfile saved = cryoSystem(cryo, &report);
             if (report.ok && (saved.components.size() != profile.components.size()
                               || saved.dataPortConnectors.size() != profile.dataPortConnectors.size())) {
                 return QStringLiteral("saw %1 components, %2 connectors")
                     .arg(saved.components.size())
                     .arg(saved.dataPortConnectors.size());
             }
             return reported(report);
         });
    const qint64 rssKiB = residentKiB(master->processId());
    out << QStringLiteral("\nrtmanager processes (master + %1 slaves): %2 MiB resident, %3 KiB per hosted component\n")
               .arg(options.managers)
               .arg(double(rssKiB) / 1024, 0, 'f', 1)
               .arg(rssKiB / qMax<qsizetype>(1, profile.components.size()));

    const auto msOf = [&phases](const QString &name) {
        for (const Phase &phase : std::as_const(phases)) {
            if (phase.name == name)
                return phase.result.isEmpty() ? QString::number(phase.ms) : QStringLiteral("failed");
        }
        return QStringLiteral("-");
    };
    out << QStringLiteral("\nscale: create same %1 ms, create separate %2 ms, restore+start %3 ms, teardown %4 ms, "
                          "cryo %5 ms (%6 RTCs / %7 managers)\n")
               .arg(samePer, 0, 'f', 2)
               .arg(separatePer, 0, 'f', 2)
               .arg(msOf(QStringLiteral("restore + start")), msOf(QStringLiteral("teardown")), msOf(QStringLiteral("cryo")))
               .arg(profile.components.size())
               .arg(options.managers);
    *slaves = descendants(master->processId());
    return ok ? 0 : 1;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    const Options options = parseOptions(app.arguments());
    Corba::Orb::setCallTimeout(30000);

    // --- 1. creation ---
    const QString openRtm = openRtmPrefix();
    const double rtctlAlone = rtctlStartMs();
    out << QStringLiteral("Creation through one `rtctl mgr … create …` call, naming on, a fresh "
                          "name server and "
                          "master each, the middle of %1 calls (rtctl alone starts and ends in %2 "
                          "ms: the last "
                          "column leaves it out); %3\n\n")
               .arg(CreationRounds)
               .arg(rtctlAlone, 0, 'f', 2)
               .arg(
                   openRtm.isEmpty()
                       ? QStringLiteral("no OpenRTM-aist prefix (OPENRTM_ROOT), so rtmanager alone")
                       : QStringLiteral("OpenRTM-aist's rtcd2 side by side, per component ms"));
    out << "| placement         |   N | call ms | per component ms | goal ms | met | beyond "
           "rtctl's start |"
        << (openRtm.isEmpty() ? "" : " rtcd2 as it comes | rtcd2 tuned | rtcd2 tuned / ours |")
        << "\n";
    out << "|-------------------|-----|---------|------------------|---------|-----|---------------"
           "-------|"
        << (openRtm.isEmpty() ? "" : "-------------------|-------------|--------------------|")
        << "\n";
    double samePer = -1, separatePer = -1;
    QString error;
    for (const bool separate : {false, true}) {
        for (const int count : {10, 100}) {
            const Creation c = createInFreshMasters(count, separate, &error);
            if (c.elapsedMs < 0 && c.error.isEmpty()) {
                out << "bench_scale: " << error << '\n';
                return 1;
            }
            const double per = c.error.isEmpty() ? c.elapsedMs / count : -1;
            const double goal = separate ? 2.5 : 0.5;
            const double beyond
                = c.error.isEmpty() ? qMax(0.0, c.elapsedMs - rtctlAlone) / count : -1;
            out << QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 | %7 |")
                       .arg(separate ? QStringLiteral("own slave process")
                                     : QStringLiteral("same process"),
                            -17)
                       .arg(count, 3)
                       .arg(c.elapsedMs, 7, 'f', 1)
                       .arg(c.error.isEmpty() ? QString::number(per, 'f', 2) : c.error, 16)
                       .arg(goal, 7, 'f', 1)
                       .arg(per >= 0 && per <= goal ? QStringLiteral("yes") : QStringLiteral("no"),
                            3)
                       .arg(beyond >= 0 ? QString::number(beyond, 'f', 2) : QStringLiteral("-"),
                            20);
            if (!openRtm.isEmpty()) {
                double plain = -1, tuned = -1;
                const QString plainText
                    = rtcd2PerComponent(openRtm, count, separate, false, &plain);
                const QString tunedText = rtcd2PerComponent(openRtm, count, separate, true, &tuned);
                out << QStringLiteral(" %1 | %2 | %3 |")
                           .arg(plainText, 17)
                           .arg(tunedText, 11)
                           .arg(tuned > 0 && per > 0
                                    ? QString::number(tuned / per, 'f', 1) + QLatin1Char('x')
                                    : QStringLiteral("-"),
                                18);
            }
            out << '\n';
            out.flush();
            if (count == 100)
                (separate ? separatePer : samePer) = per;
        }
    }

    // --- 2. the large system ---
    QList<qint64> slaves;
    const int code = largeSystemPhases(options, out, samePer, separatePer, &slaves);
    // The slaves leave within a tenth of a second of their master, and a thousand components take
    // a while to end: a run started right after this one would measure its creations beside them.
    waitUntilGone(slaves, 10000);
    return code;
}
