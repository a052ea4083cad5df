// SPDX-License-Identifier: MIT
#include "corbatypes.h"

namespace Corba {

QString propertyValue(const Properties &properties, const QString &key, const QString &fallback)
{
    for (const auto &property : properties) {
        if (property.first == key)
            return property.second;
    }
    return fallback;
}

bool hasProperty(const Properties &properties, const QString &key)
{
    for (const auto &property : properties) {
        if (property.first == key)
            return true;
    }
    return false;
}

void setProperty(Properties &properties, const QString &key, const QString &value)
{
    for (auto &property : properties) {
        if (property.first == key) {
            property.second = value;
            return;
        }
    }
    properties.append({key, value});
}

QString stateName(LifeCycleState state)
{
    switch (state) {
    case LifeCycleState::Created:
        return QStringLiteral("Created");
    case LifeCycleState::Inactive:
        return QStringLiteral("Inactive");
    case LifeCycleState::Active:
        return QStringLiteral("Active");
    case LifeCycleState::Error:
        return QStringLiteral("Error");
    case LifeCycleState::Unknown:
        break;
    }
    return QStringLiteral("Unknown");
}

QString PortInfo::shortName() const
{
    const int dot = name.indexOf(QLatin1Char('.'));
    return dot < 0 ? name : name.mid(dot + 1);
}

} // namespace Corba
