// SPDX-License-Identifier: MIT
#include "namingbrowser.h"

#include "corbacall.h"
#include "managerproxy.h"

#include <Manager.hh>
#include <RTC.hh>
#include <omniORB4/Naming.hh>

#include <QProcessEnvironment>

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

CosNaming::NamingContext_ptr rootContext(const RtPath &path)
{
    const QString target = QLatin1Char('/') + path.server();
    CORBA::Object_var object = toObject(path.nameServiceAddress(), target);
    return call(target, [&] {
        CosNaming::NamingContext_var context = CosNaming::NamingContext::_narrow(object.in());
        if (CORBA::is_nil(context))
            throw Error(Error::Kind::WrongType, target + QStringLiteral(": not a name server"));
        return context._retn();
    });
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

// Decides what a bound object is by asking it; any failure makes it a zombie.
NodeType classify(CORBA::Object_ptr object, const QString &kind, const QString &path,
                  QString *reason)
{
    try {
        return call(path, [&] {
            if (kind == QLatin1String("rtc") || kind == QLatin1String("mgr")) {
                const bool rtc = kind == QLatin1String("rtc");
                if (object->_is_a(rtc ? rtObjectId : managerId))
                    return rtc ? NodeType::Component : NodeType::Manager;
                *reason
                    = QStringLiteral("%1: not an %2")
                          .arg(path,
                               rtc ? QStringLiteral("RTObject") : QStringLiteral("RTM::Manager"));
                return NodeType::Zombie;
            }
            return object->_non_existent() ? NodeType::Zombie : NodeType::Object;
        });
    } catch (const Error &e) {
        *reason = e.message();
        return NodeType::Zombie;
    }
}

NamingNode objectNode(CORBA::Object_ptr object, const QString &name, const QString &path)
{
    NamingNode node;
    node.name = name;
    node.path = path;
    node.type = classify(object, kindOf(name), path, &node.reason);
    node.ior = toIor(object);
    return node;
}

std::vector<NamingNode> listContext(CosNaming::NamingContext_ptr context, const QString &path)
{
    std::vector<NamingNode> nodes;
    CosNaming::BindingList_var bindings;
    CosNaming::BindingIterator_var iterator;
    call(path, [&] { context->list(0, bindings.out(), iterator.out()); });
    bool more = !CORBA::is_nil(iterator);
    while (more) {
        CosNaming::Binding_var binding;
        more = call(path, [&] { return iterator->next_one(binding.out()); });
        if (!more)
            break;
        const QString name = elementName(binding->binding_name[0]);
        const QString childPath
            = path.endsWith(QLatin1Char('/')) ? path + name : path + QLatin1Char('/') + name;
        if (binding->binding_type == CosNaming::ncontext) {
            nodes.push_back({name, NodeType::Context, childPath, {}, {}, {}});
            continue;
        }
        CORBA::Object_var object;
        try {
            object = call(childPath, [&] { return context->resolve(binding->binding_name); });
        } catch (const Error &e) {
            nodes.push_back({name, NodeType::Zombie, childPath, {}, e.message(), {}});
            continue;
        }
        nodes.push_back(objectNode(object.in(), name, childPath));
    }
    if (!CORBA::is_nil(iterator)) {
        try {
            call(path, [&] { iterator->destroy(); });
        } catch (const Error &) {
            // The iterator is the server's to reclaim; failing to destroy it early is harmless.
        }
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
        const QString name = QStringLiteral("slave%1.mgr").arg(index++);
        nodes.push_back({name, NodeType::Manager, path + QLatin1Char('/') + name, slave, {}, {}});
    }
    return nodes;
}

} // namespace

QStringList NamingBrowser::serversFromEnvironment()
{
    QString value
        = QProcessEnvironment::systemEnvironment().value(QStringLiteral("RTCTREE_NAMESERVERS"));
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
    if (path.isRoot()) {
        std::vector<NamingNode> servers;
        for (const QString &server : rootServers)
            servers.push_back({server, NodeType::Server, QLatin1Char('/') + server, {}, {}, {}});
        return servers;
    }
    const NamingNode self = node(path);
    if (self.type == NodeType::Manager)
        return listManager(self.ior, self.path);
    if (self.type != NodeType::Server && self.type != NodeType::Context)
        return {self};
    CosNaming::NamingContext_var root = rootContext(path);
    if (path.names().isEmpty())
        return listContext(root.in(), self.path);
    CORBA::Object_var object = resolveName(path);
    CosNaming::NamingContext_var context
        = call(self.path, [&] { return CosNaming::NamingContext::_narrow(object.in()); });
    return listContext(context.in(), self.path);
}

NamingNode NamingBrowser::node(const RtPath &path)
{
    const QString text = path.withoutPort().toString();
    if (path.isRoot())
        return {QStringLiteral("/"), NodeType::Root, QStringLiteral("/"), {}, {}, {}};
    if (path.isDirect()) {
        CORBA::Object_var object = toObject(path.corbaloc, text);
        return objectNode(object.in(), QStringLiteral("manager.mgr"), text);
    }
    if (path.names().isEmpty()) {
        CosNaming::NamingContext_var root = rootContext(path);
        call(text, [&] { root->_non_existent(); });
        return {path.server(), NodeType::Server, text, {}, {}, {}};
    }
    CORBA::Object_var object = resolveName(path);
    const QString name = path.elements.last();
    const QString kind = kindOf(name);
    if (kind == QLatin1String("rtc") || kind == QLatin1String("mgr"))
        return objectNode(object.in(), name, text);
    bool isContext = false;
    try {
        isContext = call(text, [&] { return object->_is_a(CosNaming::NamingContext::_PD_repoId); });
    } catch (const Error &e) {
        return {name, NodeType::Zombie, text, toIor(object.in()), e.message(), {}};
    }
    if (isContext)
        return {name, NodeType::Context, text, {}, {}, {}};
    return objectNode(object.in(), name, text);
}

NamingNode NamingBrowser::tree(const RtPath &path, int maxDepth, const QStringList &rootServers)
{
    NamingNode root = node(path);
    if (maxDepth == 0)
        return root;
    if (root.type == NodeType::Root || root.type == NodeType::Server
        || root.type == NodeType::Context || root.type == NodeType::Manager) {
        for (NamingNode &child : list(path, rootServers)) {
            // A manager's own children are not bound in the name server; only named nodes recurse.
            const bool named = root.type != NodeType::Manager;
            const bool container = child.type == NodeType::Context || child.type == NodeType::Server
                || child.type == NodeType::Manager;
            const auto childPath = RtPath::parse(child.path);
            if (named && container && childPath) {
                try {
                    child = tree(*childPath, maxDepth - 1);
                } catch (const Error &e) {
                    child.type = NodeType::Zombie;
                    child.reason = e.message();
                }
            }
            root.children.push_back(std::move(child));
        }
    }
    return root;
}

QString NamingBrowser::resolve(const RtPath &path)
{
    CORBA::Object_var object
        = path.isDirect() ? toObject(path.corbaloc, path.corbaloc) : resolveName(path);
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
