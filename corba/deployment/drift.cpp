// SPDX-License-Identifier: MIT
#include "drift.h"

#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "liveports.h"
#include "rtsprofile.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <optional>
#include <vector>

namespace Deploy {

using Corba::ComponentProxy;
using Corba::Error;
using Kind = DriftItem::Kind;

namespace {

struct LiveComponent
{
    ComponentProxy proxy;
    std::vector<Corba::PortInfo> ports;
};

void diffConfiguration(const Profile::RtsComponent &saved, const ComponentProxy &proxy,
                       QList<DriftItem> &items)
{
    QString liveActive;
    const auto sets = proxy.configurationSets(&liveActive);
    for (const auto &set : saved.configurationSets) {
        const auto live
            = std::find_if(sets.begin(), sets.end(), [&](const auto &s) { return s.id == set.id; });
        const QString setName = saved.instanceName + QLatin1Char('.') + set.id;
        if (live == sets.end()) {
            items.append({Kind::ConfigurationValue, setName, set.id, QString()});
            continue;
        }
        for (const auto &data : set.data) {
            const QString value = data.data.value_or(QString());
            const bool present = Corba::hasProperty(live->data, data.name);
            const QString liveValue = Corba::propertyValue(live->data, data.name);
            if (!present || liveValue != value)
                items.append({Kind::ConfigurationValue, setName + QLatin1Char('.') + data.name,
                              value, present ? liveValue : QString()});
        }
    }
    const QString active = saved.activeConfigurationSet.value_or(QString());
    if (!active.isEmpty()) {
        if (liveActive != active)
            items.append({Kind::ActiveSet, saved.instanceName, active, liveActive});
    }
}

void diffComponent(const Profile::RtsComponent &saved, const LiveComponent &live,
                   QList<DriftItem> &items)
{
    for (const auto *list : {&saved.dataPorts, &saved.servicePorts}) {
        for (const auto &port : *list) {
            if (!findPort(live.ports, port.name, saved.instanceName))
                items.append({Kind::MissingPort, port.name, port.name, QString()});
        }
    }
    diffConfiguration(saved, live.proxy, items);
    const Corba::LifeCycleState state = live.proxy.state(0);
    if (state == Corba::LifeCycleState::Error || state == Corba::LifeCycleState::Unknown)
        items.append({Kind::State, saved.instanceName, QString(), Corba::stateName(state)});
}

// Saved connectors are found by id; a live connector between two saved components that no saved
// connector accounts for is extra.
void diffConnectors(const Profile::RtsProfile &profile, const QHash<QString, LiveComponent> &live,
                    QList<DriftItem> &items)
{
    QSet<QString> savedIds;
    QList<const Profile::RtsPortConnector *> connectors;
    for (const auto &c : profile.dataPortConnectors)
        connectors.append(&c);
    for (const auto &c : profile.servicePortConnectors)
        connectors.append(&c);
    for (const auto *c : connectors) {
        savedIds.insert(c->connectorId);
        const auto source = live.constFind(c->source.instanceName);
        if (source == live.constEnd() || !live.contains(c->target.instanceName))
            continue; // already reported as a missing component
        const auto *port = findPort(source->ports, c->source.portName, c->source.instanceName);
        if (!port || !findConnector(*port, c->connectorId))
            items.append({Kind::MissingConnector, c->connectorId,
                          c->source.portName + QStringLiteral(" -> ") + c->target.portName,
                          QString()});
    }
    QSet<QString> reported;
    for (const LiveComponent &component : live) {
        for (const auto &port : component.ports) {
            for (const auto &connector : port.connectors) {
                if (savedIds.contains(connector.id) || reported.contains(connector.id)
                    || !std::all_of(connector.ports.begin(), connector.ports.end(),
                                    [&](const QString &name) {
                                        return live.contains(name.section(QLatin1Char('.'), 0, 0));
                                    }))
                    continue;
                reported.insert(connector.id);
                items.append({Kind::ExtraConnector, connector.id, QString(),
                              connector.ports.join(QStringLiteral(" -> "))});
            }
        }
    }
}

} // namespace

QString DriftItem::kindName(Kind kind)
{
    switch (kind) {
    case Kind::MissingComponent:
        return QStringLiteral("missing component");
    case Kind::MissingPort:
        return QStringLiteral("missing port");
    case Kind::MissingConnector:
        return QStringLiteral("missing connector");
    case Kind::ExtraConnector:
        return QStringLiteral("extra connector");
    case Kind::ConfigurationValue:
        return QStringLiteral("configuration");
    case Kind::ActiveSet:
        return QStringLiteral("active set");
    case Kind::State:
        return QStringLiteral("state");
    case Kind::Unreachable:
        break;
    }
    return QStringLiteral("unreachable");
}

QString DriftItem::toString() const
{
    QString line = kindName(kind) + QLatin1Char(' ') + subject;
    QStringList values;
    if (!saved.isEmpty())
        values.append(QStringLiteral("saved '%1'").arg(saved));
    if (!live.isEmpty())
        values.append(QStringLiteral("live '%1'").arg(live));
    if (!values.isEmpty())
        line += QStringLiteral(": ") + values.join(QStringLiteral(", "));
    return line;
}

QList<DriftItem> diffSystem(const Profile::RtsProfile &profile, const RestorePlan &plan)
{
    // Each component is compared on its own: several at once, reported in the file's order.
    struct Compared
    {
        QList<DriftItem> items;
        std::optional<LiveComponent> component;
    };
    std::vector<Compared> compared(std::size_t(profile.components.size()));
    Corba::forEachConcurrently(compared.size(), [&](std::size_t i) {
        const auto &saved = profile.components.at(qsizetype(i));
        const ComponentMapping *mapping = plan.component(saved.instanceName);
        if (!mapping || mapping->kind != MappingKind::Existing) {
            compared[i].items.append({Kind::MissingComponent, saved.instanceName, saved.id,
                                      mapping ? mapping->message : QString()});
            return;
        }
        try {
            LiveComponent component {ComponentProxy(mapping->ior, mapping->path), {}};
            // From the component profile: every port's profile in one call.
            component.ports = component.proxy.profile().ports;
            diffComponent(saved, component, compared[i].items);
            compared[i].component = std::move(component);
        } catch (const Error &e) {
            compared[i].items.append({Kind::Unreachable, saved.instanceName, QString(), e.message()});
        }
    });
    QList<DriftItem> items;
    QHash<QString, LiveComponent> live;
    for (std::size_t i = 0; i < compared.size(); ++i) {
        items.append(compared[i].items);
        if (compared[i].component)
            live.insert(profile.components.at(qsizetype(i)).instanceName, std::move(*compared[i].component));
    }
    diffConnectors(profile, live, items);
    return items;
}

} // namespace Deploy
