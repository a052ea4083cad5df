// SPDX-License-Identifier: MIT
#include "rtcconversion.h"

#include "corbacall.h"

namespace Corba::Internal {

namespace {

// A port reference can be dead (its owner exited); the profile is still worth showing.
QString portName(RTC::PortService_ptr port)
{
    try {
        return call(QStringLiteral("port"), [&] {
            RTC::PortProfile_var profile = port->get_port_profile();
            return toQString(profile->name.in());
        });
    } catch (const Error &) {
        return QString();
    }
}

} // namespace

ConnectorInfo toConnectorInfo(const RTC::ConnectorProfile &profile)
{
    ConnectorInfo info;
    info.name = toQString(profile.name.in());
    info.id = toQString(profile.connector_id.in());
    info.properties = fromNVList(profile.properties);
    for (CORBA::ULong i = 0; i < profile.ports.length(); ++i)
        info.ports.append(portName(profile.ports[i].in()));
    return info;
}

PortInfo toPortInfo(const RTC::PortProfile &profile)
{
    PortInfo info;
    info.name = toQString(profile.name.in());
    info.properties = fromNVList(profile.properties);
    info.ior = toIor(profile.port_ref.in());
    for (CORBA::ULong i = 0; i < profile.interfaces.length(); ++i) {
        const RTC::PortInterfaceProfile &interface = profile.interfaces[i];
        info.interfaces.push_back({toQString(interface.instance_name.in()),
                                   toQString(interface.type_name.in()),
                                   interface.polarity == RTC::PROVIDED});
    }
    for (CORBA::ULong i = 0; i < profile.connector_profiles.length(); ++i)
        info.connectors.push_back(toConnectorInfo(profile.connector_profiles[i]));
    return info;
}

ComponentInfo toComponentInfo(const RTC::ComponentProfile &profile)
{
    ComponentInfo info;
    info.instanceName = toQString(profile.instance_name.in());
    info.typeName = toQString(profile.type_name.in());
    info.description = toQString(profile.description.in());
    info.version = toQString(profile.version.in());
    info.vendor = toQString(profile.vendor.in());
    info.category = toQString(profile.category.in());
    info.properties = fromNVList(profile.properties);
    for (CORBA::ULong i = 0; i < profile.port_profiles.length(); ++i)
        info.ports.push_back(toPortInfo(profile.port_profiles[i]));
    return info;
}

LifeCycleState toLifeCycleState(RTC::LifeCycleState state)
{
    switch (state) {
    case RTC::CREATED_STATE:
        return LifeCycleState::Created;
    case RTC::INACTIVE_STATE:
        return LifeCycleState::Inactive;
    case RTC::ACTIVE_STATE:
        return LifeCycleState::Active;
    case RTC::ERROR_STATE:
        return LifeCycleState::Error;
    default:
        break;
    }
    return LifeCycleState::Unknown;
}

QString executionKindName(RTC::ExecutionKind kind)
{
    switch (kind) {
    case RTC::PERIODIC:
        return QStringLiteral("PERIODIC");
    case RTC::EVENT_DRIVEN:
        return QStringLiteral("EVENT_DRIVEN");
    default:
        break;
    }
    return QStringLiteral("OTHER");
}

ConfigurationSet toConfigurationSet(const SDOPackage::ConfigurationSet &set)
{
    return {toQString(set.id.in()), toQString(set.description.in()),
            fromNVList(set.configuration_data)};
}

SDOPackage::ConfigurationSet toSdoConfigurationSet(const ConfigurationSet &set)
{
    SDOPackage::ConfigurationSet result;
    result.id = set.id.toUtf8().constData();
    result.description = set.description.toUtf8().constData();
    result.configuration_data = toNVList(set.data);
    return result;
}

} // namespace Corba::Internal
