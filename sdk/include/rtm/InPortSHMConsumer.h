// SPDX-License-Identifier: MIT
// Sends push samples to an InPort over shared_memory.
#ifndef RTC_INPORTSHMCONSUMER_H
#define RTC_INPORTSHMCONSUMER_H

#include <rtm/CorbaConsumer.h>
#include <rtm/InPortConsumer.h>
#include <rtm/Manager.h>
#include <rtm/SharedMemoryPort.h>
#include <rtm/SystemLogger.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>

namespace RTC {
/**
 * The OutPort side of push connections of interface type `shared_memory`.
 * RT Studio's runtime has no shared_memory transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class InPortSHMConsumer : public InPortConsumer
{
public:
    InPortSHMConsumer();
    ~InPortSHMConsumer() override;
    void init(coil::Properties &prop) override;
    DataPortStatus put(ByteData &data) override;
    void publishInterfaceProfile(SDOPackage::NVList &properties) override;
    bool subscribeInterface(const SDOPackage::NVList &properties) override;
    void unsubscribeInterface(const SDOPackage::NVList &properties) override;

private:
    mutable Logger rtclog;
    coil::Properties m_properties;
};
} // namespace RTC

extern "C" {
/// Registers the class in its factory under its interface type.
void InPortSHMConsumerInit();
}

#endif // RTC_INPORTSHMCONSUMER_H
