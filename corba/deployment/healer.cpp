// SPDX-License-Identifier: MIT
#include "healer.h"

#include "componentmapper.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "managerproxy.h"
#include "nodefactsreader.h"
#include "orb.h"
#include "planner.h"
#include "requirements.h"
#include "rtcprofile.h"
#include "steprecorder.h"

#include <QMutex>

namespace Deploy {

namespace {

QStringList sorted(QStringList list)
{
    list.sort();
    return list;
}

} // namespace

SystemHealer::SystemHealer(Profile::RtsProfile profile, WatchOptions options)
    : m_profile(std::move(profile))
    , m_options(std::move(options))
{ }

void SystemHealer::start()
{
    TargetOptions target = m_options.deploy.target;
    target.create = false;
    RestorePlan plan = planRestore(m_profile, target);
    applyPins(m_profile, &plan, false);
    m_nodes = m_options.nodes;
    for (const ComponentMapping &c : plan.components) {
        const QString node = creatingNode(c, target);
        if (node.isEmpty())
            continue;
        m_placement.insert(c.instanceName, node);
        if (!m_nodes.contains(node))
            m_nodes.append(node);
    }
}

QSet<QString> SystemHealer::probe() const
{
    QSet<QString> alive;
    QMutex mutex;
    const Corba::ThreadCallTimeout timeout(m_options.probeTimeoutMs);
    Corba::forEachConcurrently(m_nodes.size(), [&](std::size_t i) {
        const QString &node = m_nodes.at(int(i));
        try {
            Corba::ManagerProxy(ComponentMapper::resolveManager(node), node).isMaster();
            const QMutexLocker lock(&mutex);
            alive.insert(node);
        } catch (const Corba::Error &) {
            // Gone, or not answering within the probe timeout: both count as lost.
        }
    });
    return alive;
}

DeployReport SystemHealer::check(const DeployControl &control)
{
    const QSet<QString> alive = probe();
    QStringList lost;
    for (const QString &node : std::as_const(m_nodes)) {
        if (!alive.contains(node) && !m_gone.contains(node))
            lost.append(node);
    }
    DeployReport report;
    StepRecorder steps(control);
    // A node that answers again is a candidate for the next heal; nothing moves back to it.
    for (const QString &node : sorted(QStringList(m_gone.cbegin(), m_gone.cend()))) {
        if (alive.contains(node)) {
            m_gone.remove(node);
            steps.add(QStringLiteral("node back"), node, StepStatus::Done,
                      tr("nothing moved back"));
        }
    }
    report = steps.report();
    if (lost.isEmpty())
        return report;
    const DeployReport healed = heal(lost, alive, control);
    report.steps << healed.steps;
    report.ok = healed.ok;
    report.error = healed.error;
    return report;
}

DeployReport SystemHealer::heal(const QStringList &lost, const QSet<QString> &alive,
                                const DeployControl &control)
{
    StepRecorder steps(control);
    QStringList orphans;
    for (const QString &node : lost) {
        m_gone.insert(node);
        QStringList here;
        for (auto it = m_placement.cbegin(); it != m_placement.cend(); ++it) {
            if (it.value() == node)
                here.append(it.key());
        }
        here.sort();
        orphans << here;
        steps.add(QStringLiteral("node lost"), node, StepStatus::Done,
                  here.isEmpty() ? tr("it ran nothing of the system")
                                 : tr("it ran %1").arg(here.join(QStringLiteral(", "))));
    }
    if (orphans.isEmpty())
        return steps.report();
    const int planStep = steps.begin(QStringLiteral("replan"), orphans.join(QStringLiteral(", ")));
    QString why;
    const QHash<QString, QString> moved = replan(orphans, alive, &why);
    if (moved.isEmpty()) {
        steps.fail(planStep, why);
        return steps.report();
    }
    pinPlacement(&m_profile, moved);
    QStringList moves;
    for (const QString &orphan : std::as_const(orphans))
        moves << QStringLiteral("%1 -> %2").arg(orphan, moved.value(orphan));
    steps.finish(planStep, StepStatus::Done, moves.join(QStringLiteral(", ")));
    const DeployPlan plan = planDeploy(m_profile, m_options.deploy);
    const DeployReport deployed = deploySystem(m_profile, plan, m_options.deploy, control);
    DeployReport report = steps.report();
    report.steps << deployed.steps;
    report.ok = deployed.ok;
    report.error = deployed.error;
    if (deployed.ok) {
        for (auto it = moved.cbegin(); it != moved.cend(); ++it)
            m_placement.insert(it.key(), it.value());
    }
    return report;
}

QHash<QString, QString> SystemHealer::replan(const QStringList &orphans, const QSet<QString> &alive,
                                             QString *why) const
{
    QStringList live;
    for (const QString &node : m_nodes) {
        if (alive.contains(node))
            live.append(node);
    }
    QHash<QString, QString> fixed = m_placement;
    for (const QString &orphan : orphans)
        fixed.remove(orphan);
    const QHash<QString, QString> placement = planPlacement(m_profile, live, m_options.deploy, fixed, orphans, why);
    QHash<QString, QString> moved;
    for (const QString &orphan : orphans) {
        if (placement.contains(orphan))
            moved.insert(orphan, placement.value(orphan));
    }
    return moved;
}

QHash<QString, QString> planPlacement(const Profile::RtsProfile &profile, const QStringList &nodes,
                                      const DeployOptions &options, const QHash<QString, QString> &fixed,
                                      const QStringList &free, QString *why)
{
    Planner::PlanProblem problem;
    for (const NodeFactsReading &reading : readNodeFacts(nodes)) {
        if (reading.error.isEmpty())
            problem.nodes << reading.facts;
    }
    if (problem.nodes.isEmpty()) {
        *why = SystemHealer::tr("no node answers");
        return {};
    }
    const std::optional<Packages::RemoteIndex> index = readRepositoryIndex(options, why);
    if (!index)
        return {};
    problem.packages = plannerPackages(*index);
    const Planner::SystemRequirements requirements = Planner::readRequirements(profile, {});
    problem.links = requirements.links;
    for (Planner::ComponentRequirements c : requirements.components) {
        if (free.contains(c.instanceName))
            c.pinnedNode.clear();
        else if (fixed.contains(c.instanceName))
            c.pinnedNode = fixed.value(c.instanceName);
        problem.components << c;
    }
    const Planner::Plan plan = Planner::DeploymentPlanner().plan(problem);
    if (!plan.feasible) {
        QStringList unmet;
        for (const Planner::Unmet &u : plan.unmet)
            unmet << QStringLiteral("%1: %2").arg(u.instanceName, u.requirement);
        *why = SystemHealer::tr("no plan on %1: %2")
                   .arg(nodes.join(QLatin1Char(',')), unmet.join(QStringLiteral("; ")));
        return {};
    }
    QHash<QString, QString> placement;
    for (const Planner::Placement &p : plan.placements)
        placement.insert(p.instanceName, p.node);
    return placement;
}

void pinPlacement(Profile::RtsProfile *profile, const QHash<QString, QString> &placement)
{
    for (Profile::RtsComponent &component : profile->components) {
        const auto node = placement.constFind(component.instanceName);
        if (node != placement.constEnd())
            Profile::setRtsProperty(component.properties, Planner::Key::Pin, *node);
    }
}

} // namespace Deploy
