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
    // Only what the file says is compared, and only that is asked.
    const QString active = saved.activeConfigurationSet.value_or(QString());
    if (saved.configurationSets.isEmpty() && active.isEmpty())
        return;
    QString liveActive;
    const auto sets = proxy.configurationSets(active.isEmpty() ? nullptr : &liveActive);
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
    if (!active.isEmpty() && liveActive != active)
        items.append({Kind::ActiveSet, saved.instanceName, active, liveActive});
}

void diffPorts(const Profile::RtsComponent &saved, const std::vector<Corba::PortInfo> &ports,
               QList<DriftItem> &items)
{
    for (const auto *list : {&saved.dataPorts, &saved.servicePorts}) {
        for (const auto &port : *list) {
            if (!findPort(ports, port.name, saved.instanceName))
                items.append({Kind::MissingPort, port.name, port.name, QString()});
        }
    }
}

void diffState(const Profile::RtsComponent &saved, const ComponentProxy &proxy, QList<DriftItem> &items)
{
    const Corba::LifeCycleState state = proxy.state(0);
    if (state == Corba::LifeCycleState::Error || state == Corba::LifeCycleState::Unknown)
        items.append({Kind::State, saved.instanceName, QString(), Corba::stateName(state)});
}

// Saved connectors are found by id; a live connector between two saved components that no saved
// connector accounts for is extra. `involved` gets the instances whose ports showed a difference.
void diffConnectors(const Profile::RtsProfile &profile, const QHash<QString, LiveComponent> &live,
                    QList<DriftItem> &items, QSet<QString> &involved)
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
        if (!port || !findConnector(*port, c->connectorId)) {
            items.append({Kind::MissingConnector, c->connectorId,
                          c->source.portName + QStringLiteral(" -> ") + c->target.portName,
                          QString()});
            involved.insert(c->source.instanceName);
        }
    }
    QSet<QString> reported;
    for (auto component = live.constBegin(); component != live.constEnd(); ++component) {
        for (const auto &port : component->ports) {
            for (const auto &connector : port.connectors) {
                if (savedIds.contains(connector.id) || reported.contains(connector.id)
                    || !std::all_of(connector.ports.begin(), connector.ports.end(),
                                    [&](const QString &name) {
                                        return live.contains(name.section(QLatin1Char('.'), 0, 0));
                                    }))
                    continue;
                reported.insert(connector.id);
                involved.insert(component.key());
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
        return tr("missing component");
    case Kind::MissingPort:
        return tr("missing port");
    case Kind::MissingConnector:
        return tr("missing connector");
    case Kind::ExtraConnector:
        return tr("extra connector");
    case Kind::ConfigurationValue:
        return tr("configuration");
    case Kind::ActiveSet:
        return tr("active set");
    case Kind::State:
        return tr("state");
    case Kind::Unreachable:
        break;
    }
    return tr("unreachable");
}

// One whole sentence per combination of values, for translators.
QString DriftItem::toString() const
{
    const QString kindText = kindName(kind);
    if (!saved.isEmpty() && !live.isEmpty())
        return tr("%1 %2: saved '%3', live '%4'").arg(kindText, subject, saved, live);
    if (!saved.isEmpty())
        return tr("%1 %2: saved '%3'").arg(kindText, subject, saved);
    if (!live.isEmpty())
        return tr("%1 %2: live '%3'").arg(kindText, subject, live);
    return tr("%1 %2", "drift: kind, subject").arg(kindText, subject);
}

QList<DriftItem> diffSystem(const Profile::RtsProfile &profile, const RestorePlan &plan)
{
    // Each component is compared on its own: several at once, reported in the file's order. Ports
    // and connectors start from what the plan read a moment ago; the components where they differ
    // from the file are read again below, so what is reported is what is live now.
    struct Compared
    {
        const Profile::RtsComponent *saved = nullptr;
        QList<DriftItem> items; ///< configuration and state
        std::optional<LiveComponent> component;
    };
    const auto &components = profile.components;
    std::vector<Compared> compared(std::size_t(components.size()));
    Corba::forEachConcurrently(compared.size(), [&](std::size_t i) {
        const auto &saved = components.at(qsizetype(i));
        compared[i].saved = &saved;
        const ComponentMapping *mapping = plan.component(saved.instanceName);
        if (!mapping || mapping->kind != MappingKind::Existing) {
            compared[i].items.append({Kind::MissingComponent, saved.instanceName, saved.id,
                                      mapping ? mapping->message : QString()});
            return;
        }
        try {
            LiveComponent component {ComponentProxy(mapping->ior, mapping->path), mapping->plannedPorts};
            diffConfiguration(saved, component.proxy, compared[i].items);
            diffState(saved, component.proxy, compared[i].items);
            compared[i].component = std::move(component);
        } catch (const Error &e) {
            compared[i].items.append({Kind::Unreachable, saved.instanceName, QString(), e.message()});
        }
    });
    // The connector items of the ports as they stand now; `involved` gets the components whose
    // ports or connectors disagree with the file.
    const auto connectorItems = [&](QSet<QString> &involved) {
        QHash<QString, LiveComponent> live;
        for (const Compared &c : compared) {
            if (!c.component)
                continue;
            QList<DriftItem> missingPorts;
            diffPorts(*c.saved, c.component->ports, missingPorts);
            if (!missingPorts.isEmpty())
                involved.insert(c.saved->instanceName);
            live.insert(c.saved->instanceName, *c.component);
        }
        QList<DriftItem> items;
        diffConnectors(profile, live, items, involved);
        return items;
    };
    QSet<QString> involved;
    connectorItems(involved);
    // Read again (one call each, component profile) the components the plan's ports disagree on.
    std::vector<std::size_t> again;
    for (std::size_t i = 0; i < compared.size(); ++i) {
        if (compared[i].component && involved.contains(compared[i].saved->instanceName))
            again.push_back(i);
    }
    Corba::forEachConcurrently(again.size(), [&](std::size_t k) {
        Compared &c = compared[again[k]];
        try {
            c.component->ports = c.component->proxy.profile().ports;
        } catch (const Error &e) {
            c.items.append({Kind::Unreachable, c.saved->instanceName, QString(), e.message()});
            c.component.reset();
        }
    });
    involved.clear();
    const QList<DriftItem> connectors = connectorItems(involved);
    QList<DriftItem> items;
    for (const Compared &c : compared) {
        if (c.component)
            diffPorts(*c.saved, c.component->ports, items);
        items.append(c.items);
    }
    items.append(connectors);
    return items;
}

} // namespace Deploy
