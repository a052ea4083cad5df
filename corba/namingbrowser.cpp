// SPDX-License-Identifier: MIT
#include "namingbrowser.h"

#include "concurrent.h"
#include "corbacall.h"
#include "managerproxy.h"

#include <Manager.hh>
#include <RTC.hh>
#include <omniORB4/Naming.hh>

#include <QHash>

#include <mutex>

namespace Corba {

using namespace Internal;

QString nodeTypeName(NodeType type)
{
    switch (type) {
    case NodeType::Root:
        return QStringLiteral("root");
    case NodeType::Server:
        return QStringLiteral("server");
    case NodeType::Context:
        return QStringLiteral("context");
    case NodeType::Component:
        return QStringLiteral("component");
    case NodeType::Manager:
        return QStringLiteral("manager");
    case NodeType::Object:
        return QStringLiteral("object");
    case NodeType::Zombie:
        return QStringLiteral("zombie");
    }
    return QString();
}

namespace {

constexpr const char *rtObjectId = "IDL:omg.org/RTC/RTObject:1.0";
constexpr const char *managerId = "IDL:RTM/Manager:1.0";

CosNaming::Name toName(const QStringList &elements)
{
    CosNaming::Name name;
    name.length(CORBA::ULong(elements.size()));
    for (int i = 0; i < elements.size(); ++i) {
        const QString &element = elements.at(i);
        const int dot = element.lastIndexOf(QLatin1Char('.'));
        const QString id = dot < 0 ? element : element.left(dot);
        const QString kind = dot < 0 ? QString() : element.mid(dot + 1);
        name[CORBA::ULong(i)].id = id.toUtf8().constData();
        name[CORBA::ULong(i)].kind = kind.toUtf8().constData();
    }
    return name;
}

QString elementName(const CosNaming::NameComponent &component)
{
    const QString id = toQString(component.id.in());
    const QString kind = toQString(component.kind.in());
    return kind.isEmpty() ? id : id + QLatin1Char('.') + kind;
}

QString kindOf(const QString &element)
{
    const int dot = element.lastIndexOf(QLatin1Char('.'));
    return dot < 0 ? QString() : element.mid(dot + 1);
}

/**
 * Root contexts already known to be name servers, by address. Narrowing a corbaloc reference asks
 * the server (_is_a), and planning a large system resolves one name per component: the answer is
 * kept. A name server started again at the same address is reached through the same reference.
 */
class RootContexts
{
public:
    CosNaming::NamingContext_ptr find(const QString &address)
    {
        std::lock_guard lock(m_mutex);
        const auto found = m_contexts.constFind(address);
        return found == m_contexts.constEnd() ? CosNaming::NamingContext::_nil()
                                              : CosNaming::NamingContext::_duplicate(found->in());
    }
    void insert(const QString &address, CosNaming::NamingContext_ptr context)
    {
        std::lock_guard lock(m_mutex);
        if (m_contexts.size() >= 64) // a long-running GUI meets many addresses over time
            m_contexts.clear();
        m_contexts.insert(address, CosNaming::NamingContext::_duplicate(context));
    }

private:
    std::mutex m_mutex;
    QHash<QString, CosNaming::NamingContext_var> m_contexts;
};

CosNaming::NamingContext_ptr rootContext(const RtPath &path)
{
    // Never destroyed: the ORB lives as long as the process, and so may its references.
    static auto *const known = new RootContexts;
    const QString address = path.nameServiceAddress();
    CosNaming::NamingContext_var context = known->find(address);
    if (!CORBA::is_nil(context))
        return context._retn();
    const QString target = QLatin1Char('/') + path.server();
    CORBA::Object_var object = toObject(address, target);
    context = call(target, [&] {
        CosNaming::NamingContext_var narrowed = CosNaming::NamingContext::_narrow(object.in());
        if (CORBA::is_nil(narrowed))
            throw Error(Error::Kind::WrongType, target + QStringLiteral(": not a name server"));
        return narrowed._retn();
    });
    known->insert(address, context.in());
    return context._retn();
}

CORBA::Object_ptr resolveName(const RtPath &path)
{
    CosNaming::NamingContext_var root = rootContext(path);
    return call(path.withoutPort().toString(), [&] {
        try {
            return root->resolve(toName(path.names()));
        } catch (const CosNaming::NamingContext::NotFound &) {
            throw Error(Error::Kind::NotFound,
                        path.withoutPort().toString() + QStringLiteral(": no such name"));
        }
    });
}

/**
 * The object at @p path. Names resolve through the name server up to the first manager that is not
 * the last element; below a manager, `Name.rtc` is one of its components and `slaveN.mgr` its Nth
 * slave, as listManager() lists them (rtshell's tree offers the same paths).
 */
CORBA::Object_ptr resolveObject(const RtPath &path)
{
    const QStringList names = path.names();
    qsizetype managerAt = -1;
    for (qsizetype i = 0; i + 1 < names.size() && managerAt < 0; ++i) {
        if (kindOf(names.at(i)) == QLatin1String("mgr"))
            managerAt = i;
    }
    if (managerAt < 0)
        return resolveName(path);
    RtPath managerPath = path.withoutPort();
    managerPath.elements = path.elements.mid(0, managerAt + 2);
    CORBA::Object_var first = resolveName(managerPath);
    QString ior = toIor(first.in());
    QString at = managerPath.toString();
    for (qsizetype i = managerAt + 1; i < names.size(); ++i) {
        const QString &name = names.at(i);
        const QString below = at + QLatin1Char('/') + name;
        const ManagerProxy manager(ior, at);
        QString found;
        if (kindOf(name) == QLatin1String("mgr")) {
            const QStringList slaves = manager.slaveManagers();
            for (qsizetype k = 0; k < slaves.size() && found.isEmpty(); ++k) {
                if (ManagerProxy::slaveName(int(k)) == name)
                    found = slaves.at(k);
            }
        } else if (kindOf(name) == QLatin1String("rtc") && i + 1 == names.size()) {
            // A master lists its slaves' components with its own, but by name it answers for its
            // own only (OpenRTM-aist's and rtmanager alike): the slaves are asked next.
            const QString instance = name.chopped(4);
            found = manager.componentsByName(instance).value(0);
            const QStringList slaves = found.isEmpty() ? manager.slaveManagers() : QStringList();
            for (qsizetype k = 0; k < slaves.size() && found.isEmpty(); ++k)
                found = ManagerProxy(slaves.at(k), at + QLatin1Char('/') + ManagerProxy::slaveName(int(k)))
                            .componentsByName(instance)
                            .value(0);
        }
        if (found.isEmpty())
            throw Error(Error::Kind::NotFound, below + QStringLiteral(": no such name"));
        ior = found;
        at = below;
    }
    return toObject(ior, at);
}

/// What a bound object is taken to be before it is asked: its name's kind says it.
NodeType typeByName(const QString &kind)
{
    if (kind == QLatin1String("rtc"))
        return NodeType::Component;
    if (kind == QLatin1String("mgr"))
        return NodeType::Manager;
    return NodeType::Object;
}

/**
 * Decides what a bound object is by asking it. One that does not answer within the call timeout
 * keeps the type its name gives and is marked as not answering (it may be stopped or busy);
 * any other failure makes it a zombie.
 */
void classify(CORBA::Object_ptr object, NamingNode *node)
{
    const QString kind = kindOf(node->name);
    try {
        node->type = call(node->path, [&] {
            if (kind == QLatin1String("rtc") || kind == QLatin1String("mgr")) {
                const bool rtc = kind == QLatin1String("rtc");
                if (object->_is_a(rtc ? rtObjectId : managerId))
                    return rtc ? NodeType::Component : NodeType::Manager;
                node->reason
                    = QStringLiteral("%1: not an %2")
                          .arg(node->path,
                               rtc ? QStringLiteral("RTObject") : QStringLiteral("RTM::Manager"));
                return NodeType::Zombie;
            }
            return object->_non_existent() ? NodeType::Zombie : NodeType::Object;
        });
    } catch (const Error &e) {
        node->reason = e.message();
        if (e.kind() == Error::Kind::Timeout) {
            node->type = typeByName(kind);
            node->answering = false;
        } else {
            node->type = NodeType::Zombie;
        }
    }
}

NamingNode objectNode(CORBA::Object_ptr object, const QString &name, const QString &path,
                      NamingBrowser::Check check)
{
    NamingNode node;
    node.name = name;
    node.path = path;
    node.type = typeByName(kindOf(name));
    node.ior = toIor(object);
    if (check != NamingBrowser::Check::NamesOnly)
        classify(object, &node);
    return node;
}

/// How many bindings one list() or next_n() call brings (a large context costs a few calls).
constexpr CORBA::ULong ListBatch = 1000;

/**
 * The bindings of a context. The name server is asked for them in batches and for the bound
 * objects several at once; then, when checking, every bound object is asked what it is, all at
 * once, so that objects that hang cost one call timeout together and never hold back the others.
 */
std::vector<NamingNode> listContext(CosNaming::NamingContext_ptr context, const QString &path,
                                    NamingBrowser::Check check)
{
    std::vector<CosNaming::Binding> bindings;
    {
        CosNaming::BindingList_var batch;
        CosNaming::BindingIterator_var iterator;
        call(path, [&] { context->list(ListBatch, batch.out(), iterator.out()); });
        for (bool more = true; more;) {
            for (CORBA::ULong i = 0; i < batch->length(); ++i)
                bindings.push_back(batch[i]);
            more = !CORBA::is_nil(iterator)
                && call(path, [&] { return iterator->next_n(ListBatch, batch.out()); });
        }
        if (!CORBA::is_nil(iterator)) {
            try {
                call(path, [&] { iterator->destroy(); });
            } catch (const Error &) {
                // The iterator is the server's to reclaim; failing to destroy it early is harmless.
            }
        }
    }
    std::vector<NamingNode> nodes(bindings.size());
    std::vector<CORBA::Object_var> objects(bindings.size());
    std::vector<std::size_t> bound; // indices of object bindings
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        const QString name = elementName(bindings[i].binding_name[0]);
        const QString childPath
            = path.endsWith(QLatin1Char('/')) ? path + name : path + QLatin1Char('/') + name;
        nodes[i] = {name, NodeType::Context, childPath, {}, {}, {}};
        if (bindings[i].binding_type != CosNaming::ncontext)
            bound.push_back(i);
    }
    forEachConcurrently(bound.size(), [&](std::size_t k) {
        const std::size_t i = bound[k];
        const QString name = nodes[i].name;
        const QString childPath = nodes[i].path;
        try {
            objects[i] = call(childPath, [&] { return context->resolve(bindings[i].binding_name); });
            nodes[i] = objectNode(objects[i].in(), name, childPath, NamingBrowser::Check::NamesOnly);
        } catch (const Error &e) {
            nodes[i] = {name, NodeType::Zombie, childPath, {}, e.message(), {}};
        }
    });
    if (check != NamingBrowser::Check::NamesOnly) {
        forEachConcurrently(bound.size(), [&](std::size_t k) {
            const std::size_t i = bound[k];
            if (!CORBA::is_nil(objects[i]))
                classify(objects[i].in(), &nodes[i]);
        });
    }
    return nodes;
}

std::vector<NamingNode> listManager(const QString &ior, const QString &path)
{
    std::vector<NamingNode> nodes;
    ManagerProxy manager(ior, path);
    for (const ComponentInfo &component : manager.componentProfiles()) {
        const QString name = component.instanceName + QStringLiteral(".rtc");
        nodes.push_back({name, NodeType::Component, path + QLatin1Char('/') + name, {}, {}, {}});
    }
    int index = 0;
    for (const QString &slave : manager.slaveManagers()) {
        const QString name = ManagerProxy::slaveName(index++);
        nodes.push_back({name, NodeType::Manager, path + QLatin1Char('/') + name, slave, {}, {}});
    }
    return nodes;
}

/// The children of the node `self` at `path` (see NamingBrowser::list()).
std::vector<NamingNode> childrenOf(const NamingNode &self, const RtPath &path,
                                   const QStringList &rootServers, NamingBrowser::Check check)
{
    if (path.isRoot()) {
        std::vector<NamingNode> servers;
        for (const QString &server : rootServers)
            servers.push_back({server, NodeType::Server, QLatin1Char('/') + server, {}, {}, {}});
        return servers;
    }
    if (self.type == NodeType::Manager)
        return self.answering ? listManager(self.ior, self.path) : std::vector<NamingNode>();
    if (self.type != NodeType::Server && self.type != NodeType::Context)
        return {self};
    CosNaming::NamingContext_var root = rootContext(path);
    if (path.names().isEmpty())
        return listContext(root.in(), self.path, check);
    CORBA::Object_var object = resolveName(path);
    CosNaming::NamingContext_var context
        = call(self.path, [&] { return CosNaming::NamingContext::_narrow(object.in()); });
    return listContext(context.in(), self.path, check);
}

NamingNode nodeAt(const RtPath &path, NamingBrowser::Check check)
{
    const QString text = path.withoutPort().toString();
    if (path.isRoot())
        return {QStringLiteral("/"), NodeType::Root, QStringLiteral("/"), {}, {}, {}};
    if (path.isDirect()) {
        CORBA::Object_var object = toObject(path.corbaloc, text);
        return objectNode(object.in(), QStringLiteral("manager.mgr"), text, check);
    }
    if (path.names().isEmpty()) {
        CosNaming::NamingContext_var root = rootContext(path);
        call(text, [&] { root->_non_existent(); });
        return {path.server(), NodeType::Server, text, {}, {}, {}};
    }
    CORBA::Object_var object = resolveObject(path);
    const QString name = path.elements.last();
    const QString kind = kindOf(name);
    if (kind == QLatin1String("rtc") || kind == QLatin1String("mgr"))
        return objectNode(object.in(), name, text, check);
    bool isContext = false;
    try {
        isContext = call(text, [&] { return object->_is_a(CosNaming::NamingContext::_PD_repoId); });
    } catch (const Error &e) {
        return {name, NodeType::Zombie, text, toIor(object.in()), e.message(), {}};
    }
    if (isContext)
        return {name, NodeType::Context, text, {}, {}, {}};
    return objectNode(object.in(), name, text, check);
}

/// Fills in the children of `node` (at `path`) down to `depth` levels. A manager's slaves are listed
/// below it, with their components; slaves are not asked for slaves of their own (@p belowManager),
/// so that two managers naming each other cannot make the walk endless.
void grow(NamingNode &node, const RtPath &path, int depth, const QStringList &rootServers,
          NamingBrowser::Check check, bool belowManager = false)
{
    if (depth == 0)
        return;
    if (node.type != NodeType::Root && node.type != NodeType::Server
        && node.type != NodeType::Context && node.type != NodeType::Manager)
        return;
    node.children = childrenOf(node, path, rootServers, check);
    if (belowManager)
        return;
    std::vector<NamingNode *> managers;
    for (NamingNode &child : node.children) {
        const auto childPath = RtPath::parse(child.path);
        if (!childPath)
            continue;
        if (child.type == NodeType::Manager) {
            managers.push_back(&child);
            continue;
        }
        if (child.type != NodeType::Context && child.type != NodeType::Server)
            continue;
        try {
            grow(child, *childPath, depth - 1, {}, check);
        } catch (const Error &e) {
            child.type = NodeType::Zombie;
            child.reason = e.message();
        }
    }
    // Managers are asked for their components only when checking, and all at once.
    if (check != NamingBrowser::Check::Objects || depth == 1)
        return;
    const bool slaves = node.type == NodeType::Manager;
    forEachConcurrently(managers.size(), [&](std::size_t i) {
        NamingNode &manager = *managers[i];
        try {
            grow(manager, *RtPath::parse(manager.path), depth - 1, {}, check, slaves);
        } catch (const Error &e) {
            manager.reason = e.message();
            if (e.kind() == Error::Kind::Timeout)
                manager.answering = false;
            else
                manager.type = NodeType::Zombie;
        }
    });
}

} // namespace

QStringList NamingBrowser::serversFromEnvironment()
{
    QString value = qEnvironmentVariable("RTCTREE_NAMESERVERS");
    value.replace(QLatin1Char(','), QLatin1Char(';'));
    QStringList servers;
    for (const QString &server : value.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        if (!server.trimmed().isEmpty())
            servers.append(server.trimmed());
    }
    return servers;
}

std::vector<NamingNode> NamingBrowser::list(const RtPath &path, const QStringList &rootServers)
{
    return childrenOf(nodeAt(path, Check::Objects), path, rootServers, Check::Objects);
}

NamingNode NamingBrowser::node(const RtPath &path)
{
    return nodeAt(path, Check::Objects);
}

NamingNode NamingBrowser::tree(const RtPath &path, int maxDepth, const QStringList &rootServers,
                               Check check)
{
    NamingNode root = nodeAt(path, check);
    grow(root, path, maxDepth, rootServers, check);
    return root;
}

QString NamingBrowser::resolve(const RtPath &path)
{
    CORBA::Object_var object
        = path.isDirect() ? toObject(path.corbaloc, path.corbaloc) : resolveObject(path);
    return toIor(object.in());
}

void NamingBrowser::bind(const RtPath &path, const QString &ior)
{
    CosNaming::NamingContext_var root = rootContext(path);
    CORBA::Object_var object = toObject(ior, path.toString());
    call(path.toString(), [&] {
        try {
            root->rebind(toName(path.names()), object.in());
        } catch (const CosNaming::NamingContext::NotFound &) {
            throw Error(Error::Kind::NotFound,
                        path.toString() + QStringLiteral(": naming context does not exist"));
        }
    });
}

void NamingBrowser::unbind(const RtPath &path)
{
    CosNaming::NamingContext_var root = rootContext(path);
    call(path.toString(), [&] {
        try {
            root->unbind(toName(path.names()));
        } catch (const CosNaming::NamingContext::NotFound &) {
            throw Error(Error::Kind::NotFound, path.toString() + QStringLiteral(": no such name"));
        }
    });
}

} // namespace Corba
