// SPDX-License-Identifier: MIT
// The OutPort side of direct pull connections.
#ifndef RTC_OUTPORTDIRECTPROVIDER_H
#define RTC_OUTPORTDIRECTPROVIDER_H

#include <rtm/BufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/Manager.h>
#include <rtm/OutPortProvider.h>

#include <condition_variable>

namespace RTC {
/**
 * The OutPort side of pull connections of interface type `direct`.
 * RT Studio's runtime has no direct transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class OutPortDirectProvider : public OutPortProvider
{
public:
    OutPortDirectProvider();
    ~OutPortDirectProvider() override;
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
void OutPortDirectProviderInit();
}

#endif // RTC_OUTPORTDIRECTPROVIDER_H
