// SPDX-License-Identifier: MIT
#include "onlinesession.h"

#include "orb.h"
#include "workerthread.h"

#include <QThread>

namespace SystemEditor {

OnlineSession::OnlineSession(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<OnlineResult>();
}

OnlineSession::~OnlineSession()
{
    // A worker may be inside a call to a hung peer, or have several queued: all get one deadline
    // of about one call timeout, and those still busy then finish on their own.
    for (Worker &w : m_workers)
        w.thread->quit();
    const QDeadlineTimer deadline(Corba::Orb::callTimeout() + 1000);
    for (Worker &w : m_workers)
        Corba::retireWorkerThread(w.thread, w.service, deadline);
}

OnlineSession::Worker &OnlineSession::worker(const QString &host)
{
    auto it = m_workers.find(host);
    if (it != m_workers.end())
        return *it;
    Worker w;
    w.thread = new QThread;
    w.thread->setObjectName(QStringLiteral("online:") + host);
    w.service = new OnlineService(host);
    w.service->moveToThread(w.thread);
    connect(w.service, &OnlineService::finished, this, &OnlineSession::deliver,
            Qt::QueuedConnection);
    connect(w.service, &OnlineService::hostReachabilityChanged, this,
            &OnlineSession::updateReachability, Qt::QueuedConnection);
    w.thread->start();
    return *m_workers.insert(host, w);
}

void OnlineSession::submit(const QString &host, const OnlineService::Call &call, QObject *context,
                           const Callback &done)
{
    const quint64 ticket = m_nextTicket++;
    m_callbacks.insert(ticket, {QPointer<QObject>(context), done});
    OnlineService *service = worker(host).service;
    QMetaObject::invokeMethod(
        service, [service, ticket, call] { service->run(ticket, call); }, Qt::QueuedConnection);
}

void OnlineSession::deliver(quint64 ticket, const OnlineResult &result)
{
    const Pending pending = m_callbacks.take(ticket);
    if (pending.context && pending.done)
        pending.done(result);
    if (m_callbacks.isEmpty())
        emit idle();
}

void OnlineSession::updateReachability(const QString &host, bool reachable, const QString &message)
{
    if (reachable)
        m_unreachable.remove(host);
    else
        m_unreachable.insert(host);
    emit hostReachabilityChanged(host, reachable, message);
}

} // namespace SystemEditor
