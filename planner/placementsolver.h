// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QString>

namespace Planner {

/// One unit to place: components that must share a process (or a single free component).
struct SolverUnit
{
    QList<int> nodes; ///< the nodes it may run on (each meets all its requirements alone)
    QList<QList<int>> installs; ///< per entry of `nodes`: the installs it needs there (indexes)
    QList<int> balance; ///< per entry of `nodes`: what it adds to that node's balance figure
    int cpuMilli = 0; ///< CPU share (thousandths of a CPU) counted against capacity
};

/// A data connector between two units, weighed by its rate.
struct SolverLink
{
    int a = 0;
    int b = 0;
    int weight = 1;
};

/// The placement problem without names: what the planner hands the solver.
struct SolverInput
{
    QList<int> capacityMilli; ///< per node: free CPU (thousandths); -1: not limited
    QList<int> baseBalance; ///< per node: its balance figure before anything is placed
    QList<SolverUnit> units;
    QList<SolverLink> links;
    int installCount = 0; ///< how many distinct installs (package on node) `installs` index
    /// Per install: which package it is (the same number for one package on different nodes);
    /// tells nodes apart that need different packages. Missing entries count as all different.
    QList<int> installKind;
    int timeoutMs = 10000;
};

/// The solver's answer.
struct SolverOutput
{
    enum class Status { Optimal, Feasible, Infeasible, Unknown };
    Status status = Status::Unknown;
    QList<int> nodeOfUnit; ///< per unit: the node chosen (when Optimal or Feasible)
    QList<int> conflictingNodes; ///< when Infeasible: nodes whose CPU capacity is too small
    bool balanceProven = false; ///< the load balance (the last objective) is proven best too
    QString message; ///< the solver's reason when Unknown
};

/**
 * Places every unit on one of its nodes so that no node's CPU capacity is exceeded, minimising
 * in this order: installs, the weight of links between nodes, how far nodes rise above the even
 * balance figure. Z3 (its optimising solver) decides, one objective after the other, bounded by
 * `timeoutMs`; Optimal when the first two are proven best, Feasible when time ran out first (the
 * best placement found so far). The balance only breaks ties and gets at most a quarter of the
 * time.
 *
 * When no CPU limit can bind, nodes that no unit tells apart are solved as one (NodeClasses).
 * Connectors are first placed with the installs of the best install plan fixed (a small
 * problem), and that placement is kept when the solver proves no placement does better.
 * The result is the same for the same input whenever it is proven optimal.
 */
SolverOutput solvePlacement(const SolverInput &input);

/// Whether the units that may run on @p node could together exceed its CPU limit.
bool limitCanBind(const SolverInput &input, int node);

} // namespace Planner
