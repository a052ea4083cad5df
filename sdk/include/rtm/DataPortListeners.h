// SPDX-License-Identifier: MIT
// What data InPorts and OutPorts share: their properties, what they know of their connections
// and their listeners.
#ifndef RTM_DATAPORTLISTENERS_H
#define RTM_DATAPORTLISTENERS_H

#include <rtm/ConnectorListener.h>

#include <coil/Properties.h>
#include <coil/stringutil.h>

namespace RTC
{
/// The part of InPortBase and OutPortBase that does not depend on the direction.
class DataPortListeners
{
public:
    virtual ~DataPortListeners();

    /// Applies port properties (`buffer.length`, …) as OpenRTM's init() does.
    virtual void init(coil::Properties &prop);
    coil::Properties &properties();
    ConnectorInfoList getConnectorProfiles();
    coil::vstring getConnectorIds();
    coil::vstring getConnectorNames();

    void addConnectorDataListener(ConnectorDataListenerType type, ConnectorDataListener *listener,
                                  bool autoclean = true);
    void removeConnectorDataListener(ConnectorDataListenerType type, ConnectorDataListener *listener);
    void addConnectorListener(ConnectorListenerType type, ConnectorListener *listener, bool autoclean = true);
    void removeConnectorListener(ConnectorListenerType type, ConnectorListener *listener);

protected:
    /// @p data_type is the repository id of the port's sample type.
    explicit DataPortListeners(const char *data_type);

    coil::Properties m_properties;
    ConnectorListeners m_listeners;
};
} // namespace RTC

#endif // RTM_DATAPORTLISTENERS_H
