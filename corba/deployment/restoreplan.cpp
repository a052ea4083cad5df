// SPDX-License-Identifier: MIT
#include "restoreplan.h"

#include "rtsprofile.h"

#include <algorithm>

namespace Deploy {

namespace {

void overlay(Corba::Properties &properties, const Profile::RtsProperties &saved)
{
    for (const auto &property : saved) {
        if (!isIorKey(property.name))
            Corba::setProperty(properties, property.name, property.value.value_or(QString()));
    }
}

ConnectorPlan planFor(const Profile::RtsPortConnector &connector, bool dataPort,
                      const QList<ComponentMapping> &components)
{
    ConnectorPlan plan;
    plan.connectorId = connector.connectorId;
    plan.name = connector.name;
    plan.dataPort = dataPort;
    plan.sourceInstance = connector.source.instanceName;
    plan.sourcePort = connector.source.portName;
    plan.targetInstance = connector.target.instanceName;
    plan.targetPort = connector.target.portName;
    auto requiredEnd = [&](const QString &instance) {
        const auto it = std::find_if(components.begin(), components.end(),
                                     [&](const auto &c) { return c.instanceName == instance; });
        return it == components.end() || it->required;
    };
    plan.required = requiredEnd(plan.sourceInstance) && requiredEnd(plan.targetInstance);
    return plan;
}

} // namespace

const ComponentMapping *RestorePlan::component(const QString &instanceName) const
{
    for (const ComponentMapping &mapping : components) {
        if (mapping.instanceName == instanceName)
            return &mapping;
    }
    return nullptr;
}

QList<ComponentMapping> RestorePlan::missingRequired() const
{
    QList<ComponentMapping> missing;
    for (const ComponentMapping &mapping : components) {
        if (mapping.required && mapping.kind == MappingKind::Missing)
            missing.append(mapping);
    }
    return missing;
}

QString RestorePlan::toText() const
{
    QString text;
    for (const QString &problem : problems)
        text += tr("problem %1").arg(problem) + QLatin1Char('\n');
    for (const ComponentMapping &c : components)
        text += optionalLine(componentLine(c), c.required);
    for (const ConnectorPlan &c : connectors)
        text += optionalLine(
            tr("connect %1 %2 -> %3 (%4)").arg(c.connectorId, c.sourcePort, c.targetPort, c.name),
            c.required);
    return text;
}

// One whole sentence per mapping, so that a translation can order its parts.
QString RestorePlan::componentLine(const ComponentMapping &c)
{
    const bool note = !c.message.isEmpty();
    switch (c.kind) {
    case MappingKind::Create:
        return note
            ? tr("component %1 create (%2): %3").arg(c.instanceName, c.createArgument, c.message)
            : tr("component %1 create (%2)").arg(c.instanceName, c.createArgument);
    case MappingKind::Existing:
        return note ? tr("component %1 existing at %2: %3").arg(c.instanceName, c.path, c.message)
                    : tr("component %1 existing at %2").arg(c.instanceName, c.path);
    case MappingKind::Missing:
        break;
    }
    return note ? tr("component %1 missing: %2").arg(c.instanceName, c.message)
                : tr("component %1 missing").arg(c.instanceName);
}

QString RestorePlan::optionalLine(const QString &line, bool required)
{
    return (required ? line : tr("%1 [optional]", "a plan line of an optional component").arg(line))
        + QLatin1Char('\n');
}

bool isIorKey(const QString &key)
{
    const QString lower = key.toLower();
    return lower == QLatin1String("ior") || lower.endsWith(QLatin1String("_ior"))
        || lower.endsWith(QLatin1String("_ref"));
}

Corba::Properties dataConnectorProperties(const Profile::RtsDataPortConnector &connector)
{
    Corba::Properties properties
        = {{QStringLiteral("dataport.interface_type"), connector.interfaceType},
           {QStringLiteral("dataport.dataflow_type"), connector.dataflowType},
           {QStringLiteral("dataport.data_type"), connector.dataType}};
    if (connector.subscriptionType)
        properties.append(
            {QStringLiteral("dataport.subscription_type"), *connector.subscriptionType});
    properties.erase(std::remove_if(properties.begin(), properties.end(),
                                    [](const auto &p) { return p.second.isEmpty(); }),
                     properties.end());
    overlay(properties, connector.properties);
    return properties;
}

Corba::Properties serviceConnectorProperties(const Profile::RtsPortConnector &connector)
{
    Corba::Properties properties;
    overlay(properties, connector.properties);
    return properties;
}

QList<ConnectorPlan> connectorPlans(const Profile::RtsProfile &profile,
                                    const QList<ComponentMapping> &components)
{
    QList<ConnectorPlan> required;
    QList<ConnectorPlan> optional;
    for (const auto &connector : profile.dataPortConnectors) {
        ConnectorPlan plan = planFor(connector, true, components);
        plan.properties = dataConnectorProperties(connector);
        (plan.required ? required : optional).append(plan);
    }
    QList<ConnectorPlan> plans = required + optional;
    for (const auto &connector : profile.servicePortConnectors) {
        ConnectorPlan plan = planFor(connector, false, components);
        plan.properties = serviceConnectorProperties(connector);
        plans.append(plan);
    }
    return plans;
}

RestorePlan planRestore(const Profile::RtsProfile &profile, const TargetOptions &options)
{
    RestorePlan plan;
    ComponentMapper mapper(options);
    plan.components = mapper.map(profile);
    plan.problems = mapper.problems();
    plan.connectors = connectorPlans(profile, plan.components);
    return plan;
}

} // namespace Deploy
