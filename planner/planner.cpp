// SPDX-License-Identifier: MIT
#include "planner.h"

#include "matcher.h"
#include "placementsolver.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace Planner {

namespace {

/// CPU counted per component for balancing when it states no share of its own.
constexpr double NominalShare = 0.1;
/// The solver counts in ints: CPU in thousandths up to a million CPUs, connector weights up to
/// 1 MHz each, so that sums over a thousand units stay far from overflowing.
constexpr double LargestMilli = 1e9;
constexpr double LargestRate = 1e6;

int milli(double cpus)
{
    return int(std::clamp(std::ceil(cpus * 1000), 0.0, LargestMilli));
}

/// Components placed together (one process) and the nodes where all of them may run.
struct Unit
{
    QList<int> members; ///< component indexes
    QString process; ///< the shared process's name; empty for a single component of its own
    QList<int> nodes;
};

/// One planning run's working state.
class Run
{
public:
    Run(const PlanProblem &problem, const PlanOptions &options)
        : m_problem(problem)
        , m_options(options)
        , m_matcher(problem.packages)
    { }

    Plan plan();

private:
    void matchComponents();
    void buildUnits();
    bool explainComponents();
    bool explainUnits();
    int closestNode(int component) const;
    SolverInput solverInput();
    QList<int> installsOf(const Unit &unit, int node);
    void readSolution(const SolverOutput &output);
    void explainCapacity(const QList<int> &nodes);
    double effectiveShare(const Unit &unit) const;
    double cpusOf(int node) const;

    const PlanProblem &m_problem;
    const PlanOptions &m_options;
    Matcher m_matcher;
    Plan m_plan;
    QList<QList<QList<Mismatch>>> m_mismatches; ///< [component][node]
    QList<Unit> m_units;
    QHash<QString, int> m_unitOf; ///< instance name → unit
    QHash<QPair<QString, int>, int> m_installIndex; ///< (package, node) → install index
    QList<QPair<const RepositoryPackage *, int>> m_installKeys;
};

double Run::cpusOf(int node) const
{
    return qMax(1, m_problem.nodes.at(node).cpuCount.value_or(1));
}

void Run::matchComponents()
{
    for (const ComponentRequirements &component : m_problem.components) {
        QList<QList<Mismatch>> perNode;
        for (const NodeFacts &node : m_problem.nodes)
            perNode << m_matcher.mismatches(component, node);
        m_mismatches << perNode;
    }
}

void Run::buildUnits()
{
    QHash<QString, int> byProcess;
    for (int c = 0; c < m_problem.components.size(); ++c) {
        const QString &process = m_problem.components.at(c).process;
        int unit = process.isEmpty() ? -1 : byProcess.value(process, -1);
        if (unit < 0) {
            unit = int(m_units.size());
            m_units.append(Unit {{}, process, {}});
            if (!process.isEmpty())
                byProcess.insert(process, unit);
        }
        m_units[unit].members << c;
        m_unitOf.insert(m_problem.components.at(c).instanceName, unit);
    }
    for (Unit &unit : m_units) {
        for (int n = 0; n < m_problem.nodes.size(); ++n) {
            bool all = true;
            for (const int c : std::as_const(unit.members))
                all = all && m_mismatches.at(c).at(n).isEmpty();
            if (all)
                unit.nodes << n;
        }
    }
}

int Run::closestNode(int component) const
{
    int best = 0;
    for (int n = 1; n < m_problem.nodes.size(); ++n) {
        if (m_mismatches.at(component).at(n).size() < m_mismatches.at(component).at(best).size())
            best = n;
    }
    return best;
}

/// Components that no node can take on their own: each requirement the closest node fails.
bool Run::explainComponents()
{
    for (int c = 0; c < m_problem.components.size(); ++c) {
        bool somewhere = false;
        for (int n = 0; n < m_problem.nodes.size(); ++n)
            somewhere = somewhere || m_mismatches.at(c).at(n).isEmpty();
        if (somewhere)
            continue;
        const int closest = closestNode(c);
        for (const Mismatch &m : m_mismatches.at(c).at(closest))
            m_plan.unmet.append({m_problem.components.at(c).instanceName, m.requirement,
                                 m_problem.nodes.at(closest).name, m.found});
    }
    return m_plan.unmet.isEmpty();
}

/// Process groups whose members can each run somewhere, but nowhere together.
bool Run::explainUnits()
{
    for (const Unit &unit : std::as_const(m_units)) {
        if (!unit.nodes.isEmpty())
            continue;
        const int first = unit.members.first();
        const int closest = closestNode(first);
        for (const int c : unit.members) {
            if (m_mismatches.at(c).at(closest).isEmpty())
                continue;
            m_plan.unmet.append(
                {m_problem.components.at(c).instanceName,
                 QCoreApplication::translate("Planner", "same process (%1) as %2")
                     .arg(unit.process, m_problem.components.at(first).instanceName),
                 m_problem.nodes.at(closest).name,
                 m_mismatches.at(c).at(closest).first().requirement + QCoreApplication::translate("Planner", " not met")});
        }
    }
    return m_plan.unmet.isEmpty();
}

QList<int> Run::installsOf(const Unit &unit, int node)
{
    QList<int> needed;
    for (const int c : unit.members) {
        const Matcher::TypeSource source
            = m_matcher.typeSource(m_problem.components.at(c).typeName, m_problem.nodes.at(node));
        if (!source.package)
            continue;
        const QPair<QString, int> key(source.package->package, node);
        if (!m_installIndex.contains(key)) {
            m_installIndex.insert(key, int(m_installKeys.size()));
            m_installKeys.append({source.package, node});
        }
        if (!needed.contains(m_installIndex.value(key)))
            needed << m_installIndex.value(key);
    }
    return needed;
}

double Run::effectiveShare(const Unit &unit) const
{
    double share = 0;
    for (const int c : unit.members) {
        const double own = m_problem.components.at(c).cpuShare;
        share += own > 0 ? own : NominalShare;
    }
    return share;
}

SolverInput Run::solverInput()
{
    SolverInput input;
    input.timeoutMs = m_options.timeoutMs;
    for (int n = 0; n < m_problem.nodes.size(); ++n) {
        const std::optional<double> free = m_problem.nodes.at(n).freeCpus();
        input.capacityMilli << (free ? int(std::clamp(std::floor(*free * 1000), 0.0, LargestMilli))
                                     : -1);
        input.baseBalance << milli(m_problem.nodes.at(n).loadAverage.value_or(0) / cpusOf(n));
    }
    for (const Unit &unit : std::as_const(m_units)) {
        SolverUnit su;
        su.nodes = unit.nodes;
        for (const int c : unit.members)
            su.cpuMilli
                = qMin(su.cpuMilli + milli(m_problem.components.at(c).cpuShare), int(LargestMilli));
        for (const int n : unit.nodes) {
            su.installs << installsOf(unit, n);
            su.balance << milli(effectiveShare(unit) / cpusOf(n));
        }
        input.units << su;
    }
    input.installCount = int(m_installKeys.size());
    QStringList packages;
    for (const auto &[package, node] : std::as_const(m_installKeys)) {
        if (!packages.contains(package->package))
            packages << package->package;
        input.installKind << int(packages.indexOf(package->package));
    }
    QHash<QPair<int, int>, int> weights;
    for (const Link &link : m_problem.links) {
        const int a = m_unitOf.value(link.source, -1);
        const int b = m_unitOf.value(link.target, -1);
        if (a < 0 || b < 0 || a == b)
            continue;
        int &weight = weights[{qMin(a, b), qMax(a, b)}];
        weight = qMin(weight + qMax(1, int(std::lround(std::clamp(link.rate, 0.0, LargestRate)))),
                      int(LargestRate));
    }
    for (auto it = weights.constBegin(); it != weights.constEnd(); ++it)
        input.links.append({it.key().first, it.key().second, it.value()});
    return input;
}

void Run::explainCapacity(const QList<int> &nodes)
{
    QStringList names;
    QStringList free;
    for (const int n : nodes) {
        names << m_problem.nodes.at(n).name;
        free << QString::number(m_problem.nodes.at(n).freeCpus().value_or(0));
    }
    QStringList components;
    for (const Unit &unit : std::as_const(m_units)) {
        bool confined = true;
        for (const int n : unit.nodes)
            confined = confined && nodes.contains(n);
        for (const int c : unit.members) {
            if (confined && m_problem.components.at(c).cpuShare > 0)
                components << m_problem.components.at(c).instanceName;
        }
    }
    m_plan.unmet.append({components.join(QStringLiteral(", ")),
                         QCoreApplication::translate("Planner", "CPU shares together within the free CPUs of %1")
                             .arg(names.join(QStringLiteral(", "))),
                         names.value(0),
                         QCoreApplication::translate("Planner", "%1 CPUs free").arg(free.join(QStringLiteral(" + ")))});
}

void Run::readSolution(const SolverOutput &output)
{
    QSet<int> installed;
    for (int u = 0; u < m_units.size(); ++u) {
        const Unit &unit = m_units.at(u);
        const int n = output.nodeOfUnit.at(u);
        for (const int c : unit.members) {
            const ComponentRequirements &component = m_problem.components.at(c);
            const Matcher::TypeSource source
                = m_matcher.typeSource(component.typeName, m_problem.nodes.at(n));
            Placement p {component.instanceName,
                         component.typeName,
                         m_problem.nodes.at(n).name,
                         unit.process.isEmpty() ? component.instanceName : unit.process,
                         unit.members.size() > 1,
                         source.package ? source.package->package : QString()};
            m_plan.placements.append(p);
            if (source.package
                && !installed.contains(m_installIndex.value({source.package->package, n}))) {
                installed.insert(m_installIndex.value({source.package->package, n}));
                m_plan.installs.append({p.node, source.package->package, source.package->version});
            }
        }
        m_plan.cpuLoad[m_problem.nodes.at(n).name] += effectiveShare(unit) / cpusOf(n);
    }
}

Plan Run::plan()
{
    QElapsedTimer clock;
    clock.start();
    if (m_problem.nodes.isEmpty()) {
        m_plan.unmet.append({QString(), QCoreApplication::translate("Planner", "a node to run on"), QString(),
                             QCoreApplication::translate("Planner", "no nodes given")});
        return m_plan;
    }
    matchComponents();
    buildUnits();
    if (!explainComponents() || !explainUnits())
        return m_plan;
    for (int n = 0; n < m_problem.nodes.size(); ++n)
        m_plan.cpuLoad.insert(m_problem.nodes.at(n).name,
                              m_problem.nodes.at(n).loadAverage.value_or(0) / cpusOf(n));
    const SolverInput input = solverInput();
    const SolverOutput output = solvePlacement(input);
    m_plan.solveMs = double(clock.nsecsElapsed()) / 1e6;
    if (output.status == SolverOutput::Status::Infeasible) {
        explainCapacity(output.conflictingNodes);
    } else if (output.status == SolverOutput::Status::Unknown) {
        m_plan.unmet.append({QString(),
                             QCoreApplication::translate("Planner", "a plan within %1 ms").arg(m_options.timeoutMs),
                             QString(), output.message});
    } else {
        m_plan.feasible = true;
        m_plan.optimal = output.status == SolverOutput::Status::Optimal;
        m_plan.balanced = output.balanceProven;
        if (!m_plan.optimal)
            m_plan.warnings
                << QStringLiteral(
                       "the solver's time ran out: the plan is valid, perhaps not the best (%1)")
                       .arg(output.message);
        readSolution(output);
        for (const SolverLink &link : input.links) {
            if (output.nodeOfUnit.at(link.a) != output.nodeOfUnit.at(link.b))
                m_plan.crossHostRate += link.weight;
        }
    }
    return m_plan;
}

} // namespace

DeploymentPlanner::DeploymentPlanner(PlanOptions options)
    : m_options(options)
{ }

Plan DeploymentPlanner::plan(const PlanProblem &problem) const
{
    return Run(problem, m_options).plan();
}

} // namespace Planner
