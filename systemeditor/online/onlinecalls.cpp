// SPDX-License-Identifier: MIT
#include "onlinecalls.h"

#include "componentproxy.h"
#include "corbaerror.h"
#include "managerproxy.h"
#include "statepoller.h"

namespace SystemEditor::OnlineCalls {

using Corba::LifeCycleState;
using Corba::NamingNode;
using Corba::NodeType;

namespace {

/// The answering components of the tree with references, by path.
void collectComponents(const NamingNode &node, QHash<QString, QString> &iorsByPath)
{
    if (node.type == NodeType::Component && !node.ior.isEmpty() && node.answering)
        iorsByPath.insert(node.path, node.ior);
    for (const NamingNode &child : node.children)
        collectComponents(child, iorsByPath);
}

void fillManagedStates(const NamingNode &node, QHash<QString, LifeCycleState> &states,
                       const QHash<QString, LifeCycleState> &byName)
{
    if (node.type == NodeType::Component && node.ior.isEmpty())
        states.insert(node.path, managedState(node.path, states, byName));
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

LifeCycleState managedState(const QString &path, const QHash<QString, LifeCycleState> &byPath,
                            const QHash<QString, LifeCycleState> &byName)
{
    // `…/context/manager.mgr/Name0.rtc` → `…/context/Name0.rtc`.
    const QString name = path.section(QLatin1Char('/'), -1);
    const QString beside = path.section(QLatin1Char('/'), 0, -3) + QLatin1Char('/') + name;
    const auto found = byPath.find(beside);
    if (found != byPath.end())
        return *found;
    return byName.value(name, LifeCycleState::Unknown);
}

ServerSnapshot fetchServer(const QString &server, Corba::NamingBrowser::Check check)
{
    QString error;
    const auto path = Corba::RtPath::parse(QLatin1Char('/') + server, QString(), &error);
    if (!path)
        throw Corba::Error(Corba::Error::Kind::BadPath, server + QStringLiteral(": ") + error);
    ServerSnapshot snapshot;
    snapshot.server = server;
    snapshot.tree = Corba::NamingBrowser::tree(*path, -1, {}, check);
    if (check == Corba::NamingBrowser::Check::NamesOnly)
        return snapshot;
    QHash<QString, QString> iors;
    collectComponents(snapshot.tree, iors);
    snapshot.states = fetchStates(iors);
    QHash<QString, LifeCycleState> byName;
    collectNamedStates(snapshot.tree, snapshot.states, byName);
    fillManagedStates(snapshot.tree, snapshot.states, byName);
    return snapshot;
}

QHash<QString, LifeCycleState> fetchStates(const QHash<QString, QString> &iorsByPath)
{
    // A component bound under several names is asked once, by its reference.
    QHash<QString, QStringList> pathsByIor;
    for (auto it = iorsByPath.begin(); it != iorsByPath.end(); ++it)
        pathsByIor[it.value()].append(it.key());
    const QStringList iors = pathsByIor.keys();
    QStringList firstPaths;
    for (const QString &ior : iors)
        firstPaths.append(pathsByIor.value(ior).first());
    // One for the process: the online views poll the same components round after round.
    static Corba::StatePoller poller;
    const std::vector<LifeCycleState> found = poller.poll(iors, firstPaths);
    QHash<QString, LifeCycleState> states;
    for (int i = 0; i < iors.size(); ++i) {
        for (const QString &path : pathsByIor.value(iors.at(i)))
            states.insert(path, found[size_t(i)]);
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
