// SPDX-License-Identifier: MIT
#include "modulerun.h"

#include "componentproxy.h"
#include "corbaerror.h"
#include "managerproxy.h"
#include "orb.h"
#include "rtpath.h"

#include <QDeadlineTimer>
#include <QFileInfo>

namespace Builder {

namespace {

using Corba::Error;

/// A failed step: the text that follows "Could not run MODULE in manager ADDRESS: ".
struct StepFailure
{
    QString reason;
};

bool isUnreachable(Error::Kind kind)
{
    return kind == Error::Kind::Transient || kind == Error::Kind::CommFailure
        || kind == Error::Kind::ObjectNotExist;
}

/// Runs one remote call with what is left of the run's time.
template<typename F> auto withinDeadline(const QDeadlineTimer &deadline, int timeoutMs, F &&f)
{
    const qint64 left = deadline.remainingTime();
    if (left == 0)
        throw Error(Error::Kind::Timeout,
                    ModuleRun::tr("no answer within %1 s").arg(timeoutMs / 1000.0));
    const Corba::ThreadCallTimeout timeout(int(qMax<qint64>(1, left)));
    return f();
}

bool samePath(const QString &a, const QString &b)
{
    if (a == b)
        return true;
    const QString canonicalA = QFileInfo(a).canonicalFilePath();
    return !canonicalA.isEmpty() && canonicalA == QFileInfo(b).canonicalFilePath();
}

/// The manager's own explanation of its last refusal (rtmanager's `last_error`), if it has one.
QString lastError(const Corba::ManagerProxy &manager, const QDeadlineTimer &deadline, int timeoutMs,
                  const Error &refusal)
{
    try {
        const QString text = withinDeadline(deadline, timeoutMs, [&] {
            return Corba::propertyValue(manager.profile(), QStringLiteral("last_error"));
        });
        if (!text.isEmpty())
            return text;
    } catch (const Error &) {
        // The refusal itself is still worth showing.
    }
    return refusal.message();
}

bool isLoaded(const Corba::ManagerProxy &manager, const QString &path,
              const QDeadlineTimer &deadline, int timeoutMs)
{
    const auto modules
        = withinDeadline(deadline, timeoutMs, [&] { return manager.loadedModules(); });
    for (const Corba::Properties &module : modules) {
        if (samePath(Corba::propertyValue(module, QStringLiteral("file_path")), path))
            return true;
    }
    return false;
}

QString errorReason(const Error &error, const QString &address, int timeoutMs)
{
    if (isUnreachable(error.kind()))
        return ModuleRun::tr("manager %1 unreachable (%2)").arg(address, error.message());
    if (error.kind() == Error::Kind::Timeout)
        return ModuleRun::tr("manager %1 did not answer within %2 s")
            .arg(address)
            .arg(timeoutMs / 1000.0);
    return error.message();
}

void loadModule(const Corba::ManagerProxy &manager, const ModuleRunRequest &request,
                const QDeadlineTimer &deadline, int timeoutMs, ModuleRunResult &result)
{
    try {
        withinDeadline(deadline, timeoutMs,
                       [&] { manager.loadModule(request.modulePath, request.initFunction); });
    } catch (const Error &refusal) {
        if (refusal.kind() != Error::Kind::Refused)
            throw;
        // A module loaded by an earlier run is refused again; that is what we wanted anyway.
        if (isLoaded(manager, request.modulePath, deadline, timeoutMs)) {
            result.alreadyLoaded = true;
            return;
        }
        throw StepFailure {ModuleRun::tr("load_module refused: %1")
                               .arg(lastError(manager, deadline, timeoutMs, refusal))};
    }
}

void createComponent(const Corba::ManagerProxy &manager, const ModuleRunRequest &request,
                     const QDeadlineTimer &deadline, int timeoutMs, ModuleRunResult &result)
{
    try {
        result.ior = withinDeadline(deadline, timeoutMs,
                                    [&] { return manager.createComponent(request.typeName); });
    } catch (const Error &refusal) {
        if (refusal.kind() != Error::Kind::Refused)
            throw;
        throw StepFailure {ModuleRun::tr("create_component failed: %1")
                               .arg(lastError(manager, deadline, timeoutMs, refusal))};
    }
    result.instanceName = request.typeName;
    try {
        const Corba::ComponentProxy component(result.ior, request.managerAddress);
        result.instanceName
            = withinDeadline(deadline, timeoutMs, [&] { return component.profile().instanceName; });
    } catch (const Error &) {
        // The component exists; only its name is unknown, and the type name stands in for it.
    }
}

} // namespace

QString ModuleRun::managerLocation(const QString &address)
{
    const QString text = address.trimmed();
    if (text.isEmpty())
        return QString();
    const auto location = Corba::RtPath::normaliseCorbaloc(
        text.startsWith(QLatin1String("corbaloc:")) ? text : QStringLiteral("corbaloc::") + text);
    return location.value_or(QString());
}

ModuleRunResult ModuleRun::run(const ModuleRunRequest &request, int timeoutMs)
{
    ModuleRunResult result;
    result.request = request;
    const QString module = QFileInfo(request.modulePath).fileName();
    const auto fail = [&](const QString &reason) {
        result.error
            = tr("Could not run %1 in manager %2: %3").arg(module, request.managerAddress, reason);
        return result;
    };
    const QString location = managerLocation(request.managerAddress);
    if (location.isEmpty())
        return fail(tr("'%1' is not a manager address (host:port)").arg(request.managerAddress));
    if (!QFileInfo(request.modulePath).isFile())
        return fail(tr("no module file %1").arg(request.modulePath));
    const QDeadlineTimer deadline(timeoutMs);
    try {
        const Corba::ManagerProxy manager(location, request.managerAddress);
        loadModule(manager, request, deadline, timeoutMs, result);
        createComponent(manager, request, deadline, timeoutMs, result);
    } catch (const StepFailure &failure) {
        return fail(failure.reason);
    } catch (const Error &error) {
        return fail(errorReason(error, request.managerAddress, timeoutMs));
    } catch (const std::exception &error) {
        // Nothing may leave the worker thread: an exception there would end the application.
        return fail(QString::fromLocal8Bit(error.what()));
    } catch (...) {
        return fail(tr("unexpected error"));
    }
    result.ok = true;
    return result;
}

} // namespace Builder
