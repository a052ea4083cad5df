// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"
#include "ringbuffer.h"

#include <DataPort_OpenRTM.hh>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace Runtime {

/// What became of one sample on one connection (OpenRTM's DataPortStatus, as far as it applies).
enum class SendStatus { Ok, PortError, BufferFull, BufferEmpty, BufferTimeout, ConnectionLost, UnknownError };

/// One connection of an OutPort: receives every written sample in its byte order.
class OutPortConnector
{
public:
    OutPortConnector(const std::string &id, const Properties &connectorProperties);
    virtual ~OutPortConnector() = default;
    const std::string &id() const { return m_id; }
    /// `dataport.serializer.cdr.endian` (little unless it says big).
    bool littleEndian() const { return m_littleEndian; }
    /// `dataport.outport.marshaling_type`, else `dataport.marshaling_type`, else `cdr`.
    const std::string &marshalingType() const { return m_marshalingType; }
    /// Sends (or keeps) one sample; @p data is only valid during the call.
    virtual SendStatus write(const CdrView &data) = 0;

private:
    std::string m_id;
    bool m_littleEndian = true;
    std::string m_marshalingType;
};

/**
 * Push connection: sends to the peer's InPortCdr::put. `flush` sends in the writer's thread;
 * `new` sends the newest sample from its own thread (older unsent ones are skipped); `periodic`
 * sends from its own thread at `dataport.publisher.push_rate` Hz with `push_policy`
 * all|fifo|skip|new (`push_skip` for skip) out of a buffer with the `dataport.buffer.*` policies.
 */
class OutPortPushConnector : public OutPortConnector
{
public:
    enum class Mode { Flush, New, Periodic };

    OutPortPushConnector(const std::string &id, const Properties &connectorProperties, OpenRTM::InPortCdr_ptr peer);
    ~OutPortPushConnector() override;
    SendStatus write(const CdrView &data) override;

    /// Parses `dataport.subscription_type`; false for unknown names.
    static bool parseMode(const std::string &text, Mode *mode);

private:
    SendStatus send(const CdrView &data);
    void runNew();
    void runPeriodic();
    void pushBuffered();

    OpenRTM::InPortCdr_var m_peer;
    Mode m_mode = Mode::Flush;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    CdrBytes m_newest;
    bool m_hasNewest = false;
    bool m_stopping = false;
    RingBuffer m_buffer;
    double m_pushRate = 100.0;
    std::string m_pushPolicy = "new";
    int m_skip = 0;
    int m_skipped = 0;
    std::thread m_thread;
    /// A failing connection is reported once until a sample gets through again.
    std::atomic<bool> m_failing{false};
};

/// Servant answering OutPortCdr::get from a pull connection's buffer.
class OutPortCdrServant : public virtual POA_OpenRTM::OutPortCdr
{
public:
    explicit OutPortCdrServant(std::shared_ptr<RingBuffer> buffer) : m_buffer(std::move(buffer)) {}
    OpenRTM::PortStatus get(OpenRTM::CdrData_out data) override;

private:
    // Shared: a get() still running after the connection went keeps the buffer alive.
    std::shared_ptr<RingBuffer> m_buffer;
};

/// Pull connection: written samples wait in a buffer until the InPort calls get().
class OutPortPullConnector : public OutPortConnector
{
public:
    OutPortPullConnector(const std::string &id, const Properties &connectorProperties,
                         PortableServer::POA_ptr poa);
    ~OutPortPullConnector() override;
    SendStatus write(const CdrView &data) override;
    /// The object the InPort pulls from (published as `dataport.corba_cdr.outport_ior`).
    OpenRTM::OutPortCdr_ptr reference();

private:
    std::shared_ptr<RingBuffer> m_buffer;
    PortableServer::POA_var m_poa;
    OutPortCdrServant *m_servant;
};

/// `dataport.buffer.*` overlaid with `dataport.<side>.buffer.*` (side = inport|outport).
Properties bufferProperties(const Properties &connectorProperties, const std::string &side);

} // namespace Runtime
