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

// States by path; a component listed twice (in its naming context and below its manager) is
// asked once, by its object reference.
void collectStates(const NamingNode &node, QHash<QString, LifeCycleState> &states,
                   QHash<QString, LifeCycleState> &byIor)
{
    // A manager lists its components by profile, without references: their states are taken
    // from the same instance bound in the naming tree (see fillManagedStates()).
    if (node.type == NodeType::Component && !node.ior.isEmpty()) {
        auto known = byIor.find(node.ior);
        if (known == byIor.end()) {
            LifeCycleState state = LifeCycleState::Unknown;
            try {
                state = Corba::ComponentProxy(node.ior, node.path).state();
            } catch (const Corba::Error &) {
                // One silent component must not hide the rest of the tree.
            }
            known = byIor.insert(node.ior, state);
        }
        states.insert(node.path, *known);
    }
    for (const NamingNode &child : node.children)
        collectStates(child, states, byIor);
}

void fillManagedStates(const NamingNode &node, QHash<QString, LifeCycleState> &states,
                       const QHash<QString, LifeCycleState> &byName)
{
    if (node.type == NodeType::Component && node.ior.isEmpty())
        states.insert(node.path, byName.value(node.name, LifeCycleState::Unknown));
    for (const NamingNode &child : node.children)
        fillManagedStates(child, states, byName);
}

void collectNamedStates(const NamingNode &node, const QHash<QString, LifeCycleState> &states,
                        QHash<QString, LifeCycleState> &byName)
{
    if (node.type == NodeType::Component && !node.ior.isEmpty())
        byName.insert(node.name, states.value(node.path, LifeCycleState::Unknown));
    for (const NamingNode &child : node.children)
        collectNamedStates(child, states, byName);
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
    QHash<QString, LifeCycleState> byIor;
    collectStates(snapshot.tree, snapshot.states, byIor);
    QHash<QString, LifeCycleState> byName;
    collectNamedStates(snapshot.tree, snapshot.states, byName);
    fillManagedStates(snapshot.tree, snapshot.states, byName);
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

ExecutionContexts fetchContexts(const QString &path, const QString &ior)
{
    return Corba::ComponentProxy(ior, path).executionContexts(
        Corba::ComponentProxy::ContextDetail::Members);
}

void attachContext(const QString &path, const QString &ior, const QString &contextIor)
{
    Corba::ComponentProxy(ior, path).attachContext(contextIor);
}

void detachContext(const QString &path, const QString &ior, const QString &contextIor)
{
    Corba::ComponentProxy(ior, path).detachContext(contextIor);
}

} // namespace SystemEditor::OnlineCalls
