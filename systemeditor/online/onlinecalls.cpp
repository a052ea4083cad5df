// SPDX-License-Identifier: MIT
#include "onlinecalls.h"

#include "componentproxy.h"
#include "corbaerror.h"
#include "managerproxy.h"

namespace SystemEditor::OnlineCalls {

using Corba::LifeCycleState;
using Corba::NamingNode;
using Corba::NodeType;

namespace {

void collectStates(const NamingNode &node, QHash<QString, LifeCycleState> &states)
{
    if (node.type == NodeType::Component) {
        try {
            states.insert(node.path, Corba::ComponentProxy(node.ior, node.path).state());
        } catch (const Corba::Error &) {
            // One silent component must not hide the rest of the tree.
            states.insert(node.path, LifeCycleState::Unknown);
        }
    }
    // A manager lists its components again below itself; their states are taken where they are
    // bound in the naming tree.
    if (node.type == NodeType::Manager)
        return;
    for (const NamingNode &child : node.children)
        collectStates(child, states);
}

} // namespace

ServerSnapshot fetchServer(const QString &server)
{
    QString error;
    const auto path = Corba::RtPath::parse(QLatin1Char('/') + server, QString(), &error);
    if (!path)
        throw Corba::Error(Corba::Error::Kind::BadPath, server + QStringLiteral(": ") + error);
    ServerSnapshot snapshot;
    snapshot.server = server;
    snapshot.tree = Corba::NamingBrowser::tree(*path);
    collectStates(snapshot.tree, snapshot.states);
    return snapshot;
}

QHash<QString, LifeCycleState> fetchStates(const QHash<QString, QString> &iorsByPath)
{
    QHash<QString, LifeCycleState> states;
    for (auto it = iorsByPath.begin(); it != iorsByPath.end(); ++it) {
        try {
            states.insert(it.key(), Corba::ComponentProxy(it.value(), it.key()).state());
        } catch (const Corba::Error &) {
            states.insert(it.key(), LifeCycleState::Unknown);
        }
    }
    return states;
}

void perform(RemoteAction action, const QString &path, const QString &ior)
{
    const Corba::ComponentProxy component(ior, path);
    const Corba::ManagerProxy manager(ior, path);
    switch (action) {
    case RemoteAction::Activate:
        return component.activate();
    case RemoteAction::Deactivate:
        return component.deactivate();
    case RemoteAction::Reset:
        return component.reset();
    case RemoteAction::Exit:
        return component.exit();
    case RemoteAction::Shutdown:
        return manager.shutdown();
    case RemoteAction::Restart:
        return manager.restart();
    case RemoteAction::Unbind: {
        const auto parsed = Corba::RtPath::parse(path);
        if (!parsed)
            throw Corba::Error(Corba::Error::Kind::BadPath, path);
        return Corba::NamingBrowser::unbind(*parsed);
    }
    }
}

} // namespace SystemEditor::OnlineCalls
