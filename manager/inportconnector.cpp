// SPDX-License-Identifier: MIT
#include "inportconnector.h"

#include "corbautil.h"
#include "outportconnector.h"

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

OpenRTM::PortStatus InPortCdrServant::put(const OpenRTM::CdrData &data)
{
    CdrBytes bytes(data.get_buffer(), data.get_buffer() + data.length());
    if (m_listener)
        m_listener(bytes, m_littleEndian);
    switch (m_buffer->write(std::move(bytes))) {
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
    CdrBytes bytes;
    try {
        OpenRTM::CdrData_var cdr;
        if (m_peer->get(cdr.out()) != OpenRTM::PORT_OK)
            return false;
        bytes.assign(cdr->get_buffer(), cdr->get_buffer() + cdr->length());
    } catch (const CORBA::Exception &) {
        return false;
    }
    if (m_listener)
        m_listener(bytes, littleEndian());
    *data = std::make_shared<const CdrBytes>(std::move(bytes));
    return true;
}

} // namespace Runtime
