// SPDX-License-Identifier: MIT
// The InPort side of shared_memory push connections.
#ifndef RTC_INPORTSHMPROVIDER_H
#define RTC_INPORTSHMPROVIDER_H

#include <rtm/BufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/InPortProvider.h>
#include <rtm/Manager.h>
#include <rtm/SharedMemoryPort.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>

namespace RTC {
/**
 * The InPort side of push connections of interface type `shared_memory`.
 * RT Studio's runtime has no shared_memory transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class InPortSHMProvider : public InPortProvider
{
public:
    InPortSHMProvider();
    ~InPortSHMProvider() override;
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
void InPortSHMProviderInit();
}

#endif // RTC_INPORTSHMPROVIDER_H
