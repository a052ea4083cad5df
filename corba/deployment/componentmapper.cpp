// SPDX-License-Identifier: MIT
#include "componentmapper.h"

#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "managerproxy.h"
#include "namingbrowser.h"
#include "rtsprofile.h"

#include <QMutex>
#include <QProcessEnvironment>
#include <QSet>

namespace Deploy {

using Corba::Error;
using Corba::NamingBrowser;
using Corba::NamingNode;
using Corba::NodeType;
using Corba::RtPath;

namespace {

// Deep enough for `server/host_cxt/sub_cxt/Name.rtc` and a manager's components, shallow enough
// that a big name server is walked quickly.
constexpr int searchDepth = 4;

/// Whether two entries found under one instance name are different components bound by name.
bool isClash(const ComponentMapper::LiveEntry &existing, const NamingNode &node)
{
    return !existing.path.contains(QLatin1String(".mgr"))
        && !node.path.contains(QLatin1String(".mgr")) && !existing.ior.isEmpty()
        && !node.ior.isEmpty() && existing.ior != node.ior;
}

void collectComponents(const NamingNode &node, QHash<QString, ComponentMapper::LiveEntry> &found,
                       QStringList *problems)
{
    if (node.type == NodeType::Component && node.name.endsWith(QLatin1String(".rtc"))) {
        const QString instance = node.name.chopped(4);
        const auto existing = found.constFind(instance);
        // The naming-context binding is the path users know; a manager's listing is the fallback.
        if (existing == found.constEnd()
            || (existing->path.contains(QLatin1String(".mgr"))
                && !node.path.contains(QLatin1String(".mgr"))))
            found.insert(instance, {node.path, node.ior});
        else if (problems && isClash(*existing, node))
            // A saved system names its components by instance name only (as RTS profiles do).
            problems->append(
                ComponentMapper::tr("%1: another component is named %2 too (%3); one instance "
                                    "name can stand for one component only")
                    .arg(node.path, instance, existing->path));
    }
    for (const NamingNode &child : node.children)
        collectComponents(child, found, problems);
}

void collectManagers(const NamingNode &node, std::vector<NamingNode> &managers)
{
    if (node.type == NodeType::Manager && node.answering) {
        managers.push_back(node);
        return;
    }
    for (const NamingNode &child : node.children)
        collectManagers(child, managers);
}

/**
 * Components that managers host but no name leads to: each manager's component references are
 * compared with those found by name, and only unknown ones are asked for their instance names.
 */
void addUnnamedComponents(const std::vector<NamingNode> &managers,
                          QHash<QString, ComponentMapper::LiveEntry> &found)
{
    QSet<QString> known;
    for (const ComponentMapper::LiveEntry &entry : std::as_const(found))
        known.insert(entry.ior);
    QMutex mutex;
    Corba::forEachConcurrently(managers.size(), [&](std::size_t m) {
        const NamingNode &manager = managers[m];
        QStringList unnamed;
        try {
            for (const QString &ior : Corba::ManagerProxy(manager.ior, manager.path).components()) {
                if (!known.contains(ior))
                    unnamed.append(ior);
            }
        } catch (const Error &) {
            return; // a manager that does not answer lists nothing, as in the tree
        }
        for (const QString &ior : std::as_const(unnamed)) {
            try {
                const QString instance = Corba::ComponentProxy(ior, manager.path).profile().instanceName;
                QMutexLocker lock(&mutex);
                if (!found.contains(instance))
                    found.insert(instance, {manager.path + QLatin1Char('/') + instance + QStringLiteral(".rtc"), ior});
            } catch (const Error &) {
            }
        }
    });
}

QString firstRate(const Profile::RtsComponent &component)
{
    for (const auto &ec : component.executionContexts) {
        if (ec.rateValue())
            return QString::number(*ec.rateValue());
    }
    return QString();
}

// `hostB` for a pathUri `ns/hostB.host_cxt/X.rtc`.
QString savedHost(const QString &pathUri)
{
    for (const QString &element : pathUri.split(QLatin1Char('/'), Qt::SkipEmptyParts)) {
        if (element.endsWith(QLatin1String(".host_cxt")))
            return element.chopped(int(qstrlen(".host_cxt")));
    }
    return QString();
}

} // namespace

QString mappingKindName(MappingKind kind)
{
    switch (kind) {
    case MappingKind::Existing:
        return QStringLiteral("existing");
    case MappingKind::Create:
        return QStringLiteral("create");
    case MappingKind::Missing:
        break;
    }
    return QStringLiteral("missing");
}

ComponentMapper::ComponentMapper(TargetOptions options)
    : m_options(std::move(options))
{ }

QString ComponentMapper::notFound(const QString &instanceName)
{
    return tr("no live component named %1").arg(instanceName);
}

QString ComponentMapper::typeNameOf(const QString &componentId)
{
    const QStringList parts = componentId.split(QLatin1Char(':'));
    return parts.size() >= 5 && parts.first() == QLatin1String("RTC") ? parts.at(3) : componentId;
}

bool ComponentMapper::isLivePath(const QString &pathUri)
{
    const QString lower = pathUri.toLower();
    if (lower.isEmpty() || lower.startsWith(QLatin1String("file:"))
        || lower.endsWith(QLatin1String(".xml")) || lower.endsWith(QLatin1String(".yaml"))
        || lower.endsWith(QLatin1String(".yml")))
        return false;
    return lower.contains(QLatin1String(".rtc"));
}

QString ComponentMapper::resolveManager(const QString &address)
{
    QString error;
    const auto path = RtPath::parse(address, QStringLiteral("/"), &error);
    if (!path)
        throw Error(Error::Kind::BadPath, QStringLiteral("%1: %2").arg(address, error));
    return NamingBrowser::resolve(*path);
}

QString ComponentMapper::createArgument(const Profile::RtsComponent &component) const
{
    QString argument
        = typeNameOf(component.id) + QStringLiteral("?instance_name=") + component.instanceName;
    const QString rate = firstRate(component);
    if (!rate.isEmpty())
        argument += QStringLiteral("&exec_cxt.periodic.rate=") + rate;
    const QString address = m_options.hostManagers.value(savedHost(component.pathUri));
    if (!address.isEmpty())
        argument += QStringLiteral("&manager_address=") + address;
    return argument;
}

void ComponentMapper::indexServers(const Profile::RtsProfile &profile)
{
    QStringList servers = m_options.nameServers;
    if (servers.isEmpty()) {
        for (const auto &component : profile.components) {
            const auto path = RtPath::parse(QLatin1Char('/') + component.pathUri);
            if (isLivePath(component.pathUri) && path && !path->isDirect()
                && !servers.contains(path->server()))
                servers.append(path->server());
        }
    }
    if (servers.isEmpty())
        servers = NamingBrowser::serversFromEnvironment();
    if (servers.isEmpty())
        servers.append(QStringLiteral("localhost"));
    m_serverPaths.clear();
    for (const QString &server : servers)
        m_serverPaths.append(QLatin1Char('/') + server);
    // Whether each server answers is known now; what they hold is walked only for components
    // their saved paths do not lead to.
    for (const QString &text : std::as_const(m_serverPaths)) {
        try {
            const auto path = RtPath::parse(text);
            if (!path)
                throw Error(Error::Kind::BadPath, text);
            NamingBrowser::tree(*path, 0, {}, NamingBrowser::Check::NamesOnly);
        } catch (const Error &e) {
            m_problems.append(e.message());
        }
    }
}

const QHash<QString, ComponentMapper::LiveEntry> &ComponentMapper::namedIndex()
{
    QMutexLocker lock(&m_indexMutex);
    if (!m_named) {
        m_byInstance = liveComponents(m_serverPaths, nullptr, NamingBrowser::Check::NamesOnly);
        m_named = true;
    }
    return m_byInstance;
}

const QHash<QString, ComponentMapper::LiveEntry> &ComponentMapper::fullIndex()
{
    QMutexLocker lock(&m_indexMutex);
    if (!m_fullIndexed) {
        m_fullIndex = liveComponents(m_serverPaths, nullptr);
        m_fullIndexed = true;
    }
    return m_fullIndex;
}

QHash<QString, ComponentMapper::LiveEntry> ComponentMapper::liveComponents(const QStringList &paths,
                                                                           QStringList *problems,
                                                                           NamingBrowser::Check check)
{
    QHash<QString, LiveEntry> found;
    std::vector<NamingNode> managers;
    for (const QString &text : paths) {
        try {
            QString error;
            const auto path = RtPath::parse(text, QStringLiteral("/"), &error);
            if (!path)
                throw Error(Error::Kind::BadPath, QStringLiteral("%1: %2").arg(text, error));
            // Managers are listed below, asked only about components no name leads to.
            const NamingNode tree = NamingBrowser::tree(
                *path, searchDepth, {},
                check == NamingBrowser::Check::Objects ? NamingBrowser::Check::NamedObjects : check);
            collectComponents(tree, found, problems);
            if (check == NamingBrowser::Check::Objects)
                collectManagers(tree, managers);
        } catch (const Error &e) {
            if (problems)
                problems->append(e.message());
        }
    }
    addUnnamedComponents(managers, found);
    return found;
}

bool ComponentMapper::checkLive(ComponentMapping &mapping, const LiveEntry &entry) const
{
    try {
        const Corba::ComponentInfo info = Corba::ComponentProxy(entry.ior, entry.path).profile();
        if (info.typeName != mapping.typeName) {
            mapping.message = tr("%1 is a %2, the system wants a %3")
                                  .arg(entry.path, info.typeName, mapping.typeName);
            return false;
        }
        mapping.path = entry.path;
        mapping.ior = entry.ior;
        mapping.plannedPorts = info.ports;
        mapping.kind = MappingKind::Existing;
        mapping.message.clear();
        return true;
    } catch (const Error &e) {
        mapping.message = e.message();
        return false;
    }
}

ComponentMapping ComponentMapper::mapOne(const Profile::RtsComponent &component)
{
    ComponentMapping mapping;
    mapping.instanceName = component.instanceName;
    mapping.typeName = typeNameOf(component.id);
    mapping.required = component.isRequiredValue();
    mapping.createArgument = createArgument(component);
    if (isLivePath(component.pathUri)) {
        try {
            const auto path = RtPath::parse(QLatin1Char('/') + component.pathUri);
            if (path) {
                const QString ior = NamingBrowser::resolve(*path);
                if (checkLive(mapping, {path->toString(), ior}))
                    return mapping;
            }
        } catch (const Error &e) {
            mapping.message = e.message();
        }
    }
    const QHash<QString, LiveEntry> &named = namedIndex();
    const auto live = named.constFind(component.instanceName);
    if (live != named.constEnd() && checkLive(mapping, *live))
        return mapping;
    const QHash<QString, LiveEntry> &known = fullIndex();
    const auto listed = known.constFind(component.instanceName);
    if (listed != known.constEnd() && (live == named.constEnd() || listed->path != live->path)
        && checkLive(mapping, *listed))
        return mapping;
    if (mapping.message.isEmpty())
        mapping.message = notFound(component.instanceName);
    if (m_options.create) {
        mapping.manager = m_options.manager;
        // Without -m: the manager registered beside the component's saved name, as rtshell's users expect.
        const int slash = component.pathUri.lastIndexOf(QLatin1Char('/'));
        if (mapping.manager.isEmpty() && isLivePath(component.pathUri) && slash > 0)
            mapping.manager = QLatin1Char('/') + component.pathUri.left(slash) + QStringLiteral("/manager.mgr");
        if (mapping.manager.isEmpty()) {
            mapping.message
                = tr("%1; no manager to create it (give one with -m)").arg(mapping.message);
            return mapping;
        }
        mapping.kind = MappingKind::Create;
        mapping.path = mapping.manager + QLatin1Char('/') + component.instanceName + QStringLiteral(".rtc");
    }
    return mapping;
}

QList<ComponentMapping> ComponentMapper::map(const Profile::RtsProfile &profile)
{
    m_byInstance.clear();
    m_named = false;
    m_fullIndex.clear();
    m_fullIndexed = false;
    m_problems.clear();
    indexServers(profile);
    // Components are looked up independently: several at once.
    QList<ComponentMapping> result(profile.components.size());
    Corba::forEachConcurrently(std::size_t(profile.components.size()), [&](std::size_t i) {
        result[qsizetype(i)] = mapOne(profile.components.at(qsizetype(i)));
    });
    return result;
}

} // namespace Deploy
