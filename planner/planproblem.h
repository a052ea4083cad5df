// SPDX-License-Identifier: MIT
#pragma once

#include "nodefacts.h"
#include "requirements.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace Planner {

/// A component package a repository offers (one entry of its index).
struct RepositoryPackage
{
    QString package;
    QString version;
    QString architecture; ///< Debian's (`amd64`, `all`)
    QString sdkAbi; ///< empty: does not link the SDK
    QStringList types; ///< the component types it provides (implementation ids)
};

/// Everything a plan is made from; facts are read before the planner runs.
struct PlanProblem
{
    QList<ComponentRequirements> components;
    QList<Link> links;
    QList<NodeFacts> nodes;
    QList<RepositoryPackage> packages;
};

/// Limits of one planning run.
struct PlanOptions
{
    int timeoutMs = 10000; ///< the solver's budget; the best plan found by then is returned
    double highRate = 0; ///< connectors at or above this rate (Hz) weigh in; 0: all by their rate
};

} // namespace Planner
