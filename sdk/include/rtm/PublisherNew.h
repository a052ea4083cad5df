// SPDX-License-Identifier: MIT
// A push connection that sends the newest sample from a thread of its own.
#ifndef RTC_PUBLISHERNEW_H
#define RTC_PUBLISHERNEW_H

#include <coil/PeriodicTask.h>
#include <coil/Task.h>
#include <condition_variable>
#include <rtm/ByteData.h>
#include <rtm/CdrBufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/DataPortStatus.h>
#include <rtm/PublisherBase.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

namespace RTC {
class InPortConsumer;

/**
 * Sends from a thread of its own each time a sample is written; samples written meanwhile
 * wait in the buffer and the `publisher.push_policy` (all, fifo, skip, new: the default) says
 * which of them go (`subscription_type` new).
 */
class PublisherNew : public PublisherBase
{
public:
    PublisherNew();
    ~PublisherNew() override;
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
void PublisherNewInit();
}

#endif // RTC_PUBLISHERNEW_H
