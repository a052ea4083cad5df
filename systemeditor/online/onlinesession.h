// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "onlineservice.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>

class QThread;

namespace SystemEditor {

/**
 * The GUI-side entry to the worker layer. Owns one OnlineService per host, each in its own
 * QThread, so a hung host only delays calls to itself. submit() returns at once; the callback runs
 * later in the session's (GUI) thread, and not at all when its context object is gone.
 */
class OnlineSession : public QObject
{
    Q_OBJECT

public:
    using Callback = std::function<void(const OnlineResult &)>;

    explicit OnlineSession(QObject *parent = nullptr);
    ~OnlineSession() override;

    /// Queues `call` on `host`'s worker; `done` runs in this thread with the result.
    void submit(const QString &host, const OnlineService::Call &call, QObject *context,
                const Callback &done);

    /// The worker of the deployment engine's calls (restore, cryo, drift): they talk to many
    /// hosts, so they share one worker of their own.
    static QString deploymentHost() { return QStringLiteral("deployment"); }

    /// Hosts whose last call failed because they did not answer.
    QSet<QString> unreachableHosts() const { return m_unreachable; }
    bool isReachable(const QString &host) const { return !m_unreachable.contains(host); }
    /// Calls submitted and not yet answered.
    int pendingCalls() const { return int(m_callbacks.size()); }

signals:
    /// A host stopped or started answering; emitted once per change, never per call.
    void hostReachabilityChanged(const QString &host, bool reachable, const QString &message);
    /// Every submitted call has been answered.
    void idle();
    /// A view asks to watch the samples of a data port (the Port Monitor listens).
    void portMonitorRequested(const QString &componentPath, const Corba::PortInfo &port);

private:
    struct Pending
    {
        QPointer<QObject> context;
        Callback done;
    };
    struct Worker
    {
        QThread *thread = nullptr;
        OnlineService *service = nullptr;
    };

    Worker &worker(const QString &host);
    void deliver(quint64 ticket, const OnlineResult &result);
    void updateReachability(const QString &host, bool reachable, const QString &message);

    QHash<QString, Worker> m_workers;
    QHash<quint64, Pending> m_callbacks;
    QSet<QString> m_unreachable;
    quint64 m_nextTicket = 1;
};

} // namespace SystemEditor
