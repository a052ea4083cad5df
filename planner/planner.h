// SPDX-License-Identifier: MIT
#pragma once

#include "plan.h"
#include "planproblem.h"

namespace Planner {

/**
 * Decides where every component of a system runs: a pure function of the components'
 * requirements, the nodes' facts and the repository's packages (read before it runs; no remote
 * calls here).
 *
 * Components that must share a process are placed as one unit. Each unit goes to a node that
 * meets every requirement of its members and can load their types or install them from the
 * repository, within the nodes' free CPUs; among such plans the solver (Z3) prefers, in order,
 * fewest installs, least connector rate between hosts, the most even CPU load. When there is no
 * plan, Plan::unmet says which requirement of which component fails and the closest node.
 */
class DeploymentPlanner
{
public:
    explicit DeploymentPlanner(PlanOptions options = {});

    Plan plan(const PlanProblem &problem) const;

private:
    PlanOptions m_options;
};

} // namespace Planner
