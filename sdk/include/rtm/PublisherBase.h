// SPDX-License-Identifier: MIT
// How an OutPort push connection sends its samples: at once, the newest, or periodically.
#ifndef RTC_PUBLISHERBASE_H
#define RTC_PUBLISHERBASE_H

#include <coil/Factory.h>
#include <rtm/BufferBase.h>
#include <rtm/ByteData.h>
#include <rtm/ByteDataStreamBase.h>
#include <rtm/CdrBufferBase.h>
#include <rtm/DataPortStatus.h>
#include <rtm/RTC.h>

#include <coil/Properties.h>

#include <chrono>

namespace RTC {
class InPortConsumer;
class ConnectorListenersBase;
class ConnectorInfo;

/// The sending policy of a push connection (`subscription_type` flush, new or periodic).
class PublisherBase
{
public:
    virtual ~PublisherBase() = default;
    /// Applies the connector properties (`publisher.push_rate`, `publisher.push_policy`, …).
    virtual DataPortStatus init(coil::Properties &prop) = 0;
    /// Where samples go (not owned).
    virtual DataPortStatus setConsumer(InPortConsumer *consumer) = 0;
    /// Where samples wait before they go (not owned).
    virtual DataPortStatus setBuffer(BufferBase<ByteData> *buffer) = 0;
    virtual DataPortStatus setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) = 0;
    /// Publishes the sample in @p data, waiting at most @p timeout (negative: the configured one).
    virtual DataPortStatus write(ByteDataStreamBase *data, std::chrono::nanoseconds timeout) = 0;
    virtual bool isActive() = 0;
    virtual DataPortStatus activate() = 0;
    virtual DataPortStatus deactivate() = 0;
    virtual void release() { }
};

/// The publishers by subscription type (`flush`, `new`, `periodic`, registered by their *Init()).
using PublisherFactory = ::coil::GlobalFactory<PublisherBase>;
} // namespace RTC

#endif // RTC_PUBLISHERBASE_H
