// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QJsonObject>
#include <QMetaType>
#include <QString>

namespace Deploy {

/// A name server or manager process of the local runtime.
struct LocalProcess
{
    qint64 pid = 0;
    quint16 port = 0;
    bool running = false; ///< the process lives and its port accepts connections
};

/// What `rtctl local status` reports.
struct LocalRuntimeState
{
    LocalProcess nameServer;
    LocalProcess manager;
    QString folder; ///< where the runtime keeps its state, the name server's data and the logs
    bool startedNow = false; ///< start() launched the processes (rather than finding them running)
    bool tls = false; ///< both speak TLS only, with the runtime's own certificate authority

    bool running() const { return nameServer.running && manager.running; }
    /// `127.0.0.1:PORT` of the name server, as rtshell paths and the Name Service view name it.
    QString nameServerAddress() const;
    /// `corbaloc:iiop:127.0.0.1:PORT/manager`.
    QString managerAddress() const;
};

/// The files of a local runtime that runs with TLS (in its folder's `tls/`).
struct LocalRuntimeTls
{
    bool enabled = false;
    QString certificateAuthorityFile; ///< the runtime's own authority, `tls/ca.pem`
    QString nodeKeyFile; ///< the name server's and the manager's key and certificate, `tls/localhost.pem`
    QString userKeyFile; ///< the user's, which rtctl and rtstudio present, `tls/user.pem`
};

/**
 * A name server and an rtmanager master on this machine for trying systems out: Debian's omniNames
 * (its data and log in the runtime's folder) on port 2809 or the next free one, and rtmanager
 * (`-d`, registered in that name server) on 2810 or the next free one. Both run detached, so
 * that they outlive the program that started them; the folder's `state.json` lets every RT Studio
 * and rtctl of the user find and reuse them, and stop them.
 */
class LocalRuntime
{
    // Its reasons reach the GUI's status bar: translated there, English in rtctl (no translator).
    Q_DECLARE_TR_FUNCTIONS(Deploy::LocalRuntime)

public:
    /// The user's runtime folder (`$XDG_RUNTIME_DIR/rtstudio`, else a folder under the temp dir).
    static QString defaultFolder();

    explicit LocalRuntime(const QString &folder = defaultFolder());

    /// Reads the state file and checks that the processes live and listen.
    LocalRuntimeState status() const;
    /**
     * Starts what does not run yet (reusing a running one) and waits until both listen, at most
     * `timeoutMs`. `managerProgram` is the rtmanager binary. On failure returns the state and
     * puts the reason in `error`; a half-started runtime is stopped again.
     */
    LocalRuntimeState start(const QString &managerProgram, QString *error, int timeoutMs = 20000);
    /**
     * As start(), with @p tls: both processes speak TLS only and require a certificate of the
     * runtime's own authority, which is created with the name server's and the user's certificates
     * on first use (and again when one has expired). A runtime already running the other way is
     * stopped and started afresh.
     */
    LocalRuntimeState start(const QString &managerProgram, bool tls, QString *error, int timeoutMs = 20000);
    /// The TLS files of the runtime when it was started with TLS; disabled otherwise.
    LocalRuntimeTls tls() const;
    /// Stops both processes (TERM, then KILL after a grace time) and forgets them.
    bool stop(QString *error);

private:
    QString statePath() const;
    /// The state file's contents, empty when there is none.
    QJsonObject readStateFile() const;
    /// Creates what TLS needs that does not exist yet or has expired.
    bool prepareTls(LocalRuntimeTls *files, QString *error) const;
    void writeState(const LocalRuntimeState &state) const;

    QString m_folder;
};

} // namespace Deploy

Q_DECLARE_METATYPE(Deploy::LocalRuntimeState)
