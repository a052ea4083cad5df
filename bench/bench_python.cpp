// SPDX-License-Identifier: MIT
// bench_python: data-port latency and throughput of Python components on RT Studio's runtime beside
// C++ ones, in the shape of bench_sdkflow: RTC::TimedDoubleSeq samples (1, 1,024 and 65,536
// elements) over a push connection with subscription "flush", one-way latency taken by the sink's
// ON_BUFFER_WRITE listener (arrival minus the stamp the source set just before write(), system
// clock on both sides), throughput from the intervals between arrivals.
// Sources and sinks are modules of rtmanager (bench/pythonflow: FlowSource / FlowSink in C++,
// PyFlowSource / PyFlowSink in Python), every pairing of the two languages, placed
// (a) both in one manager process, and (b) the source in a slave manager of its own (a second
// process, over the Unix socket the runtime offers same-host peers), the sink in the master.
// The goal printed at the end: small-sample latency between processes within 2x of C++ -> C++.
#include "livesystem.h"
#include "rtctlrunner.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QRegularExpression>
#include <QTextStream>

#include <map>

namespace {

const QString hostName = QStringLiteral("benchpy");
constexpr int flowTimeoutMs = 300 * 1000;
const QList<int> sizes{1, 1024, 65536};

struct Pairing
{
    const char *name;
    const char *source;
    const char *sink;
};
const Pairing pairings[] = {{"C++ -> C++", "FlowSource", "FlowSink"},
                            {"Python -> C++", "PyFlowSource", "FlowSink"},
                            {"C++ -> Python", "FlowSource", "PyFlowSink"},
                            {"Python -> Python", "PyFlowSource", "PyFlowSink"}};

struct Placement
{
    const char *name;
    const char *sourceOptions; ///< added to the source's create request
};
const Placement placements[] = {{"one process", ""}, {"two processes", "&manager_name=benchsource"}};

/// One size's figures as the sink printed them.
struct Figures
{
    double meanUs = 0;
    double medianUs = 0;
    double mibPerSecond = 0;
};

class Bench
{
public:
    bool start(QString *error);
    /// The sink's figures by size; empty when the run failed (@p error says why).
    std::map<int, Figures> run(const Pairing &pairing, const Placement &placement, int number, QString *error);

private:
    RtctlResult rtctl(const QStringList &arguments) const
    {
        return runRtctlAt(QStringLiteral("/%1/%2.host_cxt").arg(m_live.namingServer(), hostName), arguments);
    }
    bool succeeds(const QStringList &arguments, QString *error) const;
    std::map<int, Figures> awaitFigures(const QString &sink, QString *error);

    LiveTest::LiveSystem m_live;
    LiveTest::PrintedOutput m_printed;
    QProcess *m_manager = nullptr;
    QString m_managerPath;
};

bool Bench::start(QString *error)
{
    if (!m_live.startNameServer(error))
        return false;
    const QString modules = QStringLiteral(RTSTUDIO_BENCH_FLOW_SOURCE_DIR "," RTSTUDIO_BENCH_FLOW_BUILD_DIR);
    m_manager = m_live.startHostManager(QStringLiteral(RTMANAGER_PATH), LiveTest::freePort(), hostName,
                                        {QStringLiteral("manager.modules.load_path=") + modules,
                                         QStringLiteral("logger.enable=NO")},
                                        error);
    m_managerPath = QStringLiteral("/%1/%2.host_cxt/manager.mgr").arg(m_live.namingServer(), hostName);
    return m_manager != nullptr;
}

bool Bench::succeeds(const QStringList &arguments, QString *error) const
{
    const RtctlResult r = rtctl(arguments);
    if (r.code != 0)
        *error = QStringLiteral("rtctl %1: %2%3").arg(arguments.join(' '), r.out, r.err);
    return r.code == 0;
}

std::map<int, Figures> Bench::awaitFigures(const QString &sink, QString *error)
{
    const QRegularExpression line(QStringLiteral("flow %1 (\\d+) \\d+ ([\\d.]+) ([\\d.]+) ([\\d.]+)\\n").arg(sink));
    std::map<int, Figures> figures;
    const QDeadlineTimer deadline(flowTimeoutMs);
    while (figures.size() < size_t(sizes.size()) && !deadline.hasExpired()) {
        m_manager->waitForReadyRead(200);
        QRegularExpressionMatchIterator it = line.globalMatch(m_printed.of(m_manager));
        while (it.hasNext()) {
            const QRegularExpressionMatch m = it.next();
            figures[m.captured(1).toInt()] = {m.captured(2).toDouble(), m.captured(3).toDouble(), m.captured(4).toDouble()};
        }
    }
    if (figures.size() < size_t(sizes.size())) {
        *error = QStringLiteral("%1 reported %2 of %3 sizes").arg(sink).arg(figures.size()).arg(sizes.size());
        figures.clear();
    }
    return figures;
}

std::map<int, Figures> Bench::run(const Pairing &pairing, const Placement &placement, int number, QString *error)
{
    const QString source = QStringLiteral("Source%1").arg(number);
    const QString sink = QStringLiteral("Sink%1").arg(number);
    const bool ready =
        succeeds({"mgr", m_managerPath, "create", QStringLiteral("%1?instance_name=%2").arg(pairing.sink, sink), "create",
                  QStringLiteral("%1?instance_name=%2%3").arg(pairing.source, source, placement.sourceOptions)},
                 error)
        && succeeds({"con", source + ".rtc:out", sink + ".rtc:in", "-p", "dataport.subscription_type=flush"}, error)
        && succeeds({"act", sink + ".rtc", source + ".rtc"}, error);
    std::map<int, Figures> figures = ready ? awaitFigures(sink, error) : std::map<int, Figures>();
    QString ignored;
    succeeds({"deact", source + ".rtc", sink + ".rtc"}, &ignored);
    return figures;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    Bench bench;
    QString error;
    if (!bench.start(&error)) {
        out << "bench_python: " << error << '\n';
        return 1;
    }
    out << QStringLiteral("%1 %2 %3 %4 %5 %6\n")
               .arg("pairing", -17).arg("placement", -14).arg("1 elem mean us", 15).arg("median us", 10)
               .arg("1024 elem MiB/s", 16).arg("65536 elem MiB/s", 17);
    out.flush();
    std::map<QString, double> smallBetween;
    int number = 0;
    for (const Placement &placement : placements) {
        for (const Pairing &pairing : pairings) {
            const std::map<int, Figures> figures = bench.run(pairing, placement, number++, &error);
            if (figures.empty()) {
                out << QStringLiteral("%1 %2 failed: %3\n").arg(pairing.name, -17).arg(placement.name, -14).arg(error);
                out.flush();
                continue;
            }
            out << QStringLiteral("%1 %2 %3 %4 %5 %6\n")
                       .arg(pairing.name, -17).arg(placement.name, -14)
                       .arg(figures.at(1).meanUs, 15, 'f', 1).arg(figures.at(1).medianUs, 10, 'f', 1)
                       .arg(figures.at(1024).mibPerSecond, 16, 'f', 1).arg(figures.at(65536).mibPerSecond, 17, 'f', 1);
            out.flush();
            if (placement.sourceOptions[0] != '\0')
                smallBetween[QString::fromLatin1(pairing.name)] = figures.at(1).medianUs;
        }
    }
    const double cxx = smallBetween.count("C++ -> C++") ? smallBetween.at("C++ -> C++") : 0;
    out << "\nGoal: small-sample latency between processes within 2x of C++ -> C++ (median "
        << QString::number(cxx, 'f', 1) << " us)\n";
    for (const char *pairing : {"Python -> C++", "Python -> Python"}) {
        if (!smallBetween.count(pairing) || cxx <= 0)
            continue;
        const double ratio = smallBetween.at(pairing) / cxx;
        out << QStringLiteral("  %1 %2x  %3\n").arg(pairing, -17).arg(ratio, 0, 'f', 2).arg(ratio <= 2 ? "met" : "not met");
    }
    return 0;
}
