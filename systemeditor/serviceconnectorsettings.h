// SPDX-License-Identifier: MIT
#pragma once

#include "rtsconnector.h"
#include "systemmodel.h"

#include <QCoreApplication>
#include <QList>
#include <QPair>
#include <QStringList>

#include <optional>

namespace SystemEditor {

/// One end of a service connection as the service connector dialog shows it.
struct ServicePortSide
{
    QString instanceName; ///< the component instance (`ConsoleIn0`)
    QString portName; ///< the port's name without the instance prefix (`control`)
    QList<InterfaceInfo> interfaces;
};

/**
 * CorbaPort's interface descriptor `<instance>.port.<port>.<required|provided>.<type>.<name>`,
 * the form the reference's service connector dialog writes as a connector property
 * (consumer descriptor = provider descriptor). OpenRTM's newer key `port.<type>.<name>` names a
 * required interface by type and instance name only; parse() reads it with empty component and
 * port.
 */
struct InterfaceDescriptor
{
    QString componentName;
    QString portName;
    bool required = true;
    QString type;
    QString instanceName;

    static InterfaceDescriptor of(const ServicePortSide &side, const InterfaceInfo &interface);
    /// Either form, or nothing when `text` is not a descriptor.
    static std::optional<InterfaceDescriptor> parse(const QString &text);
    QString toString() const;
    /// Whether this descriptor names `interface` of `side` (a short form matches by type and name).
    bool names(const ServicePortSide &side, const InterfaceInfo &interface) const;
};

/**
 * The fields of the service connector dialog, as a value: the name, the connect direction and
 * the explicit interface mapping (consumer descriptor → provider descriptor, written as
 * connector properties). Interfaces without an entry pair up by instance name when connecting,
 * as OpenRTM does.
 *
 * The connect direction is the port that calls `connect()`. As for data connectors, a system
 * file records it as the connector's source end (rtshell and the restore engine connect from the
 * source port), so choosing the other port turns the connector around.
 */
struct ServiceConnectorSettings
{
    Q_DECLARE_TR_FUNCTIONS(ServiceConnectorSettings)

public:
    QString name;
    QList<QPair<QString, QString>> mapping; ///< consumer descriptor, provider descriptor
    /// The port that calls connect(): component instance and port name, with or without the
    /// `instance.` prefix. Empty leaves the connector's ends as they are.
    ConnectorEnd connectingPort;

    static ServiceConnectorSettings fromConnector(const Profile::RtsServicePortConnector &connector);
    /**
     * Writes the name, replaces the connector's mapping properties by `mapping` and, when
     * `connectingPort` is the connector's target end, swaps the ends (the route is kept).
     */
    void applyTo(Profile::RtsServicePortConnector &connector) const;
    /// Whether `end` is the port `port` names (port names compared with or without the prefix).
    static bool isSamePort(const Profile::RtsTargetPort &end, const ConnectorEnd &port);
    /// True for a property key that is an interface mapping (either descriptor form).
    static bool isMappingKey(const QString &key);
    /// Problems that keep the settings from being applied (the name).
    QStringList validate() const;

    bool operator==(const ServiceConnectorSettings &other) const;
    bool operator!=(const ServiceConnectorSettings &other) const { return !(*this == other); }
};

} // namespace SystemEditor
