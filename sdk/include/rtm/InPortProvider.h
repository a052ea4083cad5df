// SPDX-License-Identifier: MIT
// The receiving end of an InPort connection: what the OutPort side calls.
#ifndef RTC_INPORTPROVIDER_H
#define RTC_INPORTPROVIDER_H

#include <coil/Factory.h>
#include <rtm/BufferBase.h>
#include <rtm/ByteData.h>
#include <rtm/DataPortStatus.h>
#include <rtm/InPortConnector.h>
#include <rtm/SystemLogger.h>
#include <condition_variable>
#include <string>

namespace RTC {
class ConnectorListenersBase;
class ConnectorInfo;

/**
 * What an InPort offers a push connection (an interface type: corba_cdr, ...): it takes the
 * samples the other side sends and puts them into the connection's buffer.
 */
class InPortProvider
{
public:
    InPortProvider();
    virtual ~InPortProvider();
    virtual void init(coil::Properties &prop) = 0;
    virtual void setBuffer(BufferBase<ByteData> *buffer) = 0;
    virtual void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) = 0;
    virtual void setConnector(InPortConnector *connector) = 0;
    /// Adds what the provider offers (`dataport.interface_type`, ...) to a port profile's
    /// properties.
    virtual void publishInterfaceProfile(SDOPackage::NVList &prop);
    /// Adds the provider's interface to connector properties @p prop when they ask for its type.
    virtual bool publishInterface(SDOPackage::NVList &prop);

protected:
    void setInterfaceType(const char *interface_type);
    void setDataFlowType(const char *dataflow_type);
    void setSubscriptionType(const char *subs_type);

    SDOPackage::NVList m_properties;
    mutable Logger rtclog;

private:
    std::string m_interfaceType;
    std::string m_dataflowType;
    std::string m_subscriptionType;
};

/// The providers by interface type (registered by their *Init()).
using InPortProviderFactory = ::coil::GlobalFactory<InPortProvider>;
} // namespace RTC

#endif // RTC_INPORTPROVIDER_H
