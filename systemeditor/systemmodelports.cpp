// SPDX-License-Identifier: MIT
// SystemModel's port queries: merging what the RTC profile says about a component's ports with
// the port names the system file uses.
#include "systemmodel.h"

#include <QSet>

namespace SystemEditor {

using namespace Profile;

namespace {

PortSide sideFromPosition(const QString &position, PortSide fallback)
{
    const QString upper = position.trimmed().toUpper();
    if (upper == QLatin1String("LEFT"))
        return PortSide::Left;
    if (upper == QLatin1String("RIGHT"))
        return PortSide::Right;
    if (upper == QLatin1String("TOP"))
        return PortSide::Top;
    if (upper == QLatin1String("BOTTOM"))
        return PortSide::Bottom;
    return fallback;
}

/// All port names the system file lists for a component.
QStringList listedPortNames(const RtsComponent &component)
{
    QStringList names;
    for (const RtsPort &port : component.dataPorts)
        names << port.name;
    for (const RtsPort &port : component.servicePorts)
        names << port.name;
    return names;
}

/**
 * The system-file name of the RTC profile port `profileName`: the listed name that is exactly it
 * or `<instance>.<it>`, else one ending in `.<it>` (a component renamed by hand), else RTSE's
 * `<instance>.<it>`.
 */
QString systemPortName(const RtsComponent &component, const QStringList &listed,
                       const QString &profileName)
{
    const QString qualified = component.instanceName + QLatin1Char('.') + profileName;
    if (listed.contains(qualified))
        return qualified;
    if (listed.contains(profileName))
        return profileName;
    for (const QString &name : listed) {
        if (name.endsWith(QLatin1Char('.') + profileName))
            return name;
    }
    return qualified;
}

PortKind dataPortKind(const RtcDataPort &port)
{
    switch (port.kind()) {
    case RtcPortType::DataIn:
    case RtcPortType::Event:
        return PortKind::DataIn;
    case RtcPortType::DataOut:
        return PortKind::DataOut;
    case RtcPortType::Unknown:
        break;
    }
    return PortKind::Unknown;
}

QList<InterfaceInfo> interfacesOf(const RtcServicePort &port)
{
    QList<InterfaceInfo> result;
    for (const RtcServiceInterface &i : port.interfaces)
        result << InterfaceInfo {i.name, i.type, i.instanceName.value_or(QString()), i.kind()};
    return result;
}

} // namespace

QList<PortInfo> SystemModel::ports(const QString &instanceName) const
{
    const RtsComponent *component = this->component(instanceName);
    if (!component)
        return {};
    const Direction direction = layout(instanceName).direction;
    const QStringList listed = listedPortNames(*component);
    QSet<QString> used;
    QList<PortInfo> result;

    if (const RtcProfile *rtc = rtcProfile(instanceName)) {
        for (const RtcDataPort &p : rtc->dataPorts) {
            PortInfo info;
            info.name = systemPortName(*component, listed, p.name);
            info.profileName = p.name;
            info.kind = dataPortKind(p);
            info.dataType = p.type;
            info.profileSide = sideFromPosition(
                p.position, info.kind == PortKind::DataOut ? PortSide::Right : PortSide::Left);
            info.described = true;
            result << info;
        }
        for (const RtcServicePort &p : rtc->servicePorts) {
            PortInfo info;
            info.name = systemPortName(*component, listed, p.name);
            info.profileName = p.name;
            info.kind = PortKind::Service;
            info.interfaces = interfacesOf(p);
            info.profileSide = sideFromPosition(p.position, PortSide::Right);
            info.described = true;
            result << info;
        }
        for (const PortInfo &info : std::as_const(result))
            used.insert(info.name);
    }

    const auto addListed = [&](const RtsPort &port, bool service) {
        if (used.contains(port.name))
            return;
        used.insert(port.name);
        PortInfo info;
        info.name = port.name;
        info.profileName = port.name;
        info.kind = service ? PortKind::Service : PortKind::Unknown;
        // Without a profile, a port that sends along a data connector is most likely an output.
        bool isSource = false;
        for (const RtsDataPortConnector &c : m_profile.dataPortConnectors)
            isSource = isSource
                || (c.source.instanceName == instanceName && c.source.portName == port.name);
        info.profileSide = isSource || service ? PortSide::Right : PortSide::Left;
        result << info;
    };
    for (const RtsPort &port : component->dataPorts)
        addListed(port, false);
    for (const RtsPort &port : component->servicePorts)
        addListed(port, true);

    for (PortInfo &info : result)
        info.side = rotatedSide(info.profileSide, direction);
    return result;
}

std::optional<PortInfo> SystemModel::port(const QString &instanceName,
                                          const QString &portName) const
{
    for (const PortInfo &info : ports(instanceName)) {
        if (info.name == portName)
            return info;
    }
    return std::nullopt;
}

} // namespace SystemEditor
