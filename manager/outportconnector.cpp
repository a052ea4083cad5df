// SPDX-License-Identifier: MIT
#include "outportconnector.h"
#include "dataport.h"

#include "corbautil.h"

#include <algorithm>
#include <chrono>
#include <iostream>

namespace Runtime {

Properties bufferProperties(const Properties &connectorProperties, const std::string &side)
{
    Properties result = connectorProperties.subtree("dataport.buffer");
    result.merge(connectorProperties.subtree("dataport." + side + ".buffer"));
    return result;
}

OutPortConnector::OutPortConnector(const std::string &id, const Properties &p)
    : m_id(id)
    , m_littleEndian(p.value("dataport.serializer.cdr.endian", "little").find("big") != 0)
    , m_marshalingType(Runtime::marshalingType(p, "outport"))
{
}

bool OutPortPushConnector::parseMode(const std::string &text, Mode *mode)
{
    std::string t = trimmed(text);
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    // OpenRTM-aist 2.x also names flush "block" and new "nonblock" (its io_mode names).
    if (t == "flush" || t == "block" || t.empty())
        *mode = Mode::Flush;
    else if (t == "new" || t == "nonblock")
        *mode = Mode::New;
    else if (t == "periodic")
        *mode = Mode::Periodic;
    else
        return false;
    return true;
}

OutPortPushConnector::OutPortPushConnector(const std::string &id, const Properties &p,
                                           OpenRTM::InPortCdr_ptr peer)
    : OutPortConnector(id, p)
    , m_peer(OpenRTM::InPortCdr::_duplicate(peer))
    , m_buffer(bufferProperties(p, "outport"))
{
    parseMode(p.value("dataport.subscription_type", "flush"), &m_mode);
    try {
        m_pushRate = std::max(0.001, std::stod(p.value("dataport.publisher.push_rate", "100")));
        m_skip = std::max(0, std::stoi(p.value("dataport.publisher.push_skip", "0")));
    } catch (...) {
        // Unreadable numbers keep OpenRTM's defaults.
    }
    m_pushPolicy = p.value("dataport.publisher.push_policy", "new");
    if (m_mode == Mode::New)
        m_thread = std::thread([this] { runNew(); });
    else if (m_mode == Mode::Periodic)
        m_thread = std::thread([this] { runPeriodic(); });
}

OutPortPushConnector::~OutPortPushConnector()
{
    {
        std::lock_guard lock(m_mutex);
        m_stopping = true;
    }
    m_wake.notify_all();
    m_buffer.close();
    if (m_thread.joinable())
        m_thread.join();
}

namespace {

SendStatus fromBuffer(RingBuffer::Status status)
{
    switch (status) {
    case RingBuffer::Status::Ok:
        return SendStatus::Ok;
    case RingBuffer::Status::Full:
        return SendStatus::BufferFull;
    case RingBuffer::Status::Empty:
        return SendStatus::BufferEmpty;
    case RingBuffer::Status::Timeout:
        return SendStatus::BufferTimeout;
    }
    return SendStatus::UnknownError;
}

SendStatus fromPeer(OpenRTM::PortStatus status)
{
    switch (status) {
    case OpenRTM::PORT_OK:
        return SendStatus::Ok;
    case OpenRTM::PORT_ERROR:
        return SendStatus::PortError;
    case OpenRTM::BUFFER_FULL:
        return SendStatus::BufferFull;
    case OpenRTM::BUFFER_EMPTY:
        return SendStatus::BufferEmpty;
    case OpenRTM::BUFFER_TIMEOUT:
        return SendStatus::BufferTimeout;
    default:
        return SendStatus::UnknownError;
    }
}

} // namespace

SendStatus OutPortPushConnector::write(const CdrView &data)
{
    switch (m_mode) {
    case Mode::Flush:
        return send(data);
    case Mode::New: {
        // Handed to the connection's thread; what the peer answers is known there, not here.
        std::lock_guard lock(m_mutex);
        m_newest.assign(data.data, data.data + data.size);
        m_hasNewest = true;
        m_wake.notify_all();
        return SendStatus::Ok;
    }
    case Mode::Periodic:
        return fromBuffer(m_buffer.write(data.bytes()));
    }
    return SendStatus::UnknownError;
}

SendStatus OutPortPushConnector::send(const CdrView &data)
{
    // The sequence borrows the bytes (release = false): nothing is copied before the ORB sends them.
    const auto length = CORBA::ULong(data.size);
    OpenRTM::CdrData cdr(length, length, const_cast<CORBA::Octet *>(data.data), false);
    try {
        const OpenRTM::PortStatus status = m_peer->put(cdr);
        m_failing = false;
        return fromPeer(status);
    } catch (const CORBA::Exception &e) {
        // The peer is gone or slow; the sample is lost as with OpenRTM's CONNECTION_LOST. Say so
        // once: a sample over omniORB's message size limit fails here on every write.
        if (!m_failing.exchange(true)) {
            const bool tooLarge = CORBA::MARSHAL::_downcast(&e) != nullptr;
            std::cerr << programName() << ": connection " << id() << ": a " << data.size
                      << "-byte sample was not delivered (" << describeException(e) << ")"
                      << (tooLarge ? "; samples over the ORB's message limit (256 MiB in RT Studio's runtime, "
                                     "2 MiB in OpenRTM-aist's by default) need "
                                     "corba.args: -ORBgiopMaxMsgSize <bytes> on both sides"
                                   : "")
                      << std::endl;
        }
        return SendStatus::ConnectionLost;
    }
}

void OutPortPushConnector::runNew()
{
    std::unique_lock lock(m_mutex);
    for (;;) {
        m_wake.wait(lock, [this] { return m_stopping || m_hasNewest; });
        if (m_stopping)
            return;
        CdrBytes data = std::move(m_newest);
        m_hasNewest = false;
        lock.unlock();
        send(CdrView::of(data));
        lock.lock();
    }
}

void OutPortPushConnector::pushBuffered()
{
    SharedCdr data;
    if (m_pushPolicy == "all") {
        while (m_buffer.readable() > 0 && m_buffer.read(&data) == RingBuffer::Status::Ok)
            send(data->view());
    } else if (m_pushPolicy == "fifo") {
        if (m_buffer.readable() > 0 && m_buffer.read(&data) == RingBuffer::Status::Ok)
            send(data->view());
    } else if (m_pushPolicy == "skip") {
        while (m_buffer.readable() > 0 && m_buffer.read(&data) == RingBuffer::Status::Ok) {
            if (m_skipped++ % (m_skip + 1) == 0)
                send(data->view());
        }
    } else { // "new": only the newest of what piled up
        bool any = false;
        while (m_buffer.readable() > 0 && m_buffer.read(&data) == RingBuffer::Status::Ok)
            any = true;
        if (any)
            send(data->view());
    }
}

void OutPortPushConnector::runPeriodic()
{
    const auto period = std::chrono::duration<double>(1.0 / m_pushRate);
    auto next = std::chrono::steady_clock::now();
    std::unique_lock lock(m_mutex);
    while (!m_stopping) {
        lock.unlock();
        pushBuffered();
        lock.lock();
        next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
        m_wake.wait_until(lock, next, [this] { return m_stopping; });
    }
}

OpenRTM::PortStatus OutPortCdrServant::get(OpenRTM::CdrData_out data)
{
    SharedCdr bytes;
    const RingBuffer::Status status = m_buffer->read(&bytes);
    const CORBA::ULong length = status == RingBuffer::Status::Ok ? CORBA::ULong(bytes->size()) : 0;
    data = new OpenRTM::CdrData(length);
    data->length(length);
    if (length > 0)
        std::copy(bytes->data(), bytes->data() + length, data->get_buffer());
    switch (status) {
    case RingBuffer::Status::Ok:
        return OpenRTM::PORT_OK;
    case RingBuffer::Status::Empty:
        return OpenRTM::BUFFER_EMPTY;
    case RingBuffer::Status::Timeout:
        return OpenRTM::BUFFER_TIMEOUT;
    case RingBuffer::Status::Full:
        break;
    }
    return OpenRTM::PORT_ERROR;
}

OutPortPullConnector::OutPortPullConnector(const std::string &id, const Properties &p,
                                           PortableServer::POA_ptr poa)
    : OutPortConnector(id, p)
    , m_buffer(std::make_shared<RingBuffer>(bufferProperties(p, "outport")))
    , m_poa(PortableServer::POA::_duplicate(poa))
    , m_servant(new OutPortCdrServant(m_buffer))
{
}

OutPortPullConnector::~OutPortPullConnector()
{
    m_buffer->close();
    releaseServant(m_poa, m_servant);
}

SendStatus OutPortPullConnector::write(const CdrView &data)
{
    return fromBuffer(m_buffer->write(data.bytes()));
}

OpenRTM::OutPortCdr_ptr OutPortPullConnector::reference()
{
    return m_servant->_this();
}

} // namespace Runtime
