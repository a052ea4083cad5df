// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QString>

#include <vector>

namespace Corba {

/// What `rtcon` asks for: connector name and id (empty = defaults) and extra properties.
struct ConnectionRequest
{
    QString name;
    QString id;
    Properties properties;
    bool noDuplicates = false;
};

/**
 * Connecting and disconnecting ports with rtshell's rules. The checks are plain functions of the
 * ports' profiles, so they can run (and be tested) without a remote call.
 */
class PortConnection
{
public:
    /**
     * The properties a connection of `ports` (source first) would use: for data ports rtcon's
     * defaults (`dataport.dataflow_type=push`, `interface_type=corba_cdr`, `subscription_type=new`,
     * `data_type` = the source port's) overlaid by `given`.
     */
    static Properties effectiveProperties(const std::vector<PortInfo> &ports,
                                          const Properties &given);
    /**
     * Why `ports` cannot be connected with `properties` (as returned by effectiveProperties()), or
     * an empty string when they can. Data ports: one out and the others in, and each `dataport.*`
     * value must be in each port's allowed list unless that list says `any`. Service ports: each
     * interface of the first port must find one with the same instance name and opposite polarity.
     */
    static QString problem(const std::vector<PortInfo> &ports, const Properties &properties);
    /**
     * The values of @p key (e.g. `dataport.subscription_type`) every one of @p ports allows, in
     * the order of the first port that lists them; a port that says `Any` or lists nothing
     * allows everything. Empty when none restricts the key or they have nothing in common.
     */
    static QStringList commonValues(const std::vector<PortInfo> &ports, const QString &key);
    /// rtcon's default connector name: the ports' short names joined by '_'.
    static QString defaultName(const std::vector<PortInfo> &ports);

    /**
     * Connects `ports` (at least two; the first one is called). Throws Incompatible when problem()
     * says so, Refused when the port refuses or (with noDuplicates) when the ports are already
     * connected. Returns the connector as the port filled it in (with its id).
     */
    static ConnectorInfo connect(const std::vector<PortInfo> &ports,
                                 const ConnectionRequest &request, const QString &path);
    /**
     * Connects `ports` (at least one; the first one is called) with exactly `properties`, without
     * rtcon's defaults and checks: for connectors whose other end is not a port (a tool's own
     * InPortCdr object named in the properties). Returns the connector as the port filled it in.
     */
    static ConnectorInfo connectAsGiven(const std::vector<PortInfo> &ports, const QString &name,
                                        const QString &id, const Properties &properties,
                                        const QString &path);
    /// Disconnects the connector `connectorId` through `port`.
    static void disconnect(const PortInfo &port, const QString &connectorId, const QString &path);
    /// Disconnects every connector of `port`.
    static void disconnectAll(const PortInfo &port, const QString &path);
    /// True when an end of `connector` no longer answers (its process has gone or hangs): asks
    /// each end, one call each.
    static bool hasEndGone(const ConnectorInfo &connector);
};

} // namespace Corba
