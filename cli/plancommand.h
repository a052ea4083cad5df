// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Planner {
struct Plan;
struct PlanProblem;
} // namespace Planner

namespace Cli {

/**
 * `rtctl plan SYSTEM (--nodes M1,M2,… | --facts FILE) [--repo DIR] [--profiles DIR] [--json]`:
 * where each component of the system would run (Planner::DeploymentPlanner), from the facts
 * the managers publish (or a facts file) and the packages of a component repository. Exit 0
 * when there is a plan, 1 when there is none (the unmet requirements printed) or a node or file
 * cannot be read, 2 usage error.
 */
class PlanCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("plan"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override { return {QStringLiteral("--json")}; }
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    /// The nodes' facts from --facts and --nodes; false (reported) when none can be had.
    bool readNodes(const RtOptions &options, Planner::PlanProblem *problem, QStringList *warnings,
                   Streams streams) const;
    void print(const Planner::Plan &plan, Streams streams) const;
};

} // namespace Cli
