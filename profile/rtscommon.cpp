// SPDX-License-Identifier: MIT
#include "rtscommon.h"

#include <tuple>

namespace Profile {

bool RtsProperty::operator==(const RtsProperty &other) const
{
    return std::tie(name, value, extras, yamlExtras)
        == std::tie(other.name, other.value, other.extras, other.yamlExtras);
}

std::optional<QString> rtsPropertyValue(const RtsProperties &properties, const QString &name)
{
    for (const RtsProperty &p : properties) {
        if (p.name == name)
            return p.value;
    }
    return std::nullopt;
}

void setRtsProperty(RtsProperties &properties, const QString &name, const QString &value)
{
    for (RtsProperty &p : properties) {
        if (p.name == name) {
            p.value = value;
            return;
        }
    }
    RtsProperty property;
    property.name = name;
    property.value = value;
    properties.append(property);
}

bool RtsTargetComponent::operator==(const RtsTargetComponent &other) const
{
    return std::tie(componentId, instanceName, properties, extras, yamlExtras)
        == std::tie(other.componentId, other.instanceName, other.properties, other.extras,
                    other.yamlExtras);
}

bool RtsTargetPort::operator==(const RtsTargetPort &other) const
{
    return RtsTargetComponent::operator==(other) && portName == other.portName;
}

bool RtsTargetExecutionContext::operator==(const RtsTargetExecutionContext &other) const
{
    return RtsTargetComponent::operator==(other) && id == other.id;
}

} // namespace Profile
