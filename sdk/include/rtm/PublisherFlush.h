// SPDX-License-Identifier: MIT
// A push connection that sends each sample in the writer's thread.
#ifndef RTC_PUBLISHERFLUSH_H
#define RTC_PUBLISHERFLUSH_H

#include <condition_variable>
#include <mutex>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/PublisherBase.h>
#include <rtm/SystemLogger.h>

namespace RTC {
class InPortConsumer;

/// Sends each written sample to the consumer at once (`subscription_type` flush).
class PublisherFlush : public PublisherBase
{
public:
    PublisherFlush();
    ~PublisherFlush() override;
    DataPortStatus init(coil::Properties &prop) override;
    DataPortStatus setConsumer(InPortConsumer *consumer) override;
    DataPortStatus setBuffer(CdrBufferBase *buffer) override;
    DataPortStatus setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) override;
    DataPortStatus write(ByteDataStreamBase *data,
                         std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1)) override;
    bool isActive() override;
    DataPortStatus activate() override;
    DataPortStatus deactivate() override;

protected:
    Logger rtclog;
    InPortConsumer *m_consumer;
    ConnectorInfo m_profile;
    ConnectorListeners *m_listeners;
    DataPortStatus m_retcode;
    std::mutex m_retmutex;
    bool m_active;
};
} // namespace RTC

extern "C" {
/// Registers the publisher in PublisherFactory under its subscription type.
void PublisherFlushInit();
}

#endif // RTC_PUBLISHERFLUSH_H
