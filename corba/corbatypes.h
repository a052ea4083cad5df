// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <vector>

namespace Corba {

/// An ordered list of name/value properties (SDOPackage::NVList with string values).
using Properties = QList<QPair<QString, QString>>;

/// The value of `key` in `properties`, or `fallback` when absent.
QString propertyValue(const Properties &properties, const QString &key,
                      const QString &fallback = QString());
/// True when `properties` contains `key`.
bool hasProperty(const Properties &properties, const QString &key);
/// Sets `key` to `value`, replacing an existing entry in place or appending.
void setProperty(Properties &properties, const QString &key, const QString &value);

/// RTC::LifeCycleState plus Unknown for "could not ask".
enum class LifeCycleState { Created, Inactive, Active, Error, Unknown };
/// "Created", "Inactive", "Active", "Error", "Unknown" (rtshell's spelling).
QString stateName(LifeCycleState state);

/// One RTC::ConnectorProfile; `ports` holds the port profile names (`Comp0.out`).
struct ConnectorInfo
{
    QString name;
    QString id;
    QStringList ports; ///< the ends' names; empty for an end never seen answering
    Properties properties;
    QStringList portIors; ///< the ends' references, in the order of `ports`
};

/// One RTC::PortInterfaceProfile.
struct PortInterfaceInfo
{
    QString instanceName;
    QString typeName;
    bool provided = true;
};

/// One RTC::PortProfile. `ior` is the port's object reference as a string.
struct PortInfo
{
    QString name; ///< full profile name, `<instance>.<port>`
    std::vector<PortInterfaceInfo> interfaces;
    std::vector<ConnectorInfo> connectors;
    Properties properties;
    QString ior;

    /// The name without the `<instance>.` prefix, as tools show it.
    QString shortName() const;
    /// `port.port_type`: DataInPort, DataOutPort or CorbaPort.
    QString portType() const { return propertyValue(properties, QStringLiteral("port.port_type")); }
    bool isDataIn() const { return portType() == QLatin1String("DataInPort"); }
    bool isDataOut() const { return portType() == QLatin1String("DataOutPort"); }
    bool isService() const { return portType() == QLatin1String("CorbaPort"); }
};

/// RTC::ComponentProfile without the object references.
struct ComponentInfo
{
    QString instanceName;
    QString typeName;
    QString description;
    QString version;
    QString vendor;
    QString category;
    Properties properties;
    std::vector<PortInfo> ports;
};

/**
 * A component's place among composites (SDO organizations): the members of the organizations it
 * owns (a composite's), and the owners of the organizations it belongs to (its composite), by
 * instance name.
 */
struct OrganizationInfo
{
    bool composite = false; ///< owns an organization, even an empty one
    QStringList members;
    QStringList parents;
};

/// A component taking part in an execution context, as its ExecutionContextProfile names it.
struct ContextMember
{
    QString name; ///< instance name; empty when the component did not answer
    QString ior;
};

/// One execution context as seen from one component: owned ones first, then participating.
struct ExecutionContextInfo
{
    int handle = -1; ///< the component's handle for this context
    bool owned = true;
    QString kind; ///< PERIODIC, EVENT_DRIVEN, OTHER
    double rate = 0;
    bool running = false;
    LifeCycleState state = LifeCycleState::Unknown; ///< the component's state in this context
    QString ior;
    /// The owning component and the others taking part (owner not repeated); filled only when
    /// asked for (ComponentProxy::ContextDetail::Members) and the context has a profile.
    ContextMember owner;
    std::vector<ContextMember> participants;
};

/// SDOPackage::ConfigurationSet with string values.
struct ConfigurationSet
{
    QString id;
    QString description;
    Properties data;
};

} // namespace Corba
