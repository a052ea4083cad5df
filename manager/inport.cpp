// SPDX-License-Identifier: MIT
#include "inport.h"

#include "corbautil.h"

#include <algorithm>

namespace Runtime {

InPortBase::InPortBase(const std::string &name, const std::string &dataType, PortableServer::POA_ptr poa)
    : DataPortBase(name, "DataInPort", dataType)
    , m_poa(PortableServer::POA::_duplicate(poa))
{
}

InPortBase::~InPortBase() = default;

std::vector<std::shared_ptr<InPortConnector>> InPortBase::connectors()
{
    std::lock_guard lock(m_mutex);
    return m_connectors;
}

bool InPortBase::isNew()
{
    for (const auto &connector : connectors()) {
        if (connector->hasNew())
            return true;
    }
    return false;
}

bool InPortBase::readMarshalled(SharedCdr *data, bool *littleEndian, std::string *connectorId)
{
    const auto all = connectors();
    const auto took = [&](const InPortConnector &connector) {
        *littleEndian = connector.littleEndian();
        if (connectorId)
            *connectorId = connector.id();
        return true;
    };
    for (const auto &connector : all) {
        if (connector->hasNew() && connector->read(data))
            return took(*connector);
    }
    for (const auto &connector : all) {
        if (dynamic_cast<InPortPullConnector *>(connector.get()) && connector->read(data))
            return took(*connector);
    }
    return false;
}

void InPortBase::setReceiveListener(SampleListener listener)
{
    std::lock_guard lock(m_mutex);
    m_listener = std::move(listener);
}

void InPortBase::notifyReceived(const CdrView &data, bool littleEndian, const std::string &connectorId)
{
    SampleListener listener;
    {
        std::lock_guard lock(m_mutex);
        listener = m_listener;
    }
    if (listener)
        listener(data, littleEndian, connectorId);
}

size_t InPortBase::connectorCount()
{
    std::lock_guard lock(m_mutex);
    return m_connectors.size();
}

RTC::ReturnCode_t InPortBase::publishInterfaces(RTC::ConnectorProfile &profile)
{
    const Properties p = connectorProperties(profile);
    Flow flow = Flow::Push;
    if (!fits(profile, p, &flow))
        return RTC::BAD_PARAMETER;
    if (flow == Flow::Channel)
        return joinChannel(profile);
    if (flow == Flow::Pull)
        return RTC::RTC_OK;
    auto connector = std::make_shared<InPortPushConnector>(
        std::string(profile.connector_id), p, m_poa,
        [this, id = std::string(profile.connector_id)](const CdrView &data, bool littleEndian) {
            notifyReceived(data, littleEndian, id);
        });
    OpenRTM::InPortCdr_var ref = connector->reference();
    offerInterface(profile, "inport", ref.in());
    std::lock_guard lock(m_mutex);
    m_connectors.push_back(connector);
    return RTC::RTC_OK;
}

RTC::ReturnCode_t InPortBase::subscribeInterfaces(const RTC::ConnectorProfile &profile)
{
    const Properties p = connectorProperties(profile);
    Flow flow = Flow::Push;
    if (!fits(profile, p, &flow))
        return RTC::BAD_PARAMETER;
    if (flow == Flow::Channel)
        return checkChannel(profile);
    if (flow == Flow::Push)
        return RTC::RTC_OK;
    OpenRTM::OutPortCdr_var peer = peerInterface<OpenRTM::OutPortCdr>(p, "outport");
    if (CORBA::is_nil(peer))
        return RTC::BAD_PARAMETER;
    auto connector = std::make_shared<InPortPullConnector>(
        std::string(profile.connector_id), p, peer,
        [this, id = std::string(profile.connector_id)](const CdrView &data, bool littleEndian) {
            notifyReceived(data, littleEndian, id);
        });
    std::lock_guard lock(m_mutex);
    m_connectors.push_back(connector);
    return RTC::RTC_OK;
}

void InPortBase::unsubscribeInterfaces(const RTC::ConnectorProfile &profile)
{
    const std::string id(profile.connector_id);
    std::lock_guard lock(m_mutex);
    m_connectors.erase(std::remove_if(m_connectors.begin(), m_connectors.end(),
                                      [&id](const auto &c) { return c->id() == id; }),
                       m_connectors.end());
}

} // namespace Runtime
