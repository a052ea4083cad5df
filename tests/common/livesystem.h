// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QList>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace LiveTest {

/// A loopback TCP port that was free a moment ago (a random one below the range of outgoing
/// connections' local ports, bound and released).
quint16 freePort();
/**
 * The rtc.conf line of a component program that joins no master manager. Without it a program
 * joins the master at the default localhost:2810, which another test's local runtime may run
 * meanwhile; that master shuts its slaves down when it stops (as OpenRTM-aist's does).
 */
inline const QString NoMasterLine = QStringLiteral("corba.master_manager:");
/// Waits up to @p timeoutMs for @p process to end; true also when it has ended already (an event
/// loop the test ran meanwhile, e.g. while rtctl ran, may have seen it end, and then
/// QProcess::waitForFinished() answers false).
inline bool waitForExit(QProcess *process, int timeoutMs)
{
    return process->state() == QProcess::NotRunning || process->waitForFinished(timeoutMs);
}
/// True when something accepts TCP connections on 127.0.0.1:`port`.
bool isListening(quint16 port);
/// True when something accepts TCP connections on `address`:`port` (an IPv4 address).
bool isListening(const QString &address, quint16 port);
/// SIGSTOP takes effect asynchronously: waits (bounded) until every thread of `pid` is stopped.
bool waitUntilStopped(qint64 pid, int timeoutMs = 5000);
/// `corbaloc:iiop:127.0.0.1:PORT/manager`: the object key of an rtmanager serving on `port`.
QByteArray managerLocation(quint16 port);
/**
 * The processes whose parent is `parent`, e.g. the slaves an OpenRTM-aist master started: they
 * begin sessions of their own, so stopping the master leaves them running.
 */
QList<qint64> childProcesses(qint64 parent);

/// This process's environment with OpenRTM-aist's installation at @p prefix first: its lib folder in
/// LD_LIBRARY_PATH (rtcd2 and its example programs find their libraries), its bin folder in PATH (a
/// master runs rtcprof2 to list the modules it can load).
QProcessEnvironment openRtmEnvironment(const QString &prefix);
/// Sets those two variables in this process's environment, for every program it starts from now on.
void useOpenRtm(const QString &prefix);

/// Where a LiveSystem runs its servers.
struct LiveHost
{
    /// The IPv4 address the servers listen on; this process must reach it.
    QString address = QStringLiteral("127.0.0.1");
    /**
     * Runs in each child process between fork and exec (e.g. to enter another network
     * namespace): async-signal-safe calls only, `_exit()` on failure. None by default.
     */
    std::function<void()> enterChild;
};

/**
 * Real peer processes for live tests: omniNames, the test peer (rtstudio_livepeer) or any other
 * server, each on free loopback ports (or on the ports and the address of a LiveHost) with its
 * own temporary data folder. Everything started is killed and reaped in the destructor, also
 * when a test fails halfway.
 */
/// What the processes a test started have printed so far, kept per process: each call reads what
/// came since the last one and answers the whole text.
class PrintedOutput
{
public:
    QString of(QProcess *process);

private:
    QHash<QProcess *, QString> m_text;
};

class LiveSystem
{
public:
    explicit LiveSystem(LiveHost host = {});
    ~LiveSystem();
    LiveSystem(const LiveSystem &) = delete;
    LiveSystem &operator=(const LiveSystem &) = delete;

    /// The address the servers listen on.
    QString address() const { return m_host.address; }
    /// Starts omniNames on `port` (0: a free loopback port) and waits until it accepts connections.
    bool startNameServer(QString *error, quint16 port = 0);
    /**
     * As startNameServer(), serving over TLS only with the certificate authority @p caFile and the
     * key and certificate @p keyFile (omniNames with omniORB's SSL transport preloaded).
     */
    bool startTlsNameServer(const QString &caFile, const QString &keyFile, QString *error);
    quint16 namingPort() const { return m_namingPort; }
    /// The name server's process (the latest started).
    QProcess *nameServer() const { return m_nameServer; }
    /// `ADDRESS:PORT` of the name server, as an rtshell path element.
    QString namingServer() const;

    /**
     * Starts rtstudio_livepeer registered in the name server under `host`.host_cxt with the given
     * components (`Type` or `Type?instance_name=NAME`); `zombies` adds Ghost0.rtc and
     * Stranger0.rtc. Waits for its "ready" line. The peer's own port is returned in `port`.
     */
    QProcess *startPeer(const QStringList &components, QString *error, quint16 *port = nullptr,
                        const QString &host = QStringLiteral("livehost"), bool zombies = false);

    /// Starts `program` and waits up to `timeoutMs` until its standard output contains `readyText`;
    /// a non-empty `environment` replaces this process's for it.
    QProcess *startProcess(const QString &program, const QStringList &arguments,
                           const QString &readyText, QString *error, int timeoutMs = 20000,
                           const QProcessEnvironment &environment = {});
    /**
     * startProcess() without a ready line, then polls `registered` (e.g. "its instance is in the
     * name server") until it holds; nothing, with what the program printed in `error`, when the
     * program ends or `timeoutMs` passes first.
     */
    QProcess *startRegistered(const QString &program, const QStringList &arguments,
                              const std::function<bool()> &registered, QString *error,
                              int timeoutMs = 20000, const QProcessEnvironment &environment = {});
    /**
     * Starts the rtmanager `program` as a master (`-d`) serving on this system's address and
     * `port`, each of `options` passed as `-o KEY=VALUE` after the endpoint, and waits for
     * "rtmanager ready".
     */
    QProcess *startManager(const QString &program, quint16 port, const QStringList &options,
                           QString *error);
    /**
     * startManager() registered in this system's name server, the manager and its components
     * under the context `<host>.host_cxt`.
     */
    QProcess *startHostManager(const QString &program, quint16 port, const QString &host,
                               const QStringList &options, QString *error);
    /**
     * Starts OpenRTM-aist's rtcd2 (of the installation at `prefix`) as a master on
     * 127.0.0.1:`masterPort`, registered with its components in this system's name server under
     * `<host>.host_cxt`, starting slaves with the same rtcd2. Its configuration goes to `confFile`
     * (slaves read the master's file, not its command line), `extraLines` after the common ones.
     * It runs with the installation's lib and bin folders first in LD_LIBRARY_PATH and PATH.
     * Its slaves run in sessions of their own and outlive it: stopping it here stops them first.
     */
    QProcess *startRtcdMaster(const QString &prefix, const QString &confFile, quint16 masterPort,
                              const QString &host, const QStringList &extraLines, QString *error);
    /**
     * Whether the processes started from now on merge their standard error into their standard
     * output, where a test reads it (a server's refusals are logged there), rather than forward it
     * to the test's own.
     */
    void setErrorsRead(bool read) { m_errorsRead = read; }
    /// What @p process printed until it was ready (startProcess() read it while it waited).
    QByteArray printedWhileStarting(QProcess *process) const { return m_startOutput.value(process); }
    /**
     * Starts OpenRTM-aist's example program @p program (`ConsoleInComp` …) of the installation at
     * @p prefix, registered in this system's name server under `<context>.host_cxt`, serving on
     * this host's address, with no manager servant (so no master is looked for) and no log file;
     * @p options (`key:value`) are given after those (the later of two wins), after @p arguments.
     */
    QProcess *startOpenRtmExample(const QString &prefix, const QString &program, const QString &context,
                                  QString *error, const QStringList &options = {},
                                  const QStringList &arguments = {});
    /// Kills and reaps one process started here (and first the slaves of an rtcd2 master).
    void stop(QProcess *process);
    /// Kills and reaps everything started here.
    void stopAll();

private:
    bool startOmniNames(const QStringList &endpointArguments, const QProcessEnvironment &environment,
                        QString *error);
    LiveHost m_host;
    std::vector<std::unique_ptr<QProcess>> m_processes;
    std::unique_ptr<QTemporaryDir> m_dataDir;
    quint16 m_namingPort = 0;
    QProcess *m_nameServer = nullptr;
    std::set<QProcess *> m_rtcdMasters; ///< whose children (slaves) are stopped with them
    bool m_errorsRead = false;
    QHash<QProcess *, QByteArray> m_startOutput;
};

} // namespace LiveTest
