// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonObject>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace Planner {

/// Where one component runs.
struct Placement
{
    QString instanceName;
    QString typeName;
    QString node;
    /// The process it runs in on that node: its group's name (shared with the group's other
    /// members) or its own instance name (a slave process of its own).
    QString process;
    bool sharedProcess = false;
    QString installPackage; ///< the package installed for it there; empty when its type is loadable
};

/// A package to install on a node before the system is launched.
struct Install
{
    QString node;
    QString package;
    QString version;
};

/// A requirement of a component that no node (or no plan) meets.
struct Unmet
{
    QString instanceName; ///< empty when it concerns the whole system (CPU capacity)
    QString requirement;
    QString closestNode; ///< the node that meets most of its requirements
    QString found; ///< what the closest node has instead
};

/// The outcome of Planner::plan().
struct Plan
{
    bool feasible = false;
    bool optimal
        = false; ///< installs and connector rate proven least (false: the time ran out first)
    bool balanced = false; ///< the CPU balance is proven best too (it only breaks ties)
    QList<Placement> placements; ///< in the system's component order
    QList<Install> installs;
    QList<Unmet> unmet; ///< why there is no plan
    double crossHostRate = 0; ///< the sum of the rates (Hz) of connectors between hosts
    QMap<QString, double> cpuLoad; ///< node → load average + CPU shares placed, per CPU
    double solveMs = 0;
    QStringList warnings;

    const Placement *placement(const QString &instanceName) const;
};

/// The plan as JSON (`rtctl plan --json`): placements, installs, unmet, figures.
QJsonObject planToJson(const Plan &plan);

} // namespace Planner
