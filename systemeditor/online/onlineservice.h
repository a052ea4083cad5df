// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QString>
#include <QVariant>

#include <functional>

namespace SystemEditor {

/// What one remote call produced: a value, or the error text and whether the host did not answer.
struct OnlineResult
{
    bool ok = false;
    QVariant value;
    QString error; ///< Corba::Error message when !ok
    bool hostFailure = false; ///< the peer was unreachable, hung or broke the connection
};

/**
 * The worker of the online views: one instance lives in its own QThread (see OnlineSession) and
 * runs the remote calls queued to it one after the other under the client library's call timeout.
 * Results leave by the queued signal finished(), so the GUI thread never waits for a peer.
 */
class OnlineService : public QObject
{
    Q_OBJECT

public:
    using Call = std::function<QVariant()>;

    explicit OnlineService(QString host, QObject *parent = nullptr);

    QString host() const { return m_host; }

    /// Runs `call` now, in the calling (worker) thread, and emits finished(ticket, ...).
    void run(quint64 ticket, const Call &call);

signals:
    void finished(quint64 ticket, const SystemEditor::OnlineResult &result);
    /// Emitted only when the host's reachability changes, so a dead host is reported once.
    void hostReachabilityChanged(const QString &host, bool reachable, const QString &message);

private:
    QString m_host;
    bool m_reachable = true;
};

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::OnlineResult)
