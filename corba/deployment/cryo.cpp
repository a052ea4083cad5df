// SPDX-License-Identifier: MIT
#include "cryo.h"

#include "componentmapper.h"
#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "restoreplan.h"
#include "rtsprofile.h"
#include "steprecorder.h"

#include <QMap>
#include <QSet>

#include <algorithm>
#include <optional>
#include <vector>

namespace Deploy {

using Corba::ComponentProxy;
using Corba::Error;

namespace {

const QString pathIdKey = QStringLiteral("COMPONENT_PATH_ID");

// Where a live port belongs in the saved system.
struct PortOwner
{
    const Profile::RtsComponent *component = nullptr;
    Corba::PortInfo port;
};

QString componentId(const Corba::ComponentInfo &info)
{
    return QStringLiteral("RTC:%1:%2:%3:%4")
        .arg(info.vendor, info.category, info.typeName, info.version);
}

Profile::RtsConfigurationSet savedSet(const Corba::ConfigurationSet &live)
{
    Profile::RtsConfigurationSet set;
    set.id = live.id;
    for (const auto &value : live.data) {
        Profile::RtsConfigurationData data;
        data.name = value.first;
        data.data = value.second;
        set.data.append(data);
    }
    return set;
}

Profile::RtsExecutionContext savedContext(const Corba::ExecutionContextInfo &live)
{
    Profile::RtsExecutionContext ec;
    ec.id = QString::number(live.handle);
    ec.kind = live.kind;
    ec.rate = QString::number(live.rate);
    return ec;
}

/// The component as a saved system keeps it; its profile @p info (ports included) was read before.
Profile::RtsComponent savedComponent(const ComponentProxy &proxy, const Corba::ComponentInfo &info)
{
    const std::vector<Corba::PortInfo> &ports = info.ports;
    Profile::RtsComponent component;
    component.id = componentId(info);
    component.pathUri = proxy.path().mid(proxy.path().startsWith(QLatin1Char('/')) ? 1 : 0);
    component.instanceName = info.instanceName;
    component.compositeType = QStringLiteral("None");
    component.isRequired = QStringLiteral("true");
    for (const Corba::PortInfo &port : ports) {
        Profile::RtsPort saved;
        saved.name = port.name;
        (port.isService() ? component.servicePorts : component.dataPorts).append(saved);
    }
    QString active;
    for (const auto &set : proxy.configurationSets(&active))
        component.configurationSets.append(savedSet(set));
    if (!component.configurationSets.isEmpty())
        component.activeConfigurationSet = active;
    for (const auto &ec : proxy.executionContexts(ComponentProxy::ContextDetail::Saved))
        component.executionContexts.append(savedContext(ec));
    Profile::setRtsProperty(component.properties, QStringLiteral("IOR"), proxy.ior());
    return component;
}

Profile::RtsTargetPort savedEnd(const PortOwner &owner)
{
    Profile::RtsTargetPort end;
    end.componentId = owner.component->id;
    end.instanceName = owner.component->instanceName;
    end.portName = owner.port.name;
    Profile::setRtsProperty(end.properties, pathIdKey, owner.component->pathUri);
    return end;
}

void fillConnector(Profile::RtsPortConnector &saved, const Corba::ConnectorInfo &live,
                   const PortOwner &source, const PortOwner &target)
{
    saved.connectorId = live.id;
    saved.name = live.name;
    saved.source = savedEnd(source);
    saved.target = savedEnd(target);
    for (const auto &property : live.properties) {
        if (!isIorKey(property.first))
            Profile::setRtsProperty(saved.properties, property.first, property.second);
    }
}

std::optional<QString> optionalValue(const Corba::Properties &properties, const QString &key)
{
    if (!Corba::hasProperty(properties, key))
        return std::nullopt;
    return Corba::propertyValue(properties, key);
}

void addConnector(Profile::RtsProfile &profile, const Corba::ConnectorInfo &live,
                  const QMap<QString, PortOwner> &owners)
{
    QList<PortOwner> ends;
    for (const QString &name : live.ports) {
        if (!owners.contains(name))
            return; // a connection to a component outside the saved system
        ends.append(owners.value(name));
    }
    if (ends.size() != 2)
        return;
    if (ends[0].port.isService()) {
        Profile::RtsServicePortConnector saved;
        fillConnector(saved, live, ends[0], ends[1]);
        profile.servicePortConnectors.append(saved);
        return;
    }
    if (ends[1].port.isDataOut())
        std::swap(ends[0], ends[1]);
    Profile::RtsDataPortConnector saved;
    fillConnector(saved, live, ends[0], ends[1]);
    const auto &p = live.properties;
    saved.dataType = Corba::propertyValue(p, QStringLiteral("dataport.data_type"));
    saved.interfaceType = Corba::propertyValue(p, QStringLiteral("dataport.interface_type"));
    saved.dataflowType = Corba::propertyValue(p, QStringLiteral("dataport.dataflow_type"));
    saved.subscriptionType = optionalValue(p, QStringLiteral("dataport.subscription_type"));
    saved.pushInterval = optionalValue(p, QStringLiteral("dataport.push_interval"));
    profile.dataPortConnectors.append(saved);
}

} // namespace

Profile::RtsProfile cryoSystem(const CryoOptions &options, DeployReport *report,
                               const DeployControl &control)
{
    StepRecorder steps(control);
    Profile::RtsProfile profile
        = Profile::RtsProfile::createNew(options.vendor, options.name, options.version);
    if (!options.abstract.isEmpty())
        profile.abstract = options.abstract;
    QStringList problems;
    const auto live = ComponentMapper::liveComponents(options.paths, &problems);
    for (const QString &problem : problems)
        steps.fail(steps.begin(QStringLiteral("list"), problem.section(QLatin1Char(':'), 0, 0)),
                   problem);
    QStringList instances = live.keys();
    instances.sort();
    // Each component is asked on its own: several at once, saved in name order.
    struct Saved
    {
        int step = -1;
        std::optional<Profile::RtsComponent> component;
        std::vector<Corba::PortInfo> ports;
    };
    std::vector<Saved> saved(std::size_t(instances.size()));
    for (std::size_t i = 0; i < saved.size(); ++i)
        saved[i].step = steps.begin(QStringLiteral("save"), instances.at(qsizetype(i)), false);
    Corba::forEachConcurrently(saved.size(), [&](std::size_t i) {
        const ComponentMapper::LiveEntry entry = live.value(instances.at(qsizetype(i)));
        if (steps.checkCancelled()) {
            steps.finish(saved[i].step, StepStatus::Skipped, DeployReport::cancelledError());
            return;
        }
        try {
            // The component profile carries every port's profile with its connectors.
            const ComponentProxy proxy(entry.ior, entry.path);
            const Corba::ComponentInfo info = proxy.profile();
            saved[i].ports = info.ports;
            saved[i].component = savedComponent(proxy, info);
            steps.finish(saved[i].step, StepStatus::Done, proxy.path());
        } catch (const Error &e) {
            steps.fail(saved[i].step, e.message());
        }
    });
    QMap<QString, std::vector<Corba::PortInfo>> ports;
    for (std::size_t i = 0; i < saved.size(); ++i) {
        if (!saved[i].component)
            continue;
        ports.insert(instances.at(qsizetype(i)), std::move(saved[i].ports));
        profile.components.append(std::move(*saved[i].component));
    }
    QMap<QString, PortOwner> owners;
    for (const auto &component : profile.components) {
        for (const Corba::PortInfo &port : ports.value(component.instanceName))
            owners.insert(port.name, {&component, port});
    }
    QSet<QString> seen;
    for (const PortOwner &owner : owners) {
        for (const Corba::ConnectorInfo &connector : owner.port.connectors) {
            if (!seen.contains(connector.id)) {
                seen.insert(connector.id);
                addConnector(profile, connector, owners);
            }
        }
    }
    if (report)
        *report = steps.report();
    return profile;
}

} // namespace Deploy
