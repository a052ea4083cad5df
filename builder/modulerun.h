// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QMetaType>
#include <QString>

namespace Builder {

/// What Run in Manager asks one manager to do: load a module, then create a component from it.
struct ModuleRunRequest
{
    QString managerAddress; ///< `host[:port]` (port 2810 when left out) or a corbaloc address
    QString modulePath; ///< absolute path of the loadable module (`build/src/<Name>.so`)
    QString initFunction; ///< the module's init function (`<Name>Init`)
    QString typeName; ///< the component type to create (`<Name>`)
};

/// What a run ended with.
struct ModuleRunResult
{
    ModuleRunRequest request;
    bool ok = false;
    bool alreadyLoaded = false; ///< the manager had the module loaded before
    QString instanceName; ///< the component created, when ok
    QString ior; ///< its object reference, when ok
    QString error; ///< one line naming the manager and the module, when not ok
};

/**
 * The remote side of Run in Manager: `load_module(path, init)` then `create_component(type)` on
 * the manager at `managerAddress`. A module the manager has loaded already counts as loaded.
 *
 * run() blocks in CORBA calls and must only be called from a worker thread; all calls together
 * take at most `timeoutMs` (each call gets what is left of it).
 */
class ModuleRun
{
    Q_DECLARE_TR_FUNCTIONS(Builder::ModuleRun)

public:
    static ModuleRunResult run(const ModuleRunRequest &request, int timeoutMs);

    /// `corbaloc:iiop:HOST:PORT/manager` for `host[:port]` or a corbaloc address; empty when the
    /// text is not an address.
    static QString managerLocation(const QString &address);
};

} // namespace Builder

Q_DECLARE_METATYPE(Builder::ModuleRunRequest)
Q_DECLARE_METATYPE(Builder::ModuleRunResult)
