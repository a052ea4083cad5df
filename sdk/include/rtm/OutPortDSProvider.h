// SPDX-License-Identifier: MIT
// The OutPort side of data_service pull connections.
#ifndef RTC_OUTPORTDSPROVIDER_H
#define RTC_OUTPORTDSPROVIDER_H

#include <rtm/BufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/Manager.h>
#include <rtm/OutPortProvider.h>

#include <condition_variable>

namespace RTC {
/**
 * The OutPort side of pull connections of interface type `data_service`.
 * RT Studio's runtime has no data_service transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class OutPortDSProvider : public OutPortProvider
{
public:
    OutPortDSProvider();
    ~OutPortDSProvider() override;
    void init(coil::Properties &prop) override;
    void setBuffer(CdrBufferBase *buffer) override;
    void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) override;
    void setConnector(OutPortConnector *connector) override;
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
void OutPortDSProviderInit();
}

#endif // RTC_OUTPORTDSPROVIDER_H
