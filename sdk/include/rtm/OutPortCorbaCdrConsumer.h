// SPDX-License-Identifier: MIT
// Takes pull samples from an OutPort's OpenRTM::OutPortCdr object.
#ifndef RTC_OUTPORTCORBACDRCONSUMER_H
#define RTC_OUTPORTCORBACDRCONSUMER_H

#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/CorbaConsumer.h>
#include <rtm/OutPortConsumer.h>
#include <rtm/SystemLogger.h>
#include <rtmruntime/outportconnector.h>

namespace RTC {
/**
 * The InPort side of pull connections of interface type `corba_cdr`.
 */
class OutPortCorbaCdrConsumer : public OutPortConsumer, public CorbaConsumer<::OpenRTM::OutPortCdr>
{
public:
    OutPortCorbaCdrConsumer();
    ~OutPortCorbaCdrConsumer() override;
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
void OutPortCorbaCdrConsumerInit();
}

#endif // RTC_OUTPORTCORBACDRCONSUMER_H
