// SPDX-License-Identifier: MIT
// The OutPort side of corba_cdr pull connections: an OpenRTM::OutPortCdr object.
#ifndef RTC_OUTPORTCORBACDRPROVIDER_H
#define RTC_OUTPORTCORBACDRPROVIDER_H

#include <rtm/BufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/Manager.h>
#include <rtm/OutPortProvider.h>
#include <rtmruntime/outportconnector.h>

namespace RTC {
/**
 * The OutPort side of pull connections of interface type `corba_cdr`.
 */
class OutPortCorbaCdrProvider : public OutPortProvider,
                                public virtual ::POA_OpenRTM::OutPortCdr,
                                public virtual PortableServer::RefCountServantBase
{
public:
    OutPortCorbaCdrProvider();
    ~OutPortCorbaCdrProvider() override;
    void init(coil::Properties &prop) override;
    void setBuffer(CdrBufferBase *buffer) override;
    void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) override;
    void setConnector(OutPortConnector *connector) override;
    ::OpenRTM::PortStatus get(::OpenRTM::CdrData_out data) override;
    bool publishInterface(SDOPackage::NVList &prop) override;

private:
    CdrBufferBase *m_buffer;
    ConnectorInfo m_profile;
    ConnectorListenersBase *m_listeners;
    OutPortConnector *m_connector;
};
} // namespace RTC

extern "C" {
/// Registers the class in its factory under its interface type.
void OutPortCorbaCdrProviderInit();
}

#endif // RTC_OUTPORTCORBACDRPROVIDER_H
