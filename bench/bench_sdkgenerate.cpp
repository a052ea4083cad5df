// SPDX-License-Identifier: MIT
// From Generate to a running instance: a component with six data ports (three in, three out, of
// different types) and one configuration parameter is generated with `rtctl gen`, configured and
// built with CMake against this build tree's SDK, loaded into a real rtmanager and instantiated.
// Target: ≤ 30 s for all steps on 2 cores. Without --ccache the compiler runs cold; with it, ccache
// is the compiler launcher (a second run then shows a warm cache). --keep leaves the project
// behind.
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextStream>
#include <QThread>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <functional>
#include <vector>

namespace {

const QString componentName = QStringLiteral("SixPorts");
const QString fixture = QStringLiteral(RTSTUDIO_BENCH_DATA_DIR "/SixPorts/RTC.xml");
constexpr double targetMs = 30000;

quint16 freePort()
{
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    quint16 port = 0;
    if (bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0
        && getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length) == 0)
        port = ntohs(address.sin_port);
    close(fd);
    return port;
}

/// Runs a tool to its end; false with its output in @p log when it fails or runs past @p timeoutMs
/// (then it is killed).
bool runTool(const QString &program, const QStringList &arguments, int timeoutMs, QString *log)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    const bool finished = process.waitForFinished(timeoutMs);
    *log = QString::fromLocal8Bit(process.readAll());
    if (!finished) {
        process.kill();
        process.waitForFinished(5000);
        *log += QStringLiteral("\n(timed out after %1 ms)").arg(timeoutMs);
        return false;
    }
    return process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
}

/// A master rtmanager serving on a loopback port and loading modules from one folder; killed
/// (with any slave it started, which follow their master) when this object goes.
class ManagerProcess
{
public:
    ~ManagerProcess()
    {
        if (m_process.state() != QProcess::NotRunning) {
            m_process.kill();
            m_process.waitForFinished(10000);
        }
    }
    bool start(quint16 port, const QString &modules, QString *log)
    {
        m_process.setProcessChannelMode(QProcess::MergedChannels);
        m_process.start(QStringLiteral(RTMANAGER_PATH),
                        {"-d", "-o", QString("corba.endpoints=127.0.0.1:%1").arg(port), "-o",
                         "naming.enable=NO", "-o", "manager.modules.load_path=" + modules});
        QByteArray output;
        QElapsedTimer waited;
        waited.start();
        while (!output.contains("rtmanager ready") && waited.elapsed() < 20000
               && m_process.waitForReadyRead(int(20000 - waited.elapsed())))
            output += m_process.readAll();
        *log = QString::fromLocal8Bit(output);
        return output.contains("rtmanager ready");
    }

private:
    QProcess m_process;
};

struct Step
{
    QString name;
    std::function<bool(QString *log)> run;
};

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    const QStringList args = app.arguments();
    const bool useCcache = args.contains(QStringLiteral("--ccache"));
    QTemporaryDir work;
    if (!work.isValid()) {
        out << "cannot make a working folder\n";
        return 1;
    }
    work.setAutoRemove(!args.contains(QStringLiteral("--keep")));
    const QString project = work.filePath(componentName);
    const QString build = project + QStringLiteral("/build");

    QStringList configure {"-S",
                           project,
                           "-B",
                           build,
                           "-G",
                           "Ninja",
                           "-DCMAKE_BUILD_TYPE=Release",
                           "-DCMAKE_PREFIX_PATH=" RTSTUDIO_BUILD_DIR};
    QString launcher = QStringLiteral("none (cold compiler)");
    if (useCcache) {
        const QString ccache = QStandardPaths::findExecutable(QStringLiteral("ccache"));
        if (!ccache.isEmpty()) {
            // Each run builds in a new folder: paths relative to it let a later run hit the cache.
            qputenv("CCACHE_BASEDIR", work.path().toLocal8Bit());
            configure << "-DCMAKE_CXX_COMPILER_LAUNCHER=" + ccache;
            launcher = ccache;
        } else {
            launcher = QStringLiteral("none (--ccache given, but no ccache on PATH)");
        }
    }
    const quint16 port = freePort();
    const QString address = QStringLiteral("corbaloc::127.0.0.1:%1").arg(port);
    ManagerProcess manager;
    QString instance;

    const std::vector<Step> steps = {
        {"generate (rtctl gen)",
         [&](QString *log) {
             return runTool(RTCTL_PATH, {"gen", fixture, "--lang", "cpp", "-o", project}, 60000,
                            log);
         }},
        {"configure (cmake)",
         [&](QString *log) { return runTool(CMAKE_COMMAND, configure, 120000, log); }},
        {"build (cmake --build -j2)",
         [&](QString *log) {
             return runTool(CMAKE_COMMAND, {"--build", build, "-j2"}, 600000, log)
                 && QFile::exists(build + "/src/" + componentName + ".so");
         }},
        {"start rtmanager", [&](QString *log) { return manager.start(port, build + "/src", log); }},
        {"load + create (rtctl mgr)",
         [&](QString *log) {
             const bool ok = runTool(
                 RTCTL_PATH, {"mgr", address, "load", componentName, "create", componentName},
                 60000, log);
             instance = log->trimmed().section('\n', -1).trimmed();
             return ok && instance.startsWith(componentName);
         }},
    };

    out << QStringLiteral("%1: 3 in + 3 out data ports, 1 parameter; Release, Ninja, %2 cores "
                          "seen, launcher %3\n\n")
               .arg(componentName)
               .arg(QThread::idealThreadCount())
               .arg(launcher);
    out << "| step                       |        ms |\n";
    out << "|----------------------------|-----------|\n";
    out.flush();
    double total = 0;
    for (const Step &step : steps) {
        QString log;
        QElapsedTimer timer;
        timer.start();
        const bool ok = step.run(&log);
        const double ms = double(timer.nsecsElapsed()) / 1e6;
        total += ms;
        out << QStringLiteral("| %1 | %2 |\n").arg(step.name, -26).arg(ms, 9, 'f', 1);
        out.flush();
        if (!ok) {
            out << "\n" << step.name << " failed:\n" << log << '\n';
            return 1;
        }
    }
    out << QStringLiteral("| %1 | %2 |\n").arg("total", -26).arg(total, 9, 'f', 1);
    out << QStringLiteral("\nrunning instance: %1; total %2 s, target <= %3 s on 2 cores: %4\n")
               .arg(instance)
               .arg(total / 1000, 0, 'f', 1)
               .arg(targetMs / 1000, 0, 'f', 0)
               .arg(total <= targetMs ? QStringLiteral("met") : QStringLiteral("not met"));
    if (!work.autoRemove())
        out << "project kept in " << project << '\n';
    return 0;
}
