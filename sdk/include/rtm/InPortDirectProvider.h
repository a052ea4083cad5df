// SPDX-License-Identifier: MIT
// The InPort side of direct push connections.
#ifndef RTC_INPORTDIRECTPROVIDER_H
#define RTC_INPORTDIRECTPROVIDER_H

#include <rtm/BufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/InPortProvider.h>
#include <rtm/Manager.h>

#include <condition_variable>

namespace RTC {
/**
 * The InPort side of push connections of interface type `direct`.
 * RT Studio's runtime has no direct transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class InPortDirectProvider : public InPortProvider
{
public:
    InPortDirectProvider();
    ~InPortDirectProvider() override;
    void init(coil::Properties &prop) override;
    void setBuffer(BufferBase<ByteData> *buffer) override;
    void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) override;
    void setConnector(InPortConnector *connector) override;
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
void InPortDirectProviderInit();
}

#endif // RTC_INPORTDIRECTPROVIDER_H
