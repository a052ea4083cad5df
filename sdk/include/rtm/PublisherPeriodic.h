// SPDX-License-Identifier: MIT
// A push connection that sends from its buffer at a fixed rate.
#ifndef RTC_PUBLISHERPERIODIC_H
#define RTC_PUBLISHERPERIODIC_H

#include <coil/PeriodicTask.h>
#include <coil/Task.h>
#include <condition_variable>
#include <rtm/CdrBufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/PublisherBase.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

namespace RTC {
class InPortConsumer;

/**
 * Sends from its buffer `publisher.push_rate` times a second (default 100) from a thread of
 * its own; `publisher.push_policy` (all, fifo, skip, new: the default) says which waiting
 * samples go each time (`subscription_type` periodic).
 */
class PublisherPeriodic : public PublisherBase
{
public:
    PublisherPeriodic();
    ~PublisherPeriodic() override;
    DataPortStatus init(coil::Properties &prop) override;
    DataPortStatus setConsumer(InPortConsumer *consumer) override;
    DataPortStatus setBuffer(CdrBufferBase *buffer) override;
    DataPortStatus setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) override;
    DataPortStatus write(ByteDataStreamBase *data, std::chrono::nanoseconds timeout) override;
    bool isActive() override;
    DataPortStatus activate() override;
    DataPortStatus deactivate() override;
    /// One round of the sending thread: sends what the policy says; 0 to go on.
    virtual int svc();

protected:
    Logger rtclog;

private:
    struct Private;
    Private *d;
};
} // namespace RTC

extern "C" {
void PublisherPeriodicInit();
}

#endif // RTC_PUBLISHERPERIODIC_H
