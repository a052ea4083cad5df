// SPDX-License-Identifier: MIT
#pragma once

#include "nodefacts.h"
#include "plan.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

namespace SystemEditor {

class SystemModel;

/// One component as the Plan view shows it in a lane.
struct PlanCard
{
    QString instanceName;
    QString typeName;
    QString process; ///< the shared process's name; empty when it runs in its own
    QString installPackage; ///< installed on the lane's node for it; empty when loadable
    bool pinned = false; ///< the system pins it to the lane's node
    QStringList unmet; ///< its requirements no node meets, with the planner's explanation
};

/// One node of the plan: its components and what gets installed there.
struct PlanLane
{
    QString node; ///< empty: the lane of components the plan could not place
    QStringList installs; ///< "package version"
    double load = 0; ///< load average plus CPU shares placed, per CPU
    QList<PlanCard> cards;
};

/**
 * The lanes of the Plan view: one per node of @p nodes (in their order) with the components
 * @p plan places there, then, when some are not placed, a last lane without a node. A component
 * the system pins (its `deploy.pin`) shows in its pinned node's lane even before re-planning;
 * its requirements in @p plan's unmet list travel with it.
 */
QList<PlanLane> planLanes(const Planner::Plan &plan, const QList<Planner::NodeFacts> &nodes,
                          const SystemModel &model);

/// One line per unmet requirement: "COMPONENT: REQUIREMENT — closest NODE has FOUND".
QString unmetText(const Planner::Unmet &unmet);

/// What a dry run lists: the installs, then each component created, where and in which process.
QStringList dryRunSteps(const Planner::Plan &plan);

} // namespace SystemEditor
