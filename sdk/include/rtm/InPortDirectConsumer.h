// SPDX-License-Identifier: MIT
// Sends push samples to an InPort over direct.
#ifndef RTC_INPORTDIRECTCONSUMER_H
#define RTC_INPORTDIRECTCONSUMER_H

#include <rtm/CorbaConsumer.h>
#include <rtm/InPortConsumer.h>
#include <rtm/Manager.h>
#include <rtm/SystemLogger.h>

#include <condition_variable>

namespace RTC {
/**
 * The OutPort side of push connections of interface type `direct`.
 * RT Studio's runtime has no direct transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class InPortDirectConsumer : public InPortConsumer
{
public:
    InPortDirectConsumer();
    ~InPortDirectConsumer() override;
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
void InPortDirectConsumerInit();
}

#endif // RTC_INPORTDIRECTCONSUMER_H
