// SPDX-License-Identifier: MIT
// Takes pull samples from an OutPort over shared_memory.
#ifndef RTC_OUTPORTSHMCONSUMER_H
#define RTC_OUTPORTSHMCONSUMER_H

#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/CorbaConsumer.h>
#include <rtm/OutPortConsumer.h>
#include <rtm/SharedMemoryPort.h>
#include <rtm/SystemLogger.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>

namespace RTC {
/**
 * The InPort side of pull connections of interface type `shared_memory`.
 * RT Studio's runtime has no shared_memory transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class OutPortSHMConsumer : public OutPortConsumer
{
public:
    OutPortSHMConsumer();
    ~OutPortSHMConsumer() override;
    void init(coil::Properties &prop) override;
    void setBuffer(CdrBufferBase *buffer) override;
    void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) override;
    DataPortStatus get(ByteData &data) override;
    bool subscribeInterface(const SDOPackage::NVList &properties) override;
    void unsubscribeInterface(const SDOPackage::NVList &properties) override;

private:
    mutable Logger rtclog;
    CdrBufferBase *m_buffer;
    ConnectorInfo m_profile;
    ConnectorListenersBase *m_listeners;
};
} // namespace RTC

extern "C" {
/// Registers the class in its factory under its interface type.
void OutPortSHMConsumerInit();
}

#endif // RTC_OUTPORTSHMCONSUMER_H
