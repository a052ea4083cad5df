// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Corba {
class ManagerProxy;
}

namespace Cli {

/**
 * `rtctl mgr PATH|corbaloc [load FILE:INIT] [unload FILE] [create "Type?k=v"] [delete NAME]
 * [list] [fork] [restart] [--json]` (rtshell's rtmgr); actions run in command-line order, silent
 * on success like rtshell's (create prints the new instance name); the first failure ends the run.
 */
class RtMgrCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("mgr"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override { return {QStringLiteral("--json")}; }
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    /// Consecutive creates with their own instance names, sent at once; see usage().
    bool createInOneCall(const Corba::ManagerProxy &manager,
                         const QList<QPair<QString, QString>> &creates, Streams streams) const;
    void createSideBySide(const Corba::ManagerProxy &manager, const QList<QPair<QString, QString>> &creates,
                          Streams streams) const;
    void run(const Corba::ManagerProxy &manager, const QString &action, const QString &argument,
             bool json, Streams streams) const;
    void list(const Corba::ManagerProxy &manager, bool json, Streams streams) const;
    /// Deletes through @p manager, or through the slave of it that hosts the component.
    void deleteComponent(const Corba::ManagerProxy &manager, const QString &instanceName,
                         Streams streams) const;
};

} // namespace Cli
