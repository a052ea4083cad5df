// SPDX-License-Identifier: MIT
#include "systemmodel.h"

#include <algorithm>
#include <utility>

namespace SystemEditor {

using namespace Profile;

namespace {

QString numberText(qreal value)
{
    return QString::number(qRound(value));
}

template<typename List>
int indexOfConnector(const List &list, const QString &connectorId)
{
    for (int i = 0; i < list.size(); ++i) {
        if (list.at(i).connectorId == connectorId)
            return i;
    }
    return -1;
}

/// `Old.port` → `New.port`; other names stay (files may name ports without the instance).
QString renamedPort(const QString &portName, const QString &oldName, const QString &newName)
{
    const QString prefix = oldName + QLatin1Char('.');
    if (portName.startsWith(prefix))
        return newName + QLatin1Char('.') + portName.mid(prefix.size());
    return portName;
}

void renameTarget(RtsTargetComponent &target, const QString &oldName, const QString &newName)
{
    if (target.instanceName == oldName)
        target.instanceName = newName;
}

void renameEnd(RtsTargetPort &end, const QString &oldName, const QString &newName)
{
    if (end.instanceName != oldName)
        return;
    end.instanceName = newName;
    end.portName = renamedPort(end.portName, oldName, newName);
}

void renameInSequence(RtsMessageSequence &sequence, const QString &oldName, const QString &newName)
{
    for (RtsCondition &condition : sequence.targets) {
        renameTarget(condition.targetComponent, oldName, newName);
        if (condition.preceding) {
            for (RtsTargetExecutionContext &preceding : condition.preceding->precedingComponents)
                renameTarget(preceding, oldName, newName);
        }
    }
}

} // namespace

// ---- whole model ---------------------------------------------------------------------------

SystemModel::SystemModel(QObject *parent)
    : QObject(parent)
{ }

SystemModel::SystemModel(RtsProfile profile, QObject *parent)
    : QObject(parent)
    , m_profile(std::move(profile))
{ }

void SystemModel::setProfile(RtsProfile profile, QHash<QString, RtcProfile> rtcProfiles)
{
    m_profile = std::move(profile);
    m_rtcProfiles = std::move(rtcProfiles);
    emit reset();
}

void SystemModel::adoptSavedProfile(const RtsProfile &saved)
{
    // Only the structure this model made can come back; anything else is a full reset.
    if (componentIds() != SystemModel(saved).componentIds()
        || connectorIds() != SystemModel(saved).connectorIds()) {
        setProfile(saved, m_rtcProfiles);
        return;
    }
    const RtsProfile before = std::exchange(m_profile, saved);
    for (int i = 0; i < m_profile.components.size(); ++i) {
        if (m_profile.components.at(i) != before.components.at(i))
            emit componentChanged(m_profile.components.at(i).instanceName);
    }
    for (const QString &id : connectorIds()) {
        if (*m_profile.connector(id) != *before.connector(id))
            emit connectorChanged(id);
    }
    if (SystemProfileInfo::fromProfile(before) != SystemProfileInfo::fromProfile(m_profile)
        || before.id != m_profile.id)
        emit systemInfoChanged();
}

SystemProfileInfo SystemModel::systemInfo() const
{
    return SystemProfileInfo::fromProfile(m_profile);
}

void SystemModel::setSystemInfo(const SystemProfileInfo &info)
{
    const RtsProfile before = m_profile;
    info.applyTo(m_profile);
    if (m_profile == before)
        return;
    emit systemInfoChanged();
    for (int i = 0; i < m_profile.components.size(); ++i) {
        if (m_profile.components.at(i).isRequired != before.components.at(i).isRequired)
            emit componentChanged(m_profile.components.at(i).instanceName);
    }
}

void SystemModel::setSystemId(const QString &id)
{
    if (m_profile.id == id)
        return;
    m_profile.id = id;
    emit systemInfoChanged();
}

void SystemModel::setAbstract(const std::optional<QString> &abstract)
{
    if (m_profile.abstract == abstract)
        return;
    m_profile.abstract = abstract;
    emit systemInfoChanged();
}

// ---- components ----------------------------------------------------------------------------

QStringList SystemModel::componentIds() const
{
    QStringList ids;
    ids.reserve(m_profile.components.size());
    for (const RtsComponent &component : m_profile.components)
        ids << component.instanceName;
    return ids;
}

bool SystemModel::hasComponent(const QString &instanceName) const
{
    return componentIndex(instanceName) >= 0;
}

const RtsComponent *SystemModel::component(const QString &instanceName) const
{
    return m_profile.component(instanceName);
}

int SystemModel::componentIndex(const QString &instanceName) const
{
    for (int i = 0; i < m_profile.components.size(); ++i) {
        if (m_profile.components.at(i).instanceName == instanceName)
            return i;
    }
    return -1;
}

const RtcProfile *SystemModel::rtcProfile(const QString &instanceName) const
{
    const auto it = m_rtcProfiles.constFind(instanceName);
    return it == m_rtcProfiles.constEnd() ? nullptr : &it.value();
}

void SystemModel::setRtcProfile(const QString &instanceName, const RtcProfile &rtc)
{
    if (!hasComponent(instanceName))
        return;
    m_rtcProfiles.insert(instanceName, rtc);
    emit componentChanged(instanceName);
}

ComponentLayout SystemModel::layout(const QString &instanceName) const
{
    ComponentLayout result;
    const RtsComponent *c = component(instanceName);
    if (!c || !c->layout)
        return result;
    const RtsLocation &l = *c->layout;
    result.position = QPointF(RtsLocation::toInt(l.x).value_or(0), RtsLocation::toInt(l.y).value_or(0));
    result.size = QSizeF(RtsLocation::toInt(l.width).value_or(-1),
                         RtsLocation::toInt(l.height).value_or(-1));
    result.direction = directionFromText(l.direction);
    return result;
}

QString SystemModel::uniqueInstanceName(const QString &typeName) const
{
    for (int n = 0;; ++n) {
        const QString candidate = typeName + QString::number(n);
        if (!hasComponent(candidate))
            return candidate;
    }
}

// ---- connectors ----------------------------------------------------------------------------

QStringList SystemModel::connectorIds() const
{
    QStringList ids;
    for (const RtsDataPortConnector &c : m_profile.dataPortConnectors)
        ids << c.connectorId;
    for (const RtsServicePortConnector &c : m_profile.servicePortConnectors)
        ids << c.connectorId;
    return ids;
}

std::optional<ConnectorInfo> SystemModel::connector(const QString &connectorId) const
{
    const RtsPortConnector *c = m_profile.connector(connectorId);
    if (!c)
        return std::nullopt;
    ConnectorInfo info;
    info.id = c->connectorId;
    info.name = c->name;
    info.kind = dataConnector(connectorId) ? ConnectorKind::Data : ConnectorKind::Service;
    info.source = {c->source.instanceName, c->source.portName};
    info.target = {c->target.instanceName, c->target.portName};
    if (const std::optional<QString> text = rtsPropertyValue(c->properties, BendPointProperty))
    {
        info.bendPointEntries = bendPointEntriesFromText(*text).value_or(QMap<int, QPointF>());
        info.bendPoints = info.bendPointEntries.values();
    }
    return info;
}

const RtsDataPortConnector *SystemModel::dataConnector(const QString &connectorId) const
{
    return m_profile.dataPortConnector(connectorId);
}

const RtsServicePortConnector *SystemModel::serviceConnector(const QString &connectorId) const
{
    return m_profile.servicePortConnector(connectorId);
}

QStringList SystemModel::connectorsOf(const QString &instanceName, const QString &portName) const
{
    QStringList ids;
    const auto touches = [&](const RtsTargetPort &end) {
        return end.instanceName == instanceName && (portName.isEmpty() || end.portName == portName);
    };
    const auto collect = [&](const auto &list) {
        for (const auto &c : list) {
            if (touches(c.source) || touches(c.target))
                ids << c.connectorId;
        }
    };
    collect(m_profile.dataPortConnectors);
    collect(m_profile.servicePortConnectors);
    return ids;
}

bool SystemModel::isPortConnected(const QString &instanceName, const QString &portName) const
{
    const auto touches = [&](const RtsTargetPort &end) {
        return end.instanceName == instanceName && (portName.isEmpty() || end.portName == portName);
    };
    const auto any = [&](const auto &list) {
        return std::any_of(list.begin(), list.end(),
                           [&](const auto &c) { return touches(c.source) || touches(c.target); });
    };
    return any(m_profile.dataPortConnectors) || any(m_profile.servicePortConnectors);
}

int SystemModel::connectorIndex(const QString &connectorId) const
{
    const int data = indexOfConnector(m_profile.dataPortConnectors, connectorId);
    return data >= 0 ? data : indexOfConnector(m_profile.servicePortConnectors, connectorId);
}

// ---- component mutators --------------------------------------------------------------------

RtsComponent *SystemModel::mutableComponent(const QString &instanceName)
{
    const int index = componentIndex(instanceName);
    return index < 0 ? nullptr : &m_profile.components[index];
}

RtsLocation &SystemModel::ensureLayout(RtsComponent &component)
{
    if (!component.layout) {
        RtsLocation location;
        location.x = location.y = QStringLiteral("0");
        location.width = location.height = QStringLiteral("-1");
        location.direction = QStringLiteral("RIGHT");
        component.layout = location;
    }
    return *component.layout;
}

bool SystemModel::addComponent(const RtsComponent &component,
                               const std::optional<RtcProfile> &rtc, int index)
{
    if (component.instanceName.isEmpty() || hasComponent(component.instanceName))
        return false;
    if (index < 0 || index > m_profile.components.size())
        index = int(m_profile.components.size());
    m_profile.components.insert(index, component);
    if (rtc)
        m_rtcProfiles.insert(component.instanceName, *rtc);
    else
        m_rtcProfiles.remove(component.instanceName);
    emit componentAdded(component.instanceName);
    return true;
}

bool SystemModel::removeComponent(const QString &instanceName)
{
    const int index = componentIndex(instanceName);
    if (index < 0)
        return false;
    emit componentAboutToBeRemoved(instanceName);
    m_profile.components.removeAt(index);
    m_rtcProfiles.remove(instanceName);
    emit componentRemoved(instanceName);
    return true;
}

bool SystemModel::setComponent(const RtsComponent &component)
{
    RtsComponent *current = mutableComponent(component.instanceName);
    if (!current)
        return false;
    if (*current != component) {
        *current = component;
        emit componentChanged(component.instanceName);
    }
    return true;
}

bool SystemModel::moveComponent(const QString &instanceName, const QPointF &position)
{
    RtsComponent *c = mutableComponent(instanceName);
    if (!c)
        return false;
    RtsLocation &l = ensureLayout(*c);
    const QString x = numberText(position.x());
    const QString y = numberText(position.y());
    if (l.x != x || l.y != y) {
        l.x = x;
        l.y = y;
        emit componentChanged(instanceName);
    }
    return true;
}

bool SystemModel::resizeComponent(const QString &instanceName, const QSizeF &size)
{
    RtsComponent *c = mutableComponent(instanceName);
    if (!c)
        return false;
    RtsLocation &l = ensureLayout(*c);
    const QString width = size.width() < 0 ? QStringLiteral("-1") : numberText(size.width());
    const QString height = size.height() < 0 ? QStringLiteral("-1") : numberText(size.height());
    if (l.width != width || l.height != height) {
        l.width = width;
        l.height = height;
        emit componentChanged(instanceName);
    }
    return true;
}

bool SystemModel::setDirection(const QString &instanceName, Direction direction)
{
    RtsComponent *c = mutableComponent(instanceName);
    if (!c)
        return false;
    RtsLocation &l = ensureLayout(*c);
    const QString text = directionText(direction);
    if (l.direction != text) {
        l.direction = text;
        emit componentChanged(instanceName);
    }
    return true;
}

bool SystemModel::setLocation(const QString &instanceName,
                              const std::optional<RtsLocation> &location)
{
    RtsComponent *c = mutableComponent(instanceName);
    if (!c)
        return false;
    if (c->layout != location) {
        c->layout = location;
        emit componentChanged(instanceName);
    }
    return true;
}

bool SystemModel::renameComponent(const QString &oldName, const QString &newName)
{
    RtsComponent *c = mutableComponent(oldName);
    if (!c || newName.isEmpty() || hasComponent(newName))
        return false;
    c->instanceName = newName;
    for (RtsPort &port : c->dataPorts)
        port.name = renamedPort(port.name, oldName, newName);
    for (RtsPort &port : c->servicePorts)
        port.name = renamedPort(port.name, oldName, newName);
    if (m_rtcProfiles.contains(oldName))
        m_rtcProfiles.insert(newName, m_rtcProfiles.take(oldName));
    renameReferences(oldName, newName);
    emit componentRenamed(oldName, newName);
    for (const QString &id : connectorsOf(newName))
        emit connectorChanged(id);
    return true;
}

void SystemModel::renameReferences(const QString &oldName, const QString &newName)
{
    for (RtsDataPortConnector &c : m_profile.dataPortConnectors) {
        renameEnd(c.source, oldName, newName);
        renameEnd(c.target, oldName, newName);
    }
    for (RtsServicePortConnector &c : m_profile.servicePortConnectors) {
        renameEnd(c.source, oldName, newName);
        renameEnd(c.target, oldName, newName);
    }
    for (RtsGroup &group : m_profile.groups) {
        for (RtsTargetComponent &member : group.members)
            renameTarget(member, oldName, newName);
    }
    for (RtsComponent &component : m_profile.components) {
        for (RtsParticipant &participant : component.participants)
            renameTarget(participant.participant, oldName, newName);
        for (RtsExecutionContext &context : component.executionContexts) {
            for (RtsTargetComponent &participant : context.participants)
                renameTarget(participant, oldName, newName);
        }
    }
    for (RtsSequenceKind kind : rtsSequenceKinds()) {
        if (std::optional<RtsMessageSequence> &sequence = m_profile.sequence(kind))
            renameInSequence(*sequence, oldName, newName);
    }
}

bool SystemModel::setConfigurationSets(const QString &instanceName,
                                       const QList<RtsConfigurationSet> &sets,
                                       const std::optional<QString> &activeSet)
{
    RtsComponent *c = mutableComponent(instanceName);
    if (!c)
        return false;
    if (c->configurationSets != sets || c->activeConfigurationSet != activeSet) {
        c->configurationSets = sets;
        c->activeConfigurationSet = activeSet;
        emit componentChanged(instanceName);
    }
    return true;
}

// ---- connector mutators --------------------------------------------------------------------

RtsPortConnector *SystemModel::mutableConnector(const QString &connectorId)
{
    int index = indexOfConnector(m_profile.dataPortConnectors, connectorId);
    if (index >= 0)
        return &m_profile.dataPortConnectors[index];
    index = indexOfConnector(m_profile.servicePortConnectors, connectorId);
    return index >= 0 ? &m_profile.servicePortConnectors[index] : nullptr;
}

bool SystemModel::addDataConnector(const RtsDataPortConnector &connector, int index)
{
    if (connector.connectorId.isEmpty() || m_profile.connector(connector.connectorId))
        return false;
    if (index < 0 || index > m_profile.dataPortConnectors.size())
        index = int(m_profile.dataPortConnectors.size());
    m_profile.dataPortConnectors.insert(index, connector);
    emit connectorAdded(connector.connectorId);
    return true;
}

bool SystemModel::addServiceConnector(const RtsServicePortConnector &connector, int index)
{
    if (connector.connectorId.isEmpty() || m_profile.connector(connector.connectorId))
        return false;
    if (index < 0 || index > m_profile.servicePortConnectors.size())
        index = int(m_profile.servicePortConnectors.size());
    m_profile.servicePortConnectors.insert(index, connector);
    emit connectorAdded(connector.connectorId);
    return true;
}

bool SystemModel::removeConnector(const QString &connectorId)
{
    const int data = indexOfConnector(m_profile.dataPortConnectors, connectorId);
    const int service = indexOfConnector(m_profile.servicePortConnectors, connectorId);
    if (data < 0 && service < 0)
        return false;
    emit connectorAboutToBeRemoved(connectorId);
    if (data >= 0)
        m_profile.dataPortConnectors.removeAt(data);
    else
        m_profile.servicePortConnectors.removeAt(service);
    emit connectorRemoved(connectorId);
    return true;
}

bool SystemModel::setDataConnector(const RtsDataPortConnector &connector)
{
    const int index = indexOfConnector(m_profile.dataPortConnectors, connector.connectorId);
    if (index < 0)
        return false;
    if (m_profile.dataPortConnectors.at(index) != connector) {
        m_profile.dataPortConnectors[index] = connector;
        emit connectorChanged(connector.connectorId);
    }
    return true;
}

bool SystemModel::setServiceConnector(const RtsServicePortConnector &connector)
{
    const int index = indexOfConnector(m_profile.servicePortConnectors, connector.connectorId);
    if (index < 0)
        return false;
    if (m_profile.servicePortConnectors.at(index) != connector) {
        m_profile.servicePortConnectors[index] = connector;
        emit connectorChanged(connector.connectorId);
    }
    return true;
}

bool SystemModel::setBendPoints(const QString &connectorId, const QList<QPointF> &points)
{
    RtsPortConnector *c = mutableConnector(connectorId);
    if (!c)
        return false;
    const RtsProperties before = c->properties;
    if (points.isEmpty()) {
        c->properties.removeIf(
            [](const RtsProperty &p) { return p.name == SystemModel::BendPointProperty; });
    } else {
        setRtsProperty(c->properties, BendPointProperty, bendPointsToText(points));
    }
    if (c->properties != before)
        emit connectorChanged(connectorId);
    return true;
}

} // namespace SystemEditor
