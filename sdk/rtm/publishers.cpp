// SPDX-License-Identifier: MIT
// The publishers of push connections: flush sends in the writer's thread, new and periodic
// from a thread of their own out of the connection's buffer.
#include <rtm/InPortConsumer.h>
#include <rtm/PublisherFlush.h>
#include <rtm/PublisherNew.h>
#include <rtm/PublisherPeriodic.h>

#include "dataportframework.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace RTC {

namespace {

// Sends one sample through @p consumer and tells the listeners how it went.
DataPortStatus send(InPortConsumer *consumer, ByteData &bytes, const ConnectorInfo &info,
                    ConnectorListenersBase *listeners)
{
    const bool littleEndian = Sdk::littleEndianOf(info);
    Sdk::notifyData(listeners, ConnectorDataListenerType::ON_SEND, info, bytes, littleEndian);
    const DataPortStatus status = consumer->put(bytes);
    switch (status) {
    case DataPortStatus::PORT_OK:
        Sdk::notifyData(listeners, ConnectorDataListenerType::ON_RECEIVED, info, bytes,
                        littleEndian);
        break;
    case DataPortStatus::SEND_FULL:
        Sdk::notifyData(listeners, ConnectorDataListenerType::ON_RECEIVER_FULL, info, bytes,
                        littleEndian);
        break;
    case DataPortStatus::SEND_TIMEOUT:
        Sdk::notifyData(listeners, ConnectorDataListenerType::ON_RECEIVER_TIMEOUT, info, bytes,
                        littleEndian);
        break;
    default:
        Sdk::notifyData(listeners, ConnectorDataListenerType::ON_RECEIVER_ERROR, info, bytes,
                        littleEndian);
        break;
    }
    return status;
}

} // namespace

// --- PublisherFlush ---

PublisherFlush::PublisherFlush()
    : rtclog("PublisherFlush")
    , m_consumer(nullptr)
    , m_listeners(nullptr)
    , m_retcode(DataPortStatus::PORT_OK)
    , m_active(false)
{ }

PublisherFlush::~PublisherFlush() = default;

DataPortStatus PublisherFlush::init(coil::Properties &prop)
{
    (void)prop; // flush has no settings
    return DataPortStatus::PORT_OK;
}

DataPortStatus PublisherFlush::setConsumer(InPortConsumer *consumer)
{
    if (consumer == nullptr)
        return DataPortStatus::INVALID_ARGS;
    m_consumer = consumer;
    return DataPortStatus::PORT_OK;
}

DataPortStatus PublisherFlush::setBuffer(CdrBufferBase *buffer)
{
    (void)buffer; // flush sends at once and keeps nothing
    return DataPortStatus::PORT_OK;
}

DataPortStatus PublisherFlush::setListener(ConnectorInfo &info, ConnectorListenersBase *listeners)
{
    m_profile = info;
    m_listeners = dynamic_cast<ConnectorListeners *>(listeners);
    return DataPortStatus::PORT_OK;
}

DataPortStatus PublisherFlush::write(ByteDataStreamBase *data, std::chrono::nanoseconds timeout)
{
    (void)timeout;
    if (m_consumer == nullptr || data == nullptr)
        return DataPortStatus::PRECONDITION_NOT_MET;
    std::lock_guard<std::mutex> lock(m_retmutex);
    if (!m_active)
        return DataPortStatus::PRECONDITION_NOT_MET;
    ByteData bytes = Sdk::bytesOf(*data);
    m_retcode = send(m_consumer, bytes, m_profile, m_listeners);
    return m_retcode;
}

bool PublisherFlush::isActive()
{
    return m_active;
}

DataPortStatus PublisherFlush::activate()
{
    m_active = true;
    return DataPortStatus::PORT_OK;
}

DataPortStatus PublisherFlush::deactivate()
{
    m_active = false;
    return DataPortStatus::PORT_OK;
}

// --- the threaded publishers ---

namespace {

/**
 * A sending thread over a buffer: each round sends what `push_policy` says (all waiting
 * samples, the oldest (fifo), every skip_count+1-th (skip) or the newest (new)), after a write
 * (new) or at `push_rate` Hz (periodic).
 */
class SendingThread
{
public:
    explicit SendingThread(bool periodic)
        : m_periodic(periodic)
    { }
    ~SendingThread() { stop(); }

    void configure(const coil::Properties &prop)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_policy = coil::normalize(prop.getProperty("publisher.push_policy", "new"));
        coil::stringTo(m_skipCount, prop.getProperty("publisher.skip_count", "0").c_str());
        double rate = 100.0;
        if (coil::stringTo(rate, prop.getProperty("publisher.push_rate", "100").c_str())
            && rate > 0.0)
            m_period = std::chrono::duration<double>(1.0 / rate);
    }
    void start(const std::function<void()> &round)
    {
        if (m_thread.joinable())
            return;
        m_round = round;
        m_thread = std::thread([this] { run(); });
    }
    void stop()
    {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_stopping = true;
        }
        m_wake.notify_all();
        if (m_thread.joinable())
            m_thread.join();
    }
    void kick()
    {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_pending = true;
        }
        m_wake.notify_all();
    }
    // Samples of one round, taken from @p buffer by the policy.
    std::vector<ByteData> take(CdrBufferBase *buffer)
    {
        std::vector<ByteData> all;
        ByteData bytes;
        while (buffer->readable() > 0
               && buffer->read(bytes, std::chrono::nanoseconds(0)) == BufferStatus::OK)
            all.push_back(bytes);
        std::string policy;
        int skip = 0;
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            policy = m_policy;
            skip = std::max(0, m_skipCount);
        }
        if (all.empty() || policy == "all")
            return all;
        if (policy == "fifo") {
            // One per round; the others go back, in order, for the next rounds.
            for (size_t i = 1; i < all.size(); ++i)
                buffer->write(all[i], std::chrono::nanoseconds(0));
            return {all.front()};
        }
        if (policy == "skip") {
            std::vector<ByteData> kept;
            for (size_t i = 0; i < all.size(); ++i) {
                if ((m_skipped++ % (skip + 1)) == 0)
                    kept.push_back(all[i]);
            }
            return kept;
        }
        return {all.back()};
    }

private:
    void run()
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        while (!m_stopping) {
            if (m_periodic)
                m_wake.wait_for(lock, m_period, [this] { return m_stopping; });
            else
                m_wake.wait(lock, [this] { return m_stopping || m_pending; });
            if (m_stopping)
                break;
            m_pending = false;
            lock.unlock();
            m_round();
            lock.lock();
        }
    }

    const bool m_periodic;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::thread m_thread;
    std::function<void()> m_round;
    std::string m_policy = "new";
    int m_skipCount = 0;
    unsigned long m_skipped = 0;
    std::chrono::duration<double> m_period {0.01};
    bool m_pending = false;
    bool m_stopping = false;
};

} // namespace

#define RTC_THREADED_PUBLISHER(Class, periodic)                                                    \
    struct Class::Private                                                                          \
    {                                                                                              \
        Private()                                                                                  \
            : thread(periodic)                                                                     \
        { }                                                                                        \
        InPortConsumer *consumer = nullptr;                                                        \
        CdrBufferBase *buffer = nullptr;                                                           \
        ConnectorInfo profile;                                                                     \
        ConnectorListenersBase *listeners = nullptr;                                               \
        std::atomic<bool> active {false};                                                          \
        SendingThread thread;                                                                      \
    };                                                                                             \
    Class::Class()                                                                                 \
        : rtclog(#Class)                                                                           \
        , d(new Private)                                                                           \
    { }                                                                                            \
    Class::~Class()                                                                                \
    {                                                                                              \
        d->thread.stop();                                                                          \
        delete d;                                                                                  \
    }                                                                                              \
    DataPortStatus Class::init(coil::Properties &prop)                                             \
    {                                                                                              \
        d->thread.configure(prop);                                                                 \
        d->thread.start([this] { svc(); });                                                        \
        return DataPortStatus::PORT_OK;                                                            \
    }                                                                                              \
    DataPortStatus Class::setConsumer(InPortConsumer *consumer)                                    \
    {                                                                                              \
        if (consumer == nullptr)                                                                   \
            return DataPortStatus::INVALID_ARGS;                                                   \
        d->consumer = consumer;                                                                    \
        return DataPortStatus::PORT_OK;                                                            \
    }                                                                                              \
    DataPortStatus Class::setBuffer(CdrBufferBase *buffer)                                         \
    {                                                                                              \
        if (buffer == nullptr)                                                                     \
            return DataPortStatus::INVALID_ARGS;                                                   \
        d->buffer = buffer;                                                                        \
        return DataPortStatus::PORT_OK;                                                            \
    }                                                                                              \
    DataPortStatus Class::setListener(ConnectorInfo &info, ConnectorListenersBase *listeners)      \
    {                                                                                              \
        d->profile = info;                                                                         \
        d->listeners = listeners;                                                                  \
        return DataPortStatus::PORT_OK;                                                            \
    }                                                                                              \
    DataPortStatus Class::write(ByteDataStreamBase *data, std::chrono::nanoseconds timeout)        \
    {                                                                                              \
        if (d->consumer == nullptr || d->buffer == nullptr || data == nullptr)                     \
            return DataPortStatus::PRECONDITION_NOT_MET;                                           \
        if (!d->active)                                                                            \
            return DataPortStatus::PRECONDITION_NOT_MET;                                           \
        ByteData bytes = Sdk::bytesOf(*data);                                                      \
        const BufferStatus status = d->buffer->write(bytes, timeout);                              \
        const bool littleEndian = Sdk::littleEndianOf(d->profile);                                 \
        if (status == BufferStatus::OK)                                                            \
            Sdk::notifyData(d->listeners, ConnectorDataListenerType::ON_BUFFER_WRITE, d->profile,  \
                            bytes, littleEndian);                                                  \
        else if (status == BufferStatus::FULL)                                                     \
            Sdk::notifyData(d->listeners, ConnectorDataListenerType::ON_BUFFER_FULL, d->profile,   \
                            bytes, littleEndian);                                                  \
        else if (status == BufferStatus::TIMEOUT)                                                  \
            Sdk::notifyData(d->listeners, ConnectorDataListenerType::ON_BUFFER_WRITE_TIMEOUT,      \
                            d->profile, bytes, littleEndian);                                      \
        d->thread.kick();                                                                          \
        return Sdk::toDataPortStatus(status);                                                      \
    }                                                                                              \
    bool Class::isActive()                                                                         \
    {                                                                                              \
        return d->active;                                                                          \
    }                                                                                              \
    DataPortStatus Class::activate()                                                               \
    {                                                                                              \
        d->active = true;                                                                          \
        return DataPortStatus::PORT_OK;                                                            \
    }                                                                                              \
    DataPortStatus Class::deactivate()                                                             \
    {                                                                                              \
        d->active = false;                                                                         \
        return DataPortStatus::PORT_OK;                                                            \
    }                                                                                              \
    int Class::svc()                                                                               \
    {                                                                                              \
        if (!d->active || d->consumer == nullptr || d->buffer == nullptr)                          \
            return 0;                                                                              \
        for (ByteData & bytes : d->thread.take(d->buffer))                                         \
            send(d->consumer, bytes, d->profile, d->listeners);                                    \
        return 0;                                                                                  \
    }

RTC_THREADED_PUBLISHER(PublisherNew, false)
RTC_THREADED_PUBLISHER(PublisherPeriodic, true)

#undef RTC_THREADED_PUBLISHER

} // namespace RTC

// Each publisher registers under its subscription type, as OpenRTM-aist's init functions do.
void PublisherFlushInit()
{
    RTC::PublisherFactory::instance().addFactory(
        "flush", ::coil::Creator<RTC::PublisherBase, RTC::PublisherFlush>,
        ::coil::Destructor<RTC::PublisherBase, RTC::PublisherFlush>);
}

void PublisherNewInit()
{
    RTC::PublisherFactory::instance().addFactory(
        "new", ::coil::Creator<RTC::PublisherBase, RTC::PublisherNew>,
        ::coil::Destructor<RTC::PublisherBase, RTC::PublisherNew>);
}

void PublisherPeriodicInit()
{
    RTC::PublisherFactory::instance().addFactory(
        "periodic", ::coil::Creator<RTC::PublisherBase, RTC::PublisherPeriodic>,
        ::coil::Destructor<RTC::PublisherBase, RTC::PublisherPeriodic>);
}
