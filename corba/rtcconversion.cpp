// SPDX-License-Identifier: MIT
#include "rtcconversion.h"

#include "corbacall.h"

#include <QHash>
#include <QMutex>

namespace Corba::Internal {

namespace {

/**
 * Port names by port reference. A connector profile names its ports by reference only, and
 * asking each port for its profile is a remote call per end: reading a system of a thousand
 * components asked several thousand of them. A port keeps its name for its life and its reference
 * is its own, so a name read once (or seen in the port's own profile) is not asked again.
 */
class PortNames
{
public:
    QString find(const QString &ior) const
    {
        const QMutexLocker lock(&m_mutex);
        return m_names.value(ior);
    }
    void insert(const QString &ior, const QString &name)
    {
        if (ior.isEmpty() || name.isEmpty())
            return;
        const QMutexLocker lock(&m_mutex);
        // Bounded (a few MiB; a system of a thousand components has a few thousand ports): a long
        // session that meets many short-lived ports starts over now and then.
        if (m_names.size() >= MaxNames)
            m_names.clear();
        m_names.insert(ior, name);
    }

private:
    static constexpr qsizetype MaxNames = 16384;
    mutable QMutex m_mutex;
    QHash<QString, QString> m_names;
};

PortNames &portNames()
{
    // Never destroyed: worker threads may still read profiles while the process exits.
    static auto *const names = new PortNames;
    return *names;
}

// A port reference can be dead (its owner exited); the profile is still worth showing.
QString portName(RTC::PortService_ptr port, const QString &ior)
{
    QString name = portNames().find(ior);
    if (!name.isEmpty())
        return name;
    try {
        name = call(QStringLiteral("port"), [&] {
            RTC::PortProfile_var profile = port->get_port_profile();
            return toQString(profile->name.in());
        });
    } catch (const Error &) {
        return QString();
    }
    portNames().insert(ior, name);
    return name;
}

} // namespace

ConnectorInfo toConnectorInfo(const RTC::ConnectorProfile &profile)
{
    ConnectorInfo info;
    info.name = toQString(profile.name.in());
    info.id = toQString(profile.connector_id.in());
    info.properties = fromNVList(profile.properties);
    for (CORBA::ULong i = 0; i < profile.ports.length(); ++i) {
        info.portIors.append(toIor(profile.ports[i].in()));
        info.ports.append(portName(profile.ports[i].in(), info.portIors.constLast()));
    }
    return info;
}

PortInfo toPortInfo(const RTC::PortProfile &profile)
{
    PortInfo info;
    info.name = toQString(profile.name.in());
    info.properties = fromNVList(profile.properties);
    info.ior = toIor(profile.port_ref.in());
    portNames().insert(info.ior, info.name);
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
