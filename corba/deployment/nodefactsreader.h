// SPDX-License-Identifier: MIT
#pragma once

#include "nodefacts.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace Deploy {

/// The facts of one manager, or why they could not be read.
struct NodeFactsReading
{
    Planner::NodeFacts facts; ///< named by the address asked for
    QString error; ///< empty when the manager answered
};

/**
 * Reads what the planner needs from the managers at @p addresses (rtshell paths or corbaloc, as
 * `rtctl mgr` takes them), all at once, each call under the configured call timeout: the
 * manager's profile, its configuration, its factories and its loadable modules. Blocking: call it
 * off the GUI thread. A manager that does not answer comes back with its error; a manager that
 * answers but cannot list its modules has unknown loadable types.
 */
QList<NodeFactsReading> readNodeFacts(const QStringList &addresses);

} // namespace Deploy
