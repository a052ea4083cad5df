// SPDX-License-Identifier: MIT
#include "plan.h"

#include <QJsonArray>

namespace Planner {

const Placement *Plan::placement(const QString &instanceName) const
{
    for (const Placement &p : placements) {
        if (p.instanceName == instanceName)
            return &p;
    }
    return nullptr;
}

namespace {

QJsonArray placementsJson(const QList<Placement> &placements)
{
    QJsonArray array;
    for (const Placement &p : placements) {
        array.append(QJsonObject {{QStringLiteral("component"), p.instanceName},
                                  {QStringLiteral("type"), p.typeName},
                                  {QStringLiteral("node"), p.node},
                                  {QStringLiteral("process"), p.process},
                                  {QStringLiteral("shared_process"), p.sharedProcess},
                                  {QStringLiteral("install"), p.installPackage}});
    }
    return array;
}

QJsonArray installsJson(const QList<Install> &installs)
{
    QJsonArray array;
    for (const Install &i : installs) {
        array.append(QJsonObject {{QStringLiteral("node"), i.node},
                                  {QStringLiteral("package"), i.package},
                                  {QStringLiteral("version"), i.version}});
    }
    return array;
}

QJsonArray unmetJson(const QList<Unmet> &unmet)
{
    QJsonArray array;
    for (const Unmet &u : unmet) {
        array.append(QJsonObject {{QStringLiteral("component"), u.instanceName},
                                  {QStringLiteral("requirement"), u.requirement},
                                  {QStringLiteral("closest_node"), u.closestNode},
                                  {QStringLiteral("found"), u.found}});
    }
    return array;
}

} // namespace

QJsonObject planToJson(const Plan &plan)
{
    QJsonObject load;
    for (auto it = plan.cpuLoad.constBegin(); it != plan.cpuLoad.constEnd(); ++it)
        load.insert(it.key(), it.value());
    return QJsonObject {{QStringLiteral("feasible"), plan.feasible},
                        {QStringLiteral("optimal"), plan.optimal},
                        {QStringLiteral("balanced"), plan.balanced},
                        {QStringLiteral("placements"), placementsJson(plan.placements)},
                        {QStringLiteral("installs"), installsJson(plan.installs)},
                        {QStringLiteral("unmet"), unmetJson(plan.unmet)},
                        {QStringLiteral("cross_host_rate"), plan.crossHostRate},
                        {QStringLiteral("cpu_load"), load},
                        {QStringLiteral("solve_ms"), plan.solveMs},
                        {QStringLiteral("warnings"), QJsonArray::fromStringList(plan.warnings)}};
}

} // namespace Planner
