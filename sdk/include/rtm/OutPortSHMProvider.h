// SPDX-License-Identifier: MIT
// The OutPort side of shared_memory pull connections.
#ifndef RTC_OUTPORTSHMPROVIDER_H
#define RTC_OUTPORTSHMPROVIDER_H

#include <rtm/BufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/Manager.h>
#include <rtm/OutPortProvider.h>
#include <rtm/SharedMemoryPort.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>

namespace RTC {
/**
 * The OutPort side of pull connections of interface type `shared_memory`.
 * RT Studio's runtime has no shared_memory transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class OutPortSHMProvider : public OutPortProvider
{
public:
    OutPortSHMProvider();
    ~OutPortSHMProvider() override;
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
void OutPortSHMProviderInit();
}

#endif // RTC_OUTPORTSHMPROVIDER_H
