// SPDX-License-Identifier: MIT
#pragma once

#include "placementsolver.h"

#include <QList>

namespace Planner {

/**
 * Nodes that no unit tells apart: each unit may run on all of them or on none, needing the same
 * packages on each. When no CPU limit can bind, some best plan for installs and connectors uses
 * only one node of each class (moving everything from one node of a class to another never adds
 * an install nor a crossing connector), so those two objectives are solved on one representative
 * per class — far fewer choices — and the units are spread over the class afterwards.
 */
class NodeClasses
{
public:
    /// The classes of @p input's nodes; @p input must outlive this object.
    explicit NodeClasses(const SolverInput &input);

    /// Fewer classes than nodes: reducing is worth it.
    bool reduces() const;

    /// The problem on one node per class (node indexes are class indexes).
    SolverInput reducedInput() const;

    /**
     * @p classOfUnit (a placement of reducedInput()) on the nodes of @p input: every unit on its
     * class's first node, then groups of units joined by connectors that need no install there
     * moved, largest first, to the member of their class with the least balance figure. Installs
     * and crossing connectors stay as they were.
     */
    QList<int> spread(const QList<int> &classOfUnit) const;

private:
    QList<int> unitsOnClass(const QList<int> &classOfUnit, int cls) const;
    QList<QList<int>> clusters(const QList<int> &units) const;
    bool needsNoInstall(const QList<int> &cluster, int node) const;
    int balanceOf(const QList<int> &cluster, int node) const;

    const SolverInput &m_input;
    QList<int> m_classOf; ///< per node
    QList<QList<int>> m_members; ///< per class: its nodes, ascending
};

} // namespace Planner
