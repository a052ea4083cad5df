// SPDX-License-Identifier: MIT
// The sending end of a pull connection: what the InPort side calls.
#ifndef RTC_OUTPORTPROVIDER_H
#define RTC_OUTPORTPROVIDER_H

#include <coil/Factory.h>
#include <rtm/BufferBase.h>
#include <rtm/DataPortStatus.h>
#include <rtm/OutPortConnector.h>
#include <rtm/SystemLogger.h>
#include <condition_variable>
#include <string>

namespace RTC {
class ConnectorListenersBase;

/// What an OutPort offers a pull connection: the InPort side takes samples from its buffer.
class OutPortProvider
{
public:
    virtual ~OutPortProvider();
    virtual void init(coil::Properties &prop);
    virtual void setBuffer(CdrBufferBase *buffer) = 0;
    virtual void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) = 0;
    virtual void setConnector(OutPortConnector *connector) = 0;
    virtual void publishInterfaceProfile(SDOPackage::NVList &prop);
    virtual bool publishInterface(SDOPackage::NVList &prop);

protected:
    void setPortType(const char *port_type);
    void setDataType(const char *data_type);
    void setInterfaceType(const char *interface_type);
    void setDataFlowType(const char *dataflow_type);
    void setSubscriptionType(const char *subs_type);

    SDOPackage::NVList m_properties;
    mutable Logger rtclog;

private:
    std::string m_portType;
    std::string m_dataType;
    std::string m_interfaceType;
    std::string m_dataflowType;
    std::string m_subscriptionType;
};

/// The providers by interface type (registered by their *Init()).
using OutPortProviderFactory = ::coil::GlobalFactory<OutPortProvider>;
} // namespace RTC

#endif // RTC_OUTPORTPROVIDER_H
