// SPDX-License-Identifier: MIT
// Sends push samples to an InPort's OpenRTM::InPortCdr object.
#ifndef RTC_INPORTCORBACDRCONSUMER_H
#define RTC_INPORTCORBACDRCONSUMER_H

#include <rtm/CorbaConsumer.h>
#include <rtm/InPortConsumer.h>
#include <rtm/Manager.h>
#include <rtm/SystemLogger.h>
#include <rtmruntime/inportconnector.h>

namespace RTC {
/**
 * The OutPort side of push connections of interface type `corba_cdr`.
 */
class InPortCorbaCdrConsumer : public InPortConsumer, public CorbaConsumer<::OpenRTM::InPortCdr>
{
public:
    InPortCorbaCdrConsumer();
    ~InPortCorbaCdrConsumer() override;
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
void InPortCorbaCdrConsumerInit();
}

#endif // RTC_INPORTCORBACDRCONSUMER_H
