// SPDX-License-Identifier: MIT
// What a connector listener learns about the connection it is called for.
#ifndef RTM_CONNECTORBASE_H
#define RTM_CONNECTORBASE_H

#include <rtm/CdrBufferBase.h>
#include <rtm/DataPortStatus.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

#include <coil/Properties.h>
#include <coil/stringutil.h>

#include <string>
#include <utility>
#include <vector>

namespace RTC
{
/// A connection as OpenRTM describes it: name, id, the ports' names and the connector properties.
class ConnectorInfo
{
public:
    ConnectorInfo(const char *name_, const char *id_, coil::vstring ports_, const coil::Properties &properties_)
        : name(name_), id(id_), ports(ports_), properties(properties_)
    {
    }
    ConnectorInfo() = default;

    std::string name;
    std::string id;
    coil::vstring ports;
    /// The connector's properties without their `dataport.` prefix (`data_type`, `dataflow_type`, …).
    coil::Properties properties;
};
using ConnectorInfoList = std::vector<ConnectorInfo>;

class ConnectorBase;
using ConnectorList = std::vector<ConnectorBase *>;

/// One connection of a data port, as the port's connectors() lists it.
class ConnectorBase
{
public:
    virtual ~ConnectorBase() = default;
    /// The connection's name, id, ports and properties.
    virtual const ConnectorInfo &profile() = 0;
    virtual const char *id() = 0;
    virtual const char *name() = 0;
    /// Ends the connection.
    virtual DataPortStatus disconnect() = 0;
    /// The buffer the connection keeps samples in (null when it has none of its own).
    virtual CdrBufferBase *getBuffer() = 0;
    virtual void activate() = 0;
    virtual void deactivate() = 0;
};
} // namespace RTC

#endif // RTM_CONNECTORBASE_H
