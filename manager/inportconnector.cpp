// SPDX-License-Identifier: MIT
#include "inportconnector.h"

#include "corbautil.h"
#include "outportconnector.h"

#include <utility>

namespace Runtime {

InPortConnector::InPortConnector(const std::string &id, const Properties &p)
    : m_id(id)
    , m_littleEndian(p.value("dataport.serializer.cdr.endian", "little").find("big") != 0)
{
}

InPortCdrServant::InPortCdrServant(std::shared_ptr<RingBuffer> buffer, ReceiveListener listener,
                                   bool littleEndian)
    : m_buffer(std::move(buffer))
    , m_listener(std::move(listener))
    , m_littleEndian(littleEndian)
{
}

namespace {

void releaseOctets(unsigned char *bytes)
{
    OpenRTM::CdrData::freebuf(bytes);
}

/**
 * Received bytes as a sample to keep. When @p owned, @p data is a temporary that nobody reads
 * after us (the skeleton's argument of a remote put, or the result of our own get): its buffer is
 * taken over instead of copied, a copy that cost as much as receiving a large sample. Otherwise
 * (a put from this process passes the caller's own sequence) the bytes are copied.
 */
SharedCdr adopt(const OpenRTM::CdrData &data, bool owned)
{
    auto &argument = const_cast<OpenRTM::CdrData &>(data);
    const size_t size = argument.length();
    if (owned && argument.release() && size > 0) {
        unsigned char *bytes = argument.get_buffer(true);
        return std::make_shared<const CdrSample>(bytes, size, releaseOctets);
    }
    return std::make_shared<const CdrSample>(CdrBytes(data.get_buffer(), data.get_buffer() + size));
}

/// Set while this thread runs a remote call's upcall, until its put() has looked.
thread_local bool t_remoteUpcall = false;

} // namespace

CORBA::Boolean InPortCdrServant::_dispatch(omniCallHandle &handle)
{
    // Reset however the call ends (a request that does not unmarshal throws before put()).
    struct RemoteUpcall
    {
        RemoteUpcall() { t_remoteUpcall = true; }
        ~RemoteUpcall() { t_remoteUpcall = false; }
    } upcall;
    return POA_OpenRTM::InPortCdr::_dispatch(handle);
}

OpenRTM::PortStatus InPortCdrServant::put(const OpenRTM::CdrData &data)
{
    // Cleared at once, so that a local put made from a listener below copies its caller's bytes.
    const bool remote = std::exchange(t_remoteUpcall, false);
    SharedCdr sample = adopt(data, remote);
    if (m_listener)
        m_listener(sample->view(), m_littleEndian);
    switch (m_buffer->write(std::move(sample))) {
    case RingBuffer::Status::Ok:
        return OpenRTM::PORT_OK;
    case RingBuffer::Status::Full:
        return OpenRTM::BUFFER_FULL;
    case RingBuffer::Status::Timeout:
        return OpenRTM::BUFFER_TIMEOUT;
    case RingBuffer::Status::Empty:
        break;
    }
    return OpenRTM::PORT_ERROR;
}

InPortPushConnector::InPortPushConnector(const std::string &id, const Properties &p,
                                         PortableServer::POA_ptr poa, ReceiveListener listener)
    : InPortConnector(id, p)
    , m_buffer(std::make_shared<RingBuffer>(bufferProperties(p, "inport")))
    , m_poa(PortableServer::POA::_duplicate(poa))
    , m_servant(new InPortCdrServant(m_buffer, std::move(listener), littleEndian()))
{
}

InPortPushConnector::~InPortPushConnector()
{
    m_buffer->close();
    releaseServant(m_poa, m_servant);
}

bool InPortPushConnector::hasNew() const
{
    return m_buffer->readable() > 0;
}

bool InPortPushConnector::read(SharedCdr *data)
{
    return m_buffer->read(data) == RingBuffer::Status::Ok;
}

OpenRTM::InPortCdr_ptr InPortPushConnector::reference()
{
    return m_servant->_this();
}

InPortPullConnector::InPortPullConnector(const std::string &id, const Properties &p,
                                         OpenRTM::OutPortCdr_ptr peer, ReceiveListener listener)
    : InPortConnector(id, p)
    , m_peer(OpenRTM::OutPortCdr::_duplicate(peer))
    , m_listener(std::move(listener))
{
}

bool InPortPullConnector::read(SharedCdr *data)
{
    SharedCdr sample;
    try {
        OpenRTM::CdrData_var cdr;
        if (m_peer->get(cdr.out()) != OpenRTM::PORT_OK)
            return false;
        sample = adopt(cdr.in(), true);
    } catch (const CORBA::Exception &) {
        return false;
    }
    if (m_listener)
        m_listener(sample->view(), littleEndian());
    *data = std::move(sample);
    return true;
}

} // namespace Runtime
