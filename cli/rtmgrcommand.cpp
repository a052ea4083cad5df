// SPDX-License-Identifier: MIT
#include "rtmgrcommand.h"

#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "managerproxy.h"
#include "rtjson.h"

#include <QFileInfo>
#include <QSet>

#include <optional>
#include <vector>

namespace Cli {

using namespace Corba;

namespace {

// rtshell's flags, mapped onto the action words.
QString actionOfFlag(const QString &flag)
{
    if (flag == QLatin1String("-l"))
        return QStringLiteral("load");
    if (flag == QLatin1String("-u"))
        return QStringLiteral("unload");
    if (flag == QLatin1String("-c"))
        return QStringLiteral("create");
    if (flag == QLatin1String("-d"))
        return QStringLiteral("delete");
    // --json, --timeout and the other options are settings, not actions.
    return QString();
}

/// The value of @p key in a create request's query (`Type?key=value&…`); empty when not given.
QString requestParameter(const QString &request, QLatin1String key)
{
    const QString query = request.section(QLatin1Char('?'), 1);
    for (const QString &pair : query.split(QLatin1Char('&'))) {
        if (pair.section(QLatin1Char('='), 0, 0).trimmed() == key)
            return pair.section(QLatin1Char('='), 1).trimmed();
    }
    return {};
}

/// The instance_name a create request asks for; empty when the manager is to choose one.
QString requestedInstanceName(const QString &request)
{
    return requestParameter(request, QLatin1String("instance_name"));
}

/// Whether the addressed manager hosts the component itself (no slave named or addressed).
bool hostedByAddressedManager(const QString &request)
{
    return requestParameter(request, QLatin1String("manager_name")).isEmpty()
        && requestParameter(request, QLatin1String("manager_address")).isEmpty();
}

/// How many of the actions from @p first on are creates the addressed manager hosts itself.
qsizetype createsHostedHere(const QList<QPair<QString, QString>> &actions, qsizetype first)
{
    qsizetype end = first;
    while (end < actions.size() && actions.at(end).first == QLatin1String("create")
           && hostedByAddressedManager(actions.at(end).second))
        ++end;
    return end - first;
}

/**
 * How many of the actions from @p first on are creates that can run side by side: each names its
 * own instance, and no two the same name. Creates the manager names (`Type0`, `Type1` …) stay in
 * order, so that the numbers come out as they would one after the other.
 */
qsizetype concurrentCreates(const QList<QPair<QString, QString>> &actions, qsizetype first)
{
    QSet<QString> names;
    qsizetype end = first;
    while (end < actions.size() && actions.at(end).first == QLatin1String("create")) {
        const QString name = requestedInstanceName(actions.at(end).second);
        if (name.isEmpty() || names.contains(name))
            break;
        names.insert(name);
        ++end;
    }
    return end - first;
}

} // namespace

QString RtMgrCommand::summary() const
{
    return QStringLiteral("load modules, create and delete components through a manager");
}

QString RtMgrCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl mgr [--json] [--timeout MS] PATH|corbaloc::HOST[:PORT] ACTION...\n\n"
        "Drives an RTC manager (rtshell's rtmgr), given as a tree path (…/manager.mgr, a slave\n"
        "of it as …/manager.mgr/slave0.mgr) or directly (corbaloc::host, port 2810 and key\n"
        "'manager' by default). Actions run in order and stop at the first failure. An\n"
        "rtmanager gets consecutive creates it hosts itself in one call, and consecutive creates\n"
        "in slaves that each give their own instance_name side by side (printed in order; those\n"
        "after a failed one are removed again):\n"
        "  load FILE[:INIT]     load a module (INIT defaults to <basename>Init)\n"
        "  unload FILE          unload a module\n"
        "  create 'Type?k=v&…'  create a component; prints its instance name\n"
        "  delete NAME          delete the component with that instance name (a master's\n"
        "                       slave that hosts it deletes it)\n"
        "  list                 components, loaded modules and factories (--json: one object)\n"
        "  fork                 start a new slave manager process registered with the master\n"
        "  restart              finalise the components and run the manager process again\n"
        "rtshell's -l FILE:INIT, -u FILE, -c MODULE, -d NAME are accepted too (run before "
        "words).\n");
}

QStringList RtMgrCommand::optionNames() const
{
    return {QStringLiteral("-l"), QStringLiteral("-u"), QStringLiteral("-c"), QStringLiteral("-d")};
}

void RtMgrCommand::list(const ManagerProxy &manager, bool json, Streams streams) const
{
    QJsonArray components, loaded, factories;
    for (const ComponentInfo &component : manager.componentProfiles())
        components.append(QJsonObject {{"instanceName", component.instanceName},
                                       {"typeName", component.typeName}});
    for (const Properties &module : manager.loadedModules())
        loaded.append(propertiesToJson(module));
    for (const Properties &factory : manager.factoryProfiles())
        factories.append(propertyValue(factory, QStringLiteral("implementation_id")));
    if (json) {
        streams.out << jsonText(QJsonObject {
            {"components", components}, {"loadedModules", loaded}, {"factories", factories}});
        return;
    }
    streams.out << "Components:\n";
    for (const QJsonValue &c : std::as_const(components))
        streams.out << "  " << c[QStringLiteral("instanceName")].toString() << "  "
                    << c[QStringLiteral("typeName")].toString() << '\n';
    streams.out << "Loaded modules:\n";
    for (const QJsonValue &m : std::as_const(loaded)) {
        const QJsonObject module = m.toObject();
        streams.out << "  " << module.value(QStringLiteral("file_path")).toString() << '\n';
    }
    streams.out << "Factories:\n";
    for (const QJsonValue &f : std::as_const(factories))
        streams.out << "  " << f.toString() << '\n';
}

void RtMgrCommand::run(const ManagerProxy &manager, const QString &action, const QString &argument,
                       bool json, Streams streams) const
{
    if (action == QLatin1String("list")) {
        list(manager, json, streams);
    } else if (action == QLatin1String("fork")) {
        manager.fork();
    } else if (action == QLatin1String("restart")) {
        manager.restart();
    } else if (action == QLatin1String("load")) {
        const int colon = argument.lastIndexOf(QLatin1Char(':'));
        const QString file = colon < 0 ? argument : argument.left(colon);
        const QString init = colon < 0 ? QFileInfo(file).baseName() + QStringLiteral("Init")
                                       : argument.mid(colon + 1);
        manager.loadModule(file, init);
    } else if (action == QLatin1String("unload")) {
        manager.unloadModule(argument);
    } else if (action == QLatin1String("create")) {
        const QString ior = manager.createComponent(argument);
        streams.out << ComponentProxy(ior, manager.path()).profile().instanceName << '\n';
    } else {
        deleteComponent(manager, argument, streams);
    }
}

void RtMgrCommand::deleteComponent(const ManagerProxy &manager, const QString &instanceName,
                                   Streams streams) const
{
    const QString by = manager.deleteComponent(instanceName);
    if (by != manager.path())
        streams.err << "rtctl mgr: " << instanceName << " deleted by " << by << '\n';
}

int RtMgrCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.isEmpty())
        return usageError(QStringLiteral("missing manager PATH or corbaloc"), streams);
    QList<QPair<QString, QString>> actions;
    for (const auto &flag : options.sequence) {
        const QString action = actionOfFlag(flag.first);
        if (!action.isEmpty())
            actions.append({action, flag.second});
    }
    const QStringList words = options.positionals.mid(1);
    for (int i = 0; i < words.size(); ++i) {
        const QString &word = words.at(i);
        if (QStringList {"list", "fork", "restart"}.contains(word)) {
            actions.append({word, QString()});
        } else if (QStringList {"load", "unload", "create", "delete"}.contains(word)) {
            if (i + 1 >= words.size())
                return usageError(QStringLiteral("'%1' needs an argument").arg(word), streams);
            actions.append({word, words.at(++i)});
        } else {
            return usageError(QStringLiteral("unknown action '%1'").arg(word), streams);
        }
    }
    if (actions.isEmpty())
        actions.append({QStringLiteral("list"), QString()});
    const ManagerProxy manager = managerAt(options.positionals.first());
    std::optional<bool> sideBySide; // asked once, when there is something to send side by side
    bool inOneCall = true; // until the manager turns out not to take creates in one call
    for (qsizetype i = 0; i < actions.size();) {
        const qsizetype hostedHere = createsHostedHere(actions, i);
        if (hostedHere > 1 && inOneCall) {
            if (createInOneCall(manager, actions.mid(i, hostedHere), streams)) {
                i += hostedHere;
                continue;
            }
            // Not an rtmanager (OpenRTM-aist's): it does not create side by side either.
            inOneCall = false;
            sideBySide = false;
        }
        qsizetype creates = concurrentCreates(actions, i);
        if (creates > 1 && !sideBySide) {
            sideBySide = propertyValue(manager.profile(), QStringLiteral("rtstudio.concurrent_create"))
                         == QLatin1String("YES");
        }
        if (!sideBySide.value_or(false))
            creates = 0;
        if (creates > 1) {
            createSideBySide(manager, actions.mid(i, creates), streams);
            i += creates;
        } else {
            run(manager, actions.at(i).first, actions.at(i).second, options.has(QStringLiteral("--json")),
                streams);
            ++i;
        }
    }
    return ExitOk;
}

bool RtMgrCommand::createInOneCall(const ManagerProxy &manager,
                                   const QList<QPair<QString, QString>> &creates,
                                   Streams streams) const
{
    QStringList requests;
    for (const auto &create : creates)
        requests.append(create.second);
    const std::optional<ManagerProxy::Created> created = manager.createComponents(requests);
    if (!created)
        return false;
    for (qsizetype i = 0; i < created->iors.size(); ++i) {
        // An rtmanager gives the instance the name asked for; one it numbers itself is asked.
        const QString name = requestedInstanceName(requests.at(i));
        streams.out
            << (name.isEmpty()
                    ? ComponentProxy(created->iors.at(i), manager.path()).profile().instanceName
                    : name)
            << '\n';
    }
    if (!created->refusal.isEmpty())
        throw Error(Error::Kind::Refused, created->refusal);
    return true;
}

void RtMgrCommand::createSideBySide(const ManagerProxy &manager, const QList<QPair<QString, QString>> &creates,
                                    Streams streams) const
{
    const auto count = std::size_t(creates.size());
    std::vector<QString> created(count);
    std::vector<QString> iors(count);
    std::vector<std::optional<Error>> failures(count);
    forEachConcurrently(count, [&](std::size_t i) {
        try {
            // An rtmanager gives the instance the name asked for or refuses the request, so the
            // name needs no further call to the new component.
            iors[i] = manager.createComponent(creates.at(qsizetype(i)).second);
            created[i] = requestedInstanceName(creates.at(qsizetype(i)).second);
        } catch (const Error &e) {
            failures[i].emplace(e);
        }
    });
    for (std::size_t i = 0; i < count; ++i) {
        if (!failures[i]) {
            streams.out << created[i] << '\n';
            continue;
        }
        // One after the other, the creates after this one would not have been made. The component
        // itself is asked to go: it may live in a slave process the manager does not delete in.
        for (std::size_t later = i + 1; later < count; ++later) {
            if (iors[later].isEmpty())
                continue;
            try {
                ComponentProxy(iors[later], manager.path()).exit();
            } catch (const Error &e) {
                streams.err << "rtctl: " << e.message() << '\n';
            }
        }
        throw *failures[i];
    }
}

} // namespace Cli
