// SPDX-License-Identifier: MIT
#include "onlineservice.h"

#include "corbaerror.h"

namespace SystemEditor {

namespace {

// Errors that say something about the peer's host rather than about the request.
bool isHostFailure(Corba::Error::Kind kind)
{
    using Kind = Corba::Error::Kind;
    return kind == Kind::Transient || kind == Kind::CommFailure || kind == Kind::Timeout;
}

} // namespace

OnlineService::OnlineService(QString host, QObject *parent)
    : QObject(parent)
    , m_host(std::move(host))
{ }

void OnlineService::run(quint64 ticket, const Call &call)
{
    OnlineResult result;
    try {
        result.value = call();
        result.ok = true;
    } catch (const Corba::Error &e) {
        result.error = e.message();
        result.hostFailure = isHostFailure(e.kind());
    } catch (const std::exception &e) {
        // The client library only throws Corba::Error; anything else is still reported, never
        // fatal.
        result.error = QString::fromLocal8Bit(e.what());
    } catch (...) {
        // An exception leaving a worker thread terminates the application; whatever went wrong
        // is reported to the caller like any other failed call.
        result.error = tr("The call to %1 failed with an unexpected error").arg(m_host);
    }
    const bool reachable = result.ok || !result.hostFailure;
    if (reachable != m_reachable) {
        m_reachable = reachable;
        emit hostReachabilityChanged(m_host, reachable, result.error);
    }
    emit finished(ticket, result);
}

} // namespace SystemEditor
