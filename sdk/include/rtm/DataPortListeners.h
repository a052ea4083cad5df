// SPDX-License-Identifier: MIT
// What data InPorts and OutPorts share: their properties, what they know of their connections
// and their listeners.
#ifndef RTM_DATAPORTLISTENERS_H
#define RTM_DATAPORTLISTENERS_H

#include <rtm/ConnectorListener.h>
#include <rtm/SystemLogger.h>

#include <coil/Properties.h>
#include <coil/stringutil.h>

#include <rtmruntime/properties.h>

namespace RTC
{
/// The part of InPortBase and OutPortBase that does not depend on the direction.
class DataPortListeners
{
public:
    virtual ~DataPortListeners();

    /**
     * Takes port properties (`buffer.length`, `subscription_type`, …) as OpenRTM's init() does:
     * they are the defaults of every connection's `dataport.*` settings. A component's
     * addInPort() / addOutPort() gives a port rtc.conf's `port.inport.<name>.*` (`port.outport.…`).
     */
    virtual void init(coil::Properties &prop);
    coil::Properties &properties();
    ConnectorInfoList getConnectorProfiles();
    /// The port's listeners, as connectors, publishers and providers are given them.
    virtual ConnectorListenersBase *getListeners() { return &m_listeners; }
    coil::vstring getConnectorIds();
    coil::vstring getConnectorNames();
    /// Copies the information of connection @p id into @p prof; false when there is no such connection.
    bool getConnectorProfileById(const char *id, ConnectorInfo &prof);
    /// The same for the connection named @p name.
    bool getConnectorProfileByName(const char *name, ConnectorInfo &prof);
    /// True when the samples of the port's connections travel little-endian (the default).
    bool isLittleEndian();

    void addConnectorDataListener(ConnectorDataListenerType type, ConnectorDataListener *listener,
                                  bool autoclean = true);
    void removeConnectorDataListener(ConnectorDataListenerType type, ConnectorDataListener *listener);
    void addConnectorListener(ConnectorListenerType type, ConnectorListener *listener, bool autoclean = true);
    void removeConnectorListener(ConnectorListenerType type, ConnectorListener *listener);

protected:
    /// @p data_type is the repository id of the port's sample type.
    explicit DataPortListeners(const char *data_type);

    /// The port properties init() took, as connector settings (`dataport.buffer.length`, …).
    ::Runtime::Properties connectorSettings() const;
    /// Logs that the port @p portName refused connector @p profile for @p problem.
    void logRefusal(const char *portName, const ConnectorProfile &profile, const std::string &problem) const;

    coil::Properties m_properties;
    ConnectorListeners m_listeners;
    mutable Logger rtclog;
};
} // namespace RTC

#endif // RTM_DATAPORTLISTENERS_H
