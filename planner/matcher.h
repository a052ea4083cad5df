// SPDX-License-Identifier: MIT
#pragma once

#include "planproblem.h"

#include <QList>
#include <QString>

namespace Planner {

/// One requirement a node does not meet: what was required and what the node has.
struct Mismatch
{
    QString requirement; ///< "architecture aarch64", "device lidar0", "type Camera loadable or
                         ///< installable"
    QString found; ///< "x86_64", "unknown", "not listed"
};

/**
 * Checks the requirements of one component against one node alone (what the solver does not
 * need to decide): OS, distribution, architecture, language, devices, user facts, pin, CPU share
 * within the node's free CPUs, and whether its type is loadable there or installable from the
 * repository. Unknown facts never match.
 */
class Matcher
{
public:
    explicit Matcher(QList<RepositoryPackage> packages);

    /// Where a node gets a component type from: already loadable, a package to install, or nowhere.
    struct TypeSource
    {
        bool loadable = false;
        const RepositoryPackage *package = nullptr; ///< to install; null when loadable or nowhere
        bool available() const { return loadable || package; }
    };
    TypeSource typeSource(const QString &typeName, const NodeFacts &node) const;

    /// Every requirement of @p component that @p node does not meet; empty when it may run there.
    QList<Mismatch> mismatches(const ComponentRequirements &component, const NodeFacts &node) const;

private:
    bool packageFits(const RepositoryPackage &package, const NodeFacts &node) const;

    QList<RepositoryPackage> m_packages;
};

} // namespace Planner
