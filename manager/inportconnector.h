// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"
#include "ringbuffer.h"

#include <DataPort_OpenRTM.hh>

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace Runtime {

/// Called for every sample that arrives at an InPort (bytes and their byte order).
using ReceiveListener = std::function<void(const CdrView &, bool littleEndian)>;

/// One connection of an InPort.
class InPortConnector
{
public:
    InPortConnector(const std::string &id, const Properties &connectorProperties);
    virtual ~InPortConnector() = default;
    const std::string &id() const { return m_id; }
    bool littleEndian() const { return m_littleEndian; }
    /// True when a sample is waiting (push) — pull connections never know in advance.
    virtual bool hasNew() const = 0;
    /// Takes one sample; false when there is none.
    virtual bool read(SharedCdr *data) = 0;

private:
    std::string m_id;
    bool m_littleEndian = true;
};

/// Servant answering InPortCdr::put into a push connection's buffer.
class InPortCdrServant : public virtual POA_OpenRTM::InPortCdr
{
public:
    InPortCdrServant(std::shared_ptr<RingBuffer> buffer, ReceiveListener listener, bool littleEndian);
    OpenRTM::PortStatus put(const OpenRTM::CdrData &data) override;
    /// Remote calls come through here, local ones do not: put() may take over only the bytes
    /// of a remote call, which the skeleton unmarshalled into a temporary of its own.
    CORBA::Boolean _dispatch(omniCallHandle &handle) override;

private:
    std::shared_ptr<RingBuffer> m_buffer;
    ReceiveListener m_listener;
    bool m_littleEndian;
};

/// Push connection: the OutPort puts samples into our buffer through an InPortCdr object.
class InPortPushConnector : public InPortConnector
{
public:
    InPortPushConnector(const std::string &id, const Properties &connectorProperties,
                        PortableServer::POA_ptr poa, ReceiveListener listener);
    ~InPortPushConnector() override;
    bool hasNew() const override;
    bool read(SharedCdr *data) override;
    /// Published as `dataport.corba_cdr.inport_ior`.
    OpenRTM::InPortCdr_ptr reference();

private:
    std::shared_ptr<RingBuffer> m_buffer;
    PortableServer::POA_var m_poa;
    InPortCdrServant *m_servant;
};

/// Pull connection: read() asks the OutPort's OutPortCdr::get.
class InPortPullConnector : public InPortConnector
{
public:
    InPortPullConnector(const std::string &id, const Properties &connectorProperties,
                        OpenRTM::OutPortCdr_ptr peer, ReceiveListener listener);
    bool hasNew() const override { return false; }
    bool read(SharedCdr *data) override;

private:
    OpenRTM::OutPortCdr_var m_peer;
    ReceiveListener m_listener;
};

} // namespace Runtime
