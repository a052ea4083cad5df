// SPDX-License-Identifier: MIT
// The untyped part of a data OutPort.
#ifndef RTM_OUTPORTBASE_H
#define RTM_OUTPORTBASE_H

#include <rtm/ConnectorListener.h>
#include <rtm/PortBase.h>

#include <rtmruntime/outport.h>

#include <string>

namespace RTC
{
/// A data OutPort without its sample type: connections, properties and listeners.
class OutPortBase : public ::Runtime::OutPortBase
{
public:
    /// @p data_type is the repository id of the sample type (`IDL:RTC/TimedLong:1.0`).
    OutPortBase(const char *name, const char *data_type);
    ~OutPortBase() override;

    /// Sends the bound variable to every connection.
    virtual bool write() = 0;

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

    ReturnCode_t notify_connect(ConnectorProfile &connector_profile) override;
    ReturnCode_t notify_disconnect(const char *connector_id) override;

protected:
    /// Hands a sample to the connections; @p marshal gives its bytes in the byte order asked for.
    void writeBytes(const std::function<::Runtime::CdrBytes(bool littleEndian)> &marshal);

    coil::Properties m_properties;
    ConnectorListeners m_listeners;
};
} // namespace RTC

#endif // RTM_OUTPORTBASE_H
