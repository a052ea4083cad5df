// SPDX-License-Identifier: MIT
#include "rtscomponent.h"

#include <tuple>

namespace Profile {

bool RtsPort::operator==(const RtsPort &other) const
{
    return std::tie(name, comment, visible, properties, extras, yamlExtras)
        == std::tie(other.name, other.comment, other.visible, other.properties, other.extras,
                    other.yamlExtras);
}

bool RtsConfigurationData::operator==(const RtsConfigurationData &other) const
{
    return std::tie(name, data, extras, yamlExtras)
        == std::tie(other.name, other.data, other.extras, other.yamlExtras);
}

bool RtsConfigurationSet::operator==(const RtsConfigurationSet &other) const
{
    return std::tie(id, data, extras, yamlExtras)
        == std::tie(other.id, other.data, other.extras, other.yamlExtras);
}

std::optional<double> RtsExecutionContext::rateValue() const
{
    if (!rate)
        return std::nullopt;
    bool ok = false;
    const double value = rate->trimmed().toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

bool RtsExecutionContext::operator==(const RtsExecutionContext &other) const
{
    return std::tie(id, kind, rate, participants, properties, extras, yamlExtras)
        == std::tie(other.id, other.kind, other.rate, other.participants, other.properties,
                    other.extras, other.yamlExtras);
}

bool RtsParticipant::operator==(const RtsParticipant &other) const
{
    return std::tie(participant, extras, yamlExtras)
        == std::tie(other.participant, other.extras, other.yamlExtras);
}

std::optional<int> RtsLocation::toInt(const QString &text)
{
    bool ok = false;
    const int value = text.trimmed().toInt(&ok);
    return ok ? std::optional<int>(value) : std::nullopt;
}

QStringList RtsLocation::directions()
{
    return {QStringLiteral("DOWN"), QStringLiteral("RIGHT"), QStringLiteral("UP"),
            QStringLiteral("LEFT")};
}

bool RtsLocation::operator==(const RtsLocation &other) const
{
    return std::tie(x, y, height, width, direction, extras, yamlExtras)
        == std::tie(other.x, other.y, other.height, other.width, other.direction, other.extras,
                    other.yamlExtras);
}

std::optional<RtsComponentTypeId> RtsComponentTypeId::parse(const QString &id)
{
    const QStringList parts = id.split(QLatin1Char(':'));
    if (parts.size() != 5 || parts.at(0) != QLatin1String("RTC"))
        return std::nullopt;
    for (const QString &part : parts) {
        if (part.trimmed().isEmpty())
            return std::nullopt;
    }
    return RtsComponentTypeId {parts.at(1), parts.at(2), parts.at(3), parts.at(4)};
}

QString RtsComponentTypeId::toString() const
{
    return QStringLiteral("RTC:%1:%2:%3:%4").arg(vendor, category, name, version);
}

QStringList RtsComponent::compositeTypes()
{
    return {QStringLiteral("None"),
            QStringLiteral("PeriodicECShared"),
            QStringLiteral("PeriodicStateShared"),
            QStringLiteral("Grouping"),
            QStringLiteral("FsmECShared"),
            QStringLiteral("FsmStateShared")};
}

namespace {
const RtsPort *findPort(const QList<RtsPort> &ports, const QString &name)
{
    for (const RtsPort &port : ports) {
        if (port.name == name)
            return &port;
    }
    return nullptr;
}
} // namespace

const RtsPort *RtsComponent::dataPort(const QString &name) const
{
    return findPort(dataPorts, name);
}

const RtsPort *RtsComponent::servicePort(const QString &name) const
{
    return findPort(servicePorts, name);
}

bool RtsComponent::hasPort(const QString &name) const
{
    return dataPort(name) || servicePort(name);
}

const RtsExecutionContext *RtsComponent::executionContext(const QString &contextId) const
{
    for (const RtsExecutionContext &context : executionContexts) {
        if (context.id == contextId)
            return &context;
    }
    return nullptr;
}

bool RtsComponent::isRequiredValue() const
{
    return parseBoolean(isRequired).value_or(false);
}

bool RtsComponent::operator==(const RtsComponent &other) const
{
    return std::tie(id, pathUri, instanceName, activeConfigurationSet, compositeType, isRequired,
                    comment, visible, dataPorts, servicePorts, configurationSets, executionContexts,
                    participants, layout, properties, extras, yamlExtras)
        == std::tie(other.id, other.pathUri, other.instanceName, other.activeConfigurationSet,
                    other.compositeType, other.isRequired, other.comment, other.visible,
                    other.dataPorts, other.servicePorts, other.configurationSets,
                    other.executionContexts, other.participants, other.layout, other.properties,
                    other.extras, other.yamlExtras);
}

} // namespace Profile
