// SPDX-License-Identifier: MIT
#include "rtccommon.h"

#include <tuple>

namespace Profile {

bool RtcProperty::operator==(const RtcProperty &other) const
{
    return std::tie(name, value, missing, extras)
        == std::tie(other.name, other.value, other.missing, other.extras);
}

std::optional<QString> rtcPropertyValue(const RtcProperties &properties, const QString &name)
{
    for (const RtcProperty &property : properties) {
        if (property.name == name)
            return property.value;
    }
    return std::nullopt;
}

void setRtcProperty(RtcProperties &properties, const QString &name, const QString &value)
{
    for (RtcProperty &property : properties) {
        if (property.name == name) {
            property.value = value;
            return;
        }
    }
    RtcProperty property;
    property.name = name;
    property.value = value;
    properties.append(property);
}

const QStringList &rtcComponentTypes()
{
    static const QStringList values {QStringLiteral("STATIC"), QStringLiteral("UNIQUE"),
                                     QStringLiteral("COMMUTATIVE")};
    return values;
}

const QStringList &rtcActivityTypes()
{
    static const QStringList values {QStringLiteral("PERIODIC"), QStringLiteral("SPORADIC"),
                                     QStringLiteral("EVENTDRIVEN")};
    return values;
}

const QStringList &rtcPositions()
{
    static const QStringList values {QStringLiteral("LEFT"), QStringLiteral("RIGHT"),
                                     QStringLiteral("TOP"), QStringLiteral("BOTTOM")};
    return values;
}

const QStringList &rtcPortTypes()
{
    static const QStringList values {QStringLiteral("DataInPort"), QStringLiteral("DataOutPort"),
                                     QStringLiteral("EventPort")};
    return values;
}

RtcPortType rtcPortType(const QString &text)
{
    switch (rtcPortTypes().indexOf(text)) {
    case 0:
        return RtcPortType::DataIn;
    case 1:
        return RtcPortType::DataOut;
    case 2:
        return RtcPortType::Event;
    default:
        return RtcPortType::Unknown;
    }
}

QString rtcPortTypeText(RtcPortType type)
{
    return type == RtcPortType::Unknown ? QString() : rtcPortTypes().at(int(type));
}

const QStringList &rtcDirections()
{
    static const QStringList values {QStringLiteral("Provided"), QStringLiteral("Required")};
    return values;
}

RtcDirection rtcDirection(const QString &text)
{
    switch (rtcDirections().indexOf(text)) {
    case 0:
        return RtcDirection::Provided;
    case 1:
        return RtcDirection::Required;
    default:
        return RtcDirection::Unknown;
    }
}

QString rtcDirectionText(RtcDirection direction)
{
    return direction == RtcDirection::Unknown ? QString() : rtcDirections().at(int(direction));
}

} // namespace Profile
