// SPDX-License-Identifier: MIT
#include "rtsprofile.h"

#include <QDateTime>

#include <tuple>

namespace Profile {

bool RtsGroup::operator==(const RtsGroup &other) const
{
    return std::tie(groupId, members, extras, yamlExtras)
        == std::tie(other.groupId, other.members, other.extras, other.yamlExtras);
}

bool RtsSystemPath::operator==(const RtsSystemPath &other) const
{
    return std::tie(path, extras, yamlExtras)
        == std::tie(other.path, other.extras, other.yamlExtras);
}

std::optional<RtsSystemId> RtsSystemId::parse(const QString &id)
{
    const QStringList parts = id.split(QLatin1Char(':'));
    if (parts.size() != 4 || parts.at(0) != QLatin1String("RTSystem"))
        return std::nullopt;
    for (const QString &part : parts) {
        if (part.trimmed().isEmpty())
            return std::nullopt;
    }
    return RtsSystemId {parts.at(1), parts.at(2), parts.at(3)};
}

QString RtsSystemId::toString() const
{
    return QStringLiteral("RTSystem:%1:%2:%3").arg(vendor, name, version);
}

RtsProfile RtsProfile::createNew(const QString &vendor, const QString &name, const QString &version)
{
    RtsProfile profile;
    profile.id = RtsSystemId {vendor, name, version}.toString();
    profile.version = CurrentVersion;
    profile.creationDate = currentDateTimeText();
    profile.updateDate = profile.creationDate;
    return profile;
}

QString RtsProfile::currentDateTimeText()
{
    // An explicit offset keeps the time meaningful when the file travels between time zones.
    const QDateTime now = QDateTime::currentDateTime();
    const QDateTime withOffset = now.toOffsetFromUtc(now.offsetFromUtc());
    return withOffset.toString(Qt::ISODate);
}

std::optional<RtsSystemId> RtsProfile::systemId() const
{
    return RtsSystemId::parse(id);
}

const RtsComponent *RtsProfile::component(const QString &instanceName) const
{
    for (const RtsComponent &c : components) {
        if (c.instanceName == instanceName)
            return &c;
    }
    return nullptr;
}

RtsComponent *RtsProfile::component(const QString &instanceName)
{
    for (RtsComponent &c : components) {
        if (c.instanceName == instanceName)
            return &c;
    }
    return nullptr;
}

QHash<QString, qsizetype> RtsProfile::componentIndex() const
{
    QHash<QString, qsizetype> index;
    index.reserve(components.size());
    for (qsizetype i = 0; i < components.size(); ++i) {
        if (!index.contains(components.at(i).instanceName))
            index.insert(components.at(i).instanceName, i);
    }
    return index;
}

const RtsPortConnector *RtsProfile::connector(const QString &connectorId) const
{
    if (const RtsPortConnector *c = dataPortConnector(connectorId))
        return c;
    return servicePortConnector(connectorId);
}

const RtsDataPortConnector *RtsProfile::dataPortConnector(const QString &connectorId) const
{
    for (const RtsDataPortConnector &c : dataPortConnectors) {
        if (c.connectorId == connectorId)
            return &c;
    }
    return nullptr;
}

const RtsServicePortConnector *RtsProfile::servicePortConnector(const QString &connectorId) const
{
    for (const RtsServicePortConnector &c : servicePortConnectors) {
        if (c.connectorId == connectorId)
            return &c;
    }
    return nullptr;
}

const std::optional<RtsMessageSequence> &RtsProfile::sequence(RtsSequenceKind kind) const
{
    switch (kind) {
    case RtsSequenceKind::StartUp:
        return startUp;
    case RtsSequenceKind::ShutDown:
        return shutDown;
    case RtsSequenceKind::Activation:
        return activation;
    case RtsSequenceKind::Deactivation:
        return deactivation;
    case RtsSequenceKind::Resetting:
        return resetting;
    case RtsSequenceKind::Initializing:
        return initializing;
    case RtsSequenceKind::Finalizing:
        break;
    }
    return finalizing;
}

std::optional<RtsMessageSequence> &RtsProfile::sequence(RtsSequenceKind kind)
{
    return const_cast<std::optional<RtsMessageSequence> &>(std::as_const(*this).sequence(kind));
}

bool RtsProfile::operator==(const RtsProfile &other) const
{
    return std::tie(id, version, abstract, creationDate, updateDate, comment, components, groups,
                    dataPortConnectors, servicePortConnectors, startUp, shutDown, activation,
                    deactivation, resetting, initializing, finalizing, versionUpLogs, properties,
                    systems, extras, yamlExtras)
        == std::tie(other.id, other.version, other.abstract, other.creationDate, other.updateDate,
                    other.comment, other.components, other.groups, other.dataPortConnectors,
                    other.servicePortConnectors, other.startUp, other.shutDown, other.activation,
                    other.deactivation, other.resetting, other.initializing, other.finalizing,
                    other.versionUpLogs, other.properties, other.systems, other.extras,
                    other.yamlExtras);
}

} // namespace Profile
