// SPDX-License-Identifier: MIT
// What a connector listener learns about the connection it is called for.
#ifndef RTM_CONNECTORBASE_H
#define RTM_CONNECTORBASE_H

#include <rtm/RTC.h>

#include <coil/stringutil.h>

#include <string>
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
} // namespace RTC

#endif // RTM_CONNECTORBASE_H
