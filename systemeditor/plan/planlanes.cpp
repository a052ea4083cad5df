// SPDX-License-Identifier: MIT
#include "planlanes.h"

#include "pincommand.h"
#include "systemmodel.h"

namespace SystemEditor {

namespace {

/// Translations of the texts made here (the functions are free, not QObjects).
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SystemEditor::PlanLanes)
};

PlanCard cardOf(const QString &instance, const Planner::Plan &plan, const SystemModel &model)
{
    PlanCard card;
    card.instanceName = instance;
    if (const Planner::Placement *p = plan.placement(instance)) {
        card.typeName = p->typeName;
        card.process = p->sharedProcess ? p->process : QString();
        card.installPackage = p->installPackage;
    } else if (const Profile::RtsComponent *component = model.component(instance)) {
        card.typeName = component->id.section(QLatin1Char(':'), 3, 3);
    }
    for (const Planner::Unmet &u : plan.unmet) {
        if (u.instanceName == instance
            || u.instanceName.split(QStringLiteral(", ")).contains(instance))
            card.unmet << unmetText(u);
    }
    return card;
}

/// The lane index a component goes to: its pin's node, its placement's, or -1 (not placed).
int laneOf(const QString &instance, const Planner::Plan &plan,
           const QList<Planner::NodeFacts> &nodes, const QString &pin)
{
    const QString node = !pin.isEmpty()
        ? pin
        : (plan.placement(instance) ? plan.placement(instance)->node : QString());
    for (int n = 0; n < nodes.size(); ++n) {
        if (!node.isEmpty() && (nodes.at(n).name == node || nodes.at(n).hostname == node))
            return n;
    }
    return -1;
}

} // namespace

QList<PlanLane> planLanes(const Planner::Plan &plan, const QList<Planner::NodeFacts> &nodes,
                          const SystemModel &model)
{
    QList<PlanLane> lanes;
    for (const Planner::NodeFacts &node : nodes)
        lanes.append({node.name, {}, plan.cpuLoad.value(node.name), {}});
    for (const Planner::Install &install : plan.installs) {
        for (PlanLane &lane : lanes) {
            if (lane.node == install.node)
                lane.installs << QStringLiteral("%1 %2").arg(install.package, install.version);
        }
    }
    PlanLane unplaced;
    for (const QString &instance : model.componentIds()) {
        const QString pin = pinnedNode(model, instance);
        PlanCard card = cardOf(instance, plan, model);
        card.pinned = !pin.isEmpty();
        const int lane = laneOf(instance, plan, nodes, pin);
        (lane < 0 ? unplaced : lanes[lane]).cards << card;
    }
    if (!unplaced.cards.isEmpty())
        lanes << unplaced;
    return lanes;
}

QString unmetText(const Planner::Unmet &u)
{
    const QString subject = u.instanceName.isEmpty() ? Text::tr("system") : u.instanceName;
    if (u.closestNode.isEmpty())
        return Text::tr("%1: %2 (%3)").arg(subject, u.requirement, u.found);
    return Text::tr("%1: %2 — no node meets it; closest %3 has %4")
        .arg(subject, u.requirement, u.closestNode, u.found);
}

QStringList dryRunSteps(const Planner::Plan &plan)
{
    QStringList steps;
    for (const Planner::Install &i : plan.installs)
        steps << Text::tr("Install %1 %2 on %3").arg(i.package, i.version, i.node);
    for (const Planner::Placement &p : plan.placements) {
        steps << (p.sharedProcess ? Text::tr("Create %1 (%2) on %3 in process %4")
                                        .arg(p.instanceName, p.typeName, p.node, p.process)
                                  : Text::tr("Create %1 (%2) on %3 in a process of its own")
                                        .arg(p.instanceName, p.typeName, p.node));
    }
    return steps;
}

} // namespace SystemEditor
