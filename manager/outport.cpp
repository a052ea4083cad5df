// SPDX-License-Identifier: MIT
#include "outport.h"

#include "corbautil.h"

#include <algorithm>

namespace Runtime {

OutPortBase::OutPortBase(const std::string &name, const std::string &dataType, PortableServer::POA_ptr poa)
    : DataPortBase(name, "DataOutPort", dataType)
    , m_poa(PortableServer::POA::_duplicate(poa))
{
}

OutPortBase::~OutPortBase() = default;

OutPortBase::SendResults OutPortBase::writeMarshalled(const std::function<CdrView(bool littleEndian)> &marshalIn)
{
    return writeMarshalledAs([&marshalIn](bool littleEndian, const std::string &) { return marshalIn(littleEndian); });
}

OutPortBase::SendResults OutPortBase::writeMarshalledAs(
    const std::function<CdrView(bool littleEndian, const std::string &marshalingType)> &marshalIn)
{
    SendResults results;
    std::vector<std::shared_ptr<OutPortConnector>> connectors;
    {
        std::lock_guard lock(m_mutex);
        for (const auto &connector : m_connectors) {
            if (!m_bypassed.count(connector->id()))
                connectors.push_back(connector);
        }
    }
    // Marshal once per byte order and marshaling type in use, not once per connection: all
    // connections of one kind are served before the view of the next kind is made.
    std::vector<std::pair<bool, std::string>> kinds;
    for (const auto &connector : connectors) {
        const std::pair<bool, std::string> kind(connector->littleEndian(), connector->marshalingType());
        if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
            kinds.push_back(kind);
    }
    for (const auto &[littleEndian, marshalingType] : kinds) {
        const CdrView view = marshalIn(littleEndian, marshalingType);
        for (const auto &connector : connectors) {
            if (connector->littleEndian() == littleEndian && connector->marshalingType() == marshalingType)
                results.emplace_back(connector->id(), view.data ? connector->write(view) : SendStatus::PortError);
        }
    }
    return results;
}

void OutPortBase::setBypassed(const std::string &connectorId, bool bypassed)
{
    std::lock_guard lock(m_mutex);
    if (bypassed)
        m_bypassed.insert(connectorId);
    else
        m_bypassed.erase(connectorId);
}

size_t OutPortBase::connectorCount()
{
    std::lock_guard lock(m_mutex);
    return m_connectors.size();
}

RTC::ReturnCode_t OutPortBase::publishInterfaces(RTC::ConnectorProfile &profile)
{
    const Properties p = connectorProperties(profile);
    Flow flow = Flow::Push;
    if (!fits(profile, p, &flow))
        return RTC::BAD_PARAMETER;
    if (flow == Flow::Channel)
        return joinChannel(profile);
    if (flow == Flow::Push)
        return RTC::RTC_OK;
    auto connector = std::make_shared<OutPortPullConnector>(std::string(profile.connector_id), p, m_poa);
    OpenRTM::OutPortCdr_var ref = connector->reference();
    offerInterface(profile, "outport", ref.in());
    std::lock_guard lock(m_mutex);
    m_connectors.push_back(connector);
    return RTC::RTC_OK;
}

RTC::ReturnCode_t OutPortBase::subscribeInterfaces(const RTC::ConnectorProfile &profile)
{
    const Properties p = connectorProperties(profile);
    Flow flow = Flow::Push;
    if (!fits(profile, p, &flow))
        return RTC::BAD_PARAMETER;
    if (flow == Flow::Channel)
        return checkChannel(profile);
    if (flow == Flow::Pull)
        return RTC::RTC_OK;
    OpenRTM::InPortCdr_var peer = peerInterface<OpenRTM::InPortCdr>(p, "inport");
    if (CORBA::is_nil(peer))
        return RTC::BAD_PARAMETER;
    auto connector
        = std::make_shared<OutPortPushConnector>(std::string(profile.connector_id), p, peer);
    std::lock_guard lock(m_mutex);
    m_connectors.push_back(connector);
    return RTC::RTC_OK;
}

void OutPortBase::unsubscribeInterfaces(const RTC::ConnectorProfile &profile)
{
    const std::string id(profile.connector_id);
    std::shared_ptr<OutPortConnector> removed;
    {
        std::lock_guard lock(m_mutex);
        auto it = std::find_if(m_connectors.begin(), m_connectors.end(),
                               [&id](const auto &c) { return c->id() == id; });
        if (it == m_connectors.end())
            return;
        removed = *it;
        m_connectors.erase(it);
        m_bypassed.erase(id);
    }
    // The connector's threads are joined here, outside the lock.
    removed.reset();
}

} // namespace Runtime
