// SPDX-License-Identifier: MIT
// The SDK's data and service ports: the runtime's ports plus OpenRTM-aist's listeners,
// properties and consumer objects.
#include <rtm/CorbaPort.h>
#include <rtm/InPortBase.h>
#include <rtm/OutPortBase.h>

#include "sdkinternal.h"

#include <corbautil.h>

#include <algorithm>
#include <map>
#include <mutex>

namespace RTC {

namespace {

coil::vstring connectorField(const ConnectorInfoList &infos, std::string ConnectorInfo::*field)
{
    coil::vstring result;
    for (const ConnectorInfo &info : infos)
        result.push_back(info.*field);
    return result;
}

/**
 * Push/flush connections between an OutPort and an InPort of the SDK in this process, paired
 * by connector id as both ends learn of the connection: such samples skip CORBA and CDR.
 */
class DirectLinks
{
public:
    static DirectLinks &instance()
    {
        static DirectLinks links;
        return links;
    }

    void offer(const ConnectorProfile &profile, InPortBase *in, OutPortBase *out)
    {
        if (!eligible(profile))
            return;
        const std::string id(profile.connector_id);
        std::lock_guard<std::mutex> lock(m_mutex);
        Link &link = m_links[id];
        link.in = in ? in : link.in;
        link.out = out ? out : link.out;
        if (link.in && link.out && !link.paired && link.in->dataType() == link.out->dataType()
            && link.in->takesValues() && link.out->givesValues()) {
            link.out->addDirectPeer(id, link.in);
            link.paired = true;
        }
    }

    void withdraw(const std::string &connectorId)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        auto it = m_links.find(connectorId);
        if (it == m_links.end())
            return;
        if (it->second.paired)
            it->second.out->removeDirectPeer(connectorId);
        m_links.erase(it);
    }

private:
    struct Link
    {
        InPortBase *in = nullptr;
        OutPortBase *out = nullptr;
        bool paired = false;
    };

    static bool eligible(const ConnectorProfile &profile)
    {
        const Runtime::Properties p = Runtime::nvToProperties(profile.properties);
        return p.value("dataport.interface_type", "corba_cdr") == "corba_cdr"
               && p.value("dataport.dataflow_type", "push") == "push"
               && p.value("dataport.subscription_type", "flush") == "flush";
    }

    std::mutex m_mutex;
    std::map<std::string, Link> m_links;
};

/// What a connector object of a port cannot do on a port with several connections.
DataPortStatus refuseSeveral(Logger &rtclog, const ConnectorInfo &info, const char *operation)
{
    RTC_ERROR(("connector '%s': %s refused: its port has several connections and its samples travel through the port",
               info.name.c_str(), operation));
    return DataPortStatus::PRECONDITION_NOT_MET;
}

/// A connection of an InPort of the SDK, as OpenRTM-aist's InPortConnector.
class InPortConnection : public InPortConnector
{
public:
    InPortConnection(ConnectorInfo info, ConnectorListenersBase *listeners, InPortBase *port)
        : InPortConnector(info, listeners, nullptr)
        , m_port(port)
    {
    }
    DataPortStatus disconnect() override
    {
        // The port deletes this object while disconnecting: only locals are used from here on.
        InPortBase *port = m_port;
        const std::string id = m_profile.id;
        return port->disconnect(id.c_str()) == RTC_OK ? DataPortStatus::PORT_OK : DataPortStatus::PORT_ERROR;
    }
    DataPortStatus read(ByteDataStreamBase *data) override
    {
        if (data == nullptr)
            return DataPortStatus::INVALID_ARGS;
        if (m_port->getConnectorIds().size() != 1)
            return refuseSeveral(rtclog, m_profile, "read");
        ByteData bytes;
        bool littleEndian = true;
        if (!m_port->takeMarshalled(bytes, littleEndian))
            return DataPortStatus::BUFFER_EMPTY;
        data->isLittleEndian(littleEndian);
        data->writeData(bytes.getBuffer(), bytes.getDataLength());
        return DataPortStatus::PORT_OK;
    }
    CdrBufferBase *getBuffer() override
    {
        RTC_ERROR(("connector '%s': getBuffer(): the runtime keeps the connection's samples in a buffer of its own",
                   m_profile.name.c_str()));
        return nullptr;
    }
    // The runtime's connections carry samples from connect to disconnect.
    void activate() override {}
    void deactivate() override {}

private:
    InPortBase *m_port;
};

/// A connection of an OutPort of the SDK, as OpenRTM-aist's OutPortConnector.
class OutPortConnection : public OutPortConnector
{
public:
    OutPortConnection(ConnectorInfo info, ConnectorListenersBase *listeners, OutPortBase *port)
        : OutPortConnector(info, listeners)
        , m_port(port)
    {
    }
    DataPortStatus disconnect() override
    {
        OutPortBase *port = m_port;
        const std::string id = m_profile.id;
        return port->disconnect(id.c_str()) == RTC_OK ? DataPortStatus::PORT_OK : DataPortStatus::PORT_ERROR;
    }
    DataPortStatus write(ByteDataStreamBase *data) override
    {
        if (data == nullptr)
            return DataPortStatus::INVALID_ARGS;
        if (m_port->getConnectorIds().size() != 1)
            return refuseSeveral(rtclog, m_profile, "write");
        ByteData bytes;
        bytes.setDataLength(data->getDataLength());
        data->readData(bytes.getBuffer(), bytes.getDataLength());
        return m_port->writeMarshalledTo(m_profile.id, bytes, m_littleEndian) ? DataPortStatus::PORT_OK
                                                                              : DataPortStatus::PORT_ERROR;
    }
    CdrBufferBase *getBuffer() override
    {
        RTC_ERROR(("connector '%s': getBuffer(): the runtime keeps the connection's samples in a buffer of its own",
                   m_profile.name.c_str()));
        return nullptr;
    }
    void activate() override {}
    void deactivate() override {}

private:
    OutPortBase *m_port;
};

ConnectorInfo infoOf(DataPortListeners &port, const std::string &id)
{
    ConnectorInfo info;
    port.getConnectorProfileById(id.c_str(), info);
    return info;
}

template <typename Connector>
Connector *findIn(std::mutex &mutex, const std::vector<Connector *> &list, const char *text, bool byId)
{
    const std::string wanted(text ? text : "");
    std::lock_guard<std::mutex> lock(mutex);
    for (Connector *connector : list) {
        if (wanted == (byId ? connector->id() : connector->name()))
            return connector;
    }
    return nullptr;
}

template <typename Connector>
void dropFrom(std::mutex &mutex, std::vector<Connector *> &list, const std::string &id)
{
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = list.begin(); it != list.end(); ++it) {
        if (id == (*it)->id()) {
            delete *it;
            list.erase(it);
            return;
        }
    }
}

} // namespace

// --- DataPortListeners ---

DataPortListeners::DataPortListeners(const char *data_type)
    : rtclog("DataPort")
{
    m_properties.setProperty("dataport.data_type", data_type);
}

DataPortListeners::~DataPortListeners() = default;

void DataPortListeners::init(coil::Properties &prop)
{
    m_properties << prop;
}

Runtime::Properties DataPortListeners::connectorSettings() const
{
    // The port's own `dataport.data_type` (set at construction) is not a connection setting.
    Runtime::Properties settings;
    const Runtime::Properties own = Sdk::toRuntime(m_properties);
    for (const auto &[key, value] : own.entries()) {
        if (key.rfind("dataport.", 0) != 0)
            settings.set("dataport." + key, value);
    }
    return settings;
}

void DataPortListeners::logRefusal(const char *portName, const ConnectorProfile &profile,
                                   const std::string &problem) const
{
    RTC_ERROR(("%s: connector '%s' refused: %s", portName, static_cast<const char *>(profile.name), problem.c_str()));
}

coil::Properties &DataPortListeners::properties()
{
    return m_properties;
}

ConnectorInfoList DataPortListeners::getConnectorProfiles()
{
    return m_listeners.connectorInfos();
}

coil::vstring DataPortListeners::getConnectorIds()
{
    return connectorField(m_listeners.connectorInfos(), &ConnectorInfo::id);
}

coil::vstring DataPortListeners::getConnectorNames()
{
    return connectorField(m_listeners.connectorInfos(), &ConnectorInfo::name);
}

namespace {

template <typename Match>
bool findConnector(const ConnectorInfoList &infos, Match match, ConnectorInfo &prof)
{
    for (const ConnectorInfo &info : infos) {
        if (match(info)) {
            prof = info;
            return true;
        }
    }
    return false;
}

} // namespace

bool DataPortListeners::getConnectorProfileById(const char *id, ConnectorInfo &prof)
{
    const std::string wanted(id ? id : "");
    return findConnector(m_listeners.connectorInfos(), [&](const ConnectorInfo &i) { return i.id == wanted; }, prof);
}

bool DataPortListeners::getConnectorProfileByName(const char *name, ConnectorInfo &prof)
{
    const std::string wanted(name ? name : "");
    return findConnector(m_listeners.connectorInfos(), [&](const ConnectorInfo &i) { return i.name == wanted; },
                         prof);
}

bool DataPortListeners::isLittleEndian()
{
    // Each connection states its byte order; the port is little-endian unless one says big.
    for (const ConnectorInfo &info : m_listeners.connectorInfos()) {
        if (info.properties.getProperty("serializer.cdr.endian", "little").compare(0, 3, "big") == 0)
            return false;
    }
    return true;
}

void DataPortListeners::addConnectorDataListener(ConnectorDataListenerType type, ConnectorDataListener *listener,
                                                 bool autoclean)
{
    m_listeners.addListener(type, listener, autoclean);
}

void DataPortListeners::removeConnectorDataListener(ConnectorDataListenerType type, ConnectorDataListener *listener)
{
    m_listeners.removeListener(type, listener);
}

void DataPortListeners::addConnectorListener(ConnectorListenerType type, ConnectorListener *listener, bool autoclean)
{
    m_listeners.addListener(type, listener, autoclean);
}

void DataPortListeners::removeConnectorListener(ConnectorListenerType type, ConnectorListener *listener)
{
    m_listeners.removeListener(type, listener);
}

// --- InPortBase ---

InPortBase::InPortBase(const char *name, const char *data_type)
    : Runtime::InPortBase(name, data_type, PortableServer::POA_var(Sdk::rootPoa()).in())
    , DataPortListeners(data_type)
{
    setReceiveListener([this](const Runtime::CdrView &data, bool littleEndian, const std::string &connectorId) {
        // A push sample goes into the connection's buffer right after this call.
        const auto length = static_cast<unsigned long>(data.size);
        m_listeners.notifyData(ConnectorDataListenerType::ON_RECEIVED, connectorId, data.data, length, littleEndian);
        m_listeners.notifyData(ConnectorDataListenerType::ON_BUFFER_WRITE, connectorId, data.data, length,
                               littleEndian);
    });
}

InPortBase::~InPortBase()
{
    setReceiveListener({});
    std::lock_guard<std::mutex> lock(m_connectorsMutex);
    for (InPortConnector *connector : m_connectors)
        delete connector;
}

const std::vector<InPortConnector *> &InPortBase::connectors()
{
    return m_connectors;
}

InPortConnector *InPortBase::getConnectorById(const char *id)
{
    return findIn(m_connectorsMutex, m_connectors, id, true);
}

InPortConnector *InPortBase::getConnectorByName(const char *name)
{
    return findIn(m_connectorsMutex, m_connectors, name, false);
}

bool InPortBase::takeMarshalled(ByteData &data, bool &littleEndian)
{
    Runtime::SharedCdr bytes;
    if (!readBytes(&bytes, &littleEndian))
        return false;
    data.writeData(bytes->data(), static_cast<unsigned long>(bytes->size()));
    m_listeners.notifyData(ConnectorDataListenerType::ON_BUFFER_READ, std::string(), bytes->data(),
                           static_cast<unsigned long>(bytes->size()), littleEndian);
    return true;
}

bool InPortBase::receiveMarshalled(const ByteData &, bool, const std::string &)
{
    return false;
}

bool InPortBase::isNew()
{
    return Runtime::InPortBase::isNew();
}

bool InPortBase::isEmpty()
{
    return !Runtime::InPortBase::isNew();
}

bool InPortBase::receiveValue(const void *, const std::type_info &, const std::string &)
{
    return false;
}

ReturnCode_t InPortBase::notify_connect(ConnectorProfile &connector_profile)
{
    const ReturnCode_t result = Runtime::InPortBase::notify_connect(connector_profile);
    if (result == RTC_OK) {
        m_listeners.connected(connector_profile);
        const std::string id(connector_profile.connector_id);
        {
            std::lock_guard<std::mutex> lock(m_connectorsMutex);
            m_connectors.push_back(new InPortConnection(infoOf(*this, id), &m_listeners, this));
        }
        DirectLinks::instance().offer(connector_profile, this, nullptr);
        m_listeners.notify(ConnectorListenerType::ON_CONNECT, std::string(connector_profile.connector_id));
    }
    return result;
}

ReturnCode_t InPortBase::notify_disconnect(const char *connector_id)
{
    DirectLinks::instance().withdraw(connector_id);
    if (connector_id != nullptr)
        dropFrom(m_connectorsMutex, m_connectors, connector_id);
    m_listeners.notify(ConnectorListenerType::ON_DISCONNECT, connector_id);
    const ReturnCode_t result = Runtime::InPortBase::notify_disconnect(connector_id);
    m_listeners.disconnected(connector_id);
    return result;
}

void InPortBase::refused(const ConnectorProfile &profile, const std::string &problem) const
{
    logRefusal(getName(), profile, problem);
}

void InPortBase::logUnsupported(const char *operation, const std::string &name)
{
    RTC_ERROR(("%s: %s(\"%s\") refused: the port has several connections and takes their samples in one queue",
               getName(), operation, name.c_str()));
}

bool InPortBase::readBytes(Runtime::SharedCdr *data, bool *littleEndian, std::string *connectorId)
{
    return readMarshalled(data, littleEndian, connectorId);
}

// --- OutPortBase ---

OutPortBase::OutPortBase(const char *name, const char *data_type)
    : Runtime::OutPortBase(name, data_type, PortableServer::POA_var(Sdk::rootPoa()).in())
    , DataPortListeners(data_type)
{
}

OutPortBase::~OutPortBase()
{
    std::lock_guard<std::mutex> lock(m_connectorsMutex);
    for (OutPortConnector *connector : m_connectors)
        delete connector;
}

const std::vector<OutPortConnector *> &OutPortBase::connectors()
{
    return m_connectors;
}

OutPortConnector *OutPortBase::getConnectorById(const char *id)
{
    return findIn(m_connectorsMutex, m_connectors, id, true);
}

OutPortConnector *OutPortBase::getConnectorByName(const char *name)
{
    return findIn(m_connectorsMutex, m_connectors, name, false);
}

bool OutPortBase::writeMarshalledTo(const std::string &connectorId, const ByteData &data, bool littleEndian)
{
    {
        std::lock_guard<std::mutex> lock(m_directMutex);
        for (const auto &[id, inport] : m_directPeers) {
            if (id == connectorId)
                return inport->receiveMarshalled(data, littleEndian, connectorId);
        }
    }
    // The bytes are in the connection's byte order already (the connector set the stream's).
    const auto results
        = writeMarshalled([&data](bool) { return Runtime::CdrView(data.getBuffer(), data.getDataLength()); });
    for (const auto &[id, result] : results) {
        if (id == connectorId)
            return result == Runtime::SendStatus::Ok;
    }
    return true;
}

ReturnCode_t OutPortBase::notify_connect(ConnectorProfile &connector_profile)
{
    const ReturnCode_t result = Runtime::OutPortBase::notify_connect(connector_profile);
    if (result == RTC_OK) {
        m_listeners.connected(connector_profile);
        const std::string id(connector_profile.connector_id);
        {
            std::lock_guard<std::mutex> lock(m_connectorsMutex);
            m_connectors.push_back(new OutPortConnection(infoOf(*this, id), &m_listeners, this));
        }
        DirectLinks::instance().offer(connector_profile, nullptr, this);
        m_listeners.notify(ConnectorListenerType::ON_CONNECT, std::string(connector_profile.connector_id));
    }
    return result;
}

ReturnCode_t OutPortBase::notify_disconnect(const char *connector_id)
{
    DirectLinks::instance().withdraw(connector_id);
    if (connector_id != nullptr)
        dropFrom(m_connectorsMutex, m_connectors, connector_id);
    m_listeners.notify(ConnectorListenerType::ON_DISCONNECT, connector_id);
    const ReturnCode_t result = Runtime::OutPortBase::notify_disconnect(connector_id);
    m_listeners.disconnected(connector_id);
    return result;
}

void OutPortBase::refused(const ConnectorProfile &profile, const std::string &problem) const
{
    logRefusal(getName(), profile, problem);
}

void OutPortBase::addDirectPeer(const std::string &connectorId, InPortBase *inport)
{
    {
        std::lock_guard<std::mutex> lock(m_directMutex);
        m_directPeers.emplace_back(connectorId, inport);
    }
    setBypassed(connectorId, true);
}

void OutPortBase::removeDirectPeer(const std::string &connectorId)
{
    setBypassed(connectorId, false);
    // Once this returns no writer uses the InPort any more: writers hold the same lock.
    std::lock_guard<std::mutex> lock(m_directMutex);
    m_directPeers.erase(std::remove_if(m_directPeers.begin(), m_directPeers.end(),
                                       [&connectorId](const auto &peer) { return peer.first == connectorId; }),
                        m_directPeers.end());
}

void OutPortBase::writeDirect(const void *value, const std::type_info &type)
{
    std::lock_guard<std::mutex> lock(m_directMutex);
    for (const auto &[connectorId, inport] : m_directPeers)
        inport->receiveValue(value, type, connectorId);
}

void OutPortBase::notifyWrite(void *value, const std::type_info &type,
                              const std::function<std::vector<unsigned char>()> &marshal)
{
    for (const auto event : {ConnectorDataListenerType::ON_BUFFER_WRITE, ConnectorDataListenerType::ON_SEND}) {
        if (m_listeners.hasListeners(event))
            m_listeners.notifyValue(event, std::string(), value, type, marshal);
    }
}

namespace {

DataPortStatus toDataPortStatus(Runtime::SendStatus status)
{
    switch (status) {
    case Runtime::SendStatus::Ok:
        return DataPortStatus::PORT_OK;
    case Runtime::SendStatus::PortError:
        return DataPortStatus::PORT_ERROR;
    case Runtime::SendStatus::BufferFull:
        return DataPortStatus::BUFFER_FULL;
    case Runtime::SendStatus::BufferEmpty:
        return DataPortStatus::BUFFER_EMPTY;
    case Runtime::SendStatus::BufferTimeout:
        return DataPortStatus::BUFFER_TIMEOUT;
    case Runtime::SendStatus::ConnectionLost:
        return DataPortStatus::CONNECTION_LOST;
    case Runtime::SendStatus::UnknownError:
        break;
    }
    return DataPortStatus::UNKNOWN_ERROR;
}

} // namespace

void OutPortBase::writeBytes(const std::function<Runtime::CdrView(bool littleEndian)> &marshal)
{
    keepStatuses(writeMarshalled(marshal));
}

void OutPortBase::writeBytesAs(
    const std::function<Runtime::CdrView(bool littleEndian, const std::string &marshalingType)> &marshal)
{
    keepStatuses(writeMarshalledAs(marshal));
}

void OutPortBase::keepStatuses(const SendResults &results)
{
    DataPortStatusList statuses;
    {
        std::lock_guard<std::mutex> lock(m_connectorsMutex);
        for (OutPortConnector *connector : m_connectors) {
            // Connections served directly (same process) took the value in writeDirect().
            DataPortStatus status = DataPortStatus::PORT_OK;
            for (const auto &[id, result] : results) {
                if (id == connector->id())
                    status = toDataPortStatus(result);
            }
            statuses.push_back(status);
        }
    }
    std::lock_guard<std::mutex> lock(m_statusMutex);
    m_status = statuses;
}

DataPortStatusList OutPortBase::statusList()
{
    std::lock_guard<std::mutex> lock(m_statusMutex);
    return m_status;
}

// --- CorbaPort ---

CorbaPort::CorbaPort(const char *name)
    : Runtime::ServicePort(name, PortableServer::POA_var(Sdk::rootPoa()).in())
{
}

CorbaPort::~CorbaPort() = default;

void CorbaPort::init(coil::Properties &prop)
{
    const std::string limit = prop.getProperty("connection_limit");
    if (!limit.empty())
        setProperty("connection_limit", limit);
}

bool CorbaPort::registerServant(const char *instance_name, const char *type_name, PortableServer::ServantBase *provider)
{
    if (instance_name == nullptr || type_name == nullptr || provider == nullptr)
        return false;
    // The provider is the component's member: the port's release must leave it to its owner.
    provider->_add_ref();
    try {
        Runtime::ServicePort::registerProvider(instance_name, type_name, provider);
    } catch (const CORBA::Exception &) {
        provider->_remove_ref();
        return false;
    }
    return true;
}

bool CorbaPort::registerConsumer(const char *instance_name, const char *type_name, CorbaConsumerBase &consumer)
{
    if (instance_name == nullptr || type_name == nullptr)
        return false;
    m_consumers.push_back({Runtime::ServicePort::registerConsumer(instance_name, type_name), &consumer});
    return true;
}

ReturnCode_t CorbaPort::subscribeInterfaces(const ConnectorProfile &profile)
{
    const ReturnCode_t result = Runtime::ServicePort::subscribeInterfaces(profile);
    updateConsumers();
    return result;
}

void CorbaPort::unsubscribeInterfaces(const ConnectorProfile &profile)
{
    Runtime::ServicePort::unsubscribeInterfaces(profile);
    updateConsumers();
}

void CorbaPort::updateConsumers()
{
    for (ConsumerBinding &binding : m_consumers) {
        CORBA::Object_var object = binding.slot->object();
        if (CORBA::is_nil(object))
            binding.consumer->releaseObject();
        else
            binding.consumer->setObject(object);
    }
}

} // namespace RTC
