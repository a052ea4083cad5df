// SPDX-License-Identifier: MIT
// Takes pull samples from an OutPort over direct.
#ifndef RTC_OUTPORTDIRECTCONSUMER_H
#define RTC_OUTPORTDIRECTCONSUMER_H

#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/CorbaConsumer.h>
#include <rtm/OutPortConsumer.h>
#include <rtm/SystemLogger.h>

#include <atomic>
#include <bit>
#include <condition_variable>
#include <csignal>
#include <list>
#include <memory>
#include <signal.h>
#include <sys/ucontext.h>
#include <thread>
#include <unistd.h>

namespace RTC {
/**
 * The InPort side of pull connections of interface type `direct`.
 * RT Studio's runtime has no direct transport: the class exists so that code naming it
 * builds; using it fails with a logged message naming the interface type.
 */
class OutPortDirectConsumer : public OutPortConsumer
{
public:
    OutPortDirectConsumer();
    ~OutPortDirectConsumer() override;
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
void OutPortDirectConsumerInit();
}

#endif // RTC_OUTPORTDIRECTCONSUMER_H
