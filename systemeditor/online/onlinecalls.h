// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "namingbrowser.h"

#include <QHash>
#include <QMetaType>
#include <QString>

#include <vector>

namespace SystemEditor {

/// Component states by path.
using ComponentStates = QHash<QString, Corba::LifeCycleState>;
/// The execution contexts of one component, owned ones first.
using ExecutionContexts = std::vector<Corba::ExecutionContextInfo>;

/// One name server as the worker saw it: its tree and the state of every component in it.
struct ServerSnapshot
{
    QString server;
    Corba::NamingNode tree;
    QHash<QString, Corba::LifeCycleState> states; ///< by component path
};

/// What a user can ask of a live component or manager from the online views.
enum class RemoteAction { Activate, Deactivate, Reset, Exit, Shutdown, Restart, Unbind };

/**
 * Remote calls of the online views. Each function blocks on the network and throws Corba::Error,
 * so it must only run inside an OnlineService (worker thread), never in the GUI thread.
 */
namespace OnlineCalls {

/**
 * The tree below `server` (`host:port`). With Check::Objects, objects are asked what they are and
 * components for their states, all at once (one that does not answer is Unknown and marked as
 * not answering); with Check::NamesOnly only the name server is asked, which is quick whatever
 * the objects do, and there are no states.
 */
ServerSnapshot fetchServer(const QString &server,
                           Corba::NamingBrowser::Check check = Corba::NamingBrowser::Check::Objects);
/**
 * The state shown for a component listed below its manager (at `path`, which carries no
 * reference): that of the component of the same name bound in the manager's own naming context,
 * else of any bound one of that name (`byName`), else Unknown.
 */
Corba::LifeCycleState managedState(const QString &path, const QHash<QString, Corba::LifeCycleState> &byPath,
                                   const QHash<QString, Corba::LifeCycleState> &byName);
/// The states of the given components (path → IOR); Unknown for those that do not answer.
QHash<QString, Corba::LifeCycleState> fetchStates(const QHash<QString, QString> &iorsByPath);
/// Performs `action` on the object at `path` with reference `ior`.
void perform(RemoteAction action, const QString &path, const QString &ior);
/// The execution contexts of the component at `path` with their owners and participants.
ExecutionContexts fetchContexts(const QString &path, const QString &ior);
/// Makes the component at `path` take part in the execution context `contextIor`.
void attachContext(const QString &path, const QString &ior, const QString &contextIor);
/// Takes the component at `path` out of the execution context `contextIor`.
void detachContext(const QString &path, const QString &ior, const QString &contextIor);

} // namespace OnlineCalls

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::ServerSnapshot)
Q_DECLARE_METATYPE(SystemEditor::ComponentStates)
Q_DECLARE_METATYPE(SystemEditor::ExecutionContexts)
