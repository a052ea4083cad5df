// SPDX-License-Identifier: MIT
// The InPort side of corba_cdr push connections: an OpenRTM::InPortCdr object.
#ifndef RTC_INPORTCORBACDRPROVIDER_H
#define RTC_INPORTCORBACDRPROVIDER_H

#include <rtm/BufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/InPortProvider.h>
#include <rtm/Manager.h>
#include <rtmruntime/inportconnector.h>

namespace RTC {
/**
 * The InPort side of push connections of interface type `corba_cdr`.
 */
class InPortCorbaCdrProvider : public InPortProvider,
                               public virtual POA_OpenRTM::InPortCdr,
                               public virtual PortableServer::RefCountServantBase
{
public:
    InPortCorbaCdrProvider();
    ~InPortCorbaCdrProvider() override;
    void init(coil::Properties &prop) override;
    void setBuffer(BufferBase<ByteData> *buffer) override;
    void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) override;
    void setConnector(InPortConnector *connector) override;
    ::OpenRTM::PortStatus put(const ::OpenRTM::CdrData &data) override;
    bool publishInterface(SDOPackage::NVList &prop) override;

private:
    CdrBufferBase *m_buffer;
    ConnectorInfo m_profile;
    ConnectorListenersBase *m_listeners;
    InPortConnector *m_connector;
};
} // namespace RTC

extern "C" {
/// Registers the class in its factory under its interface type.
void InPortCorbaCdrProviderInit();
}

#endif // RTC_INPORTCORBACDRPROVIDER_H
