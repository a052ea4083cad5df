// SPDX-License-Identifier: MIT
#include <rtm/ConnectorListener.h>

#include "listenerset.h"

#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace RTC {

namespace {

const char *const dataListenerNames[] = {"ON_BUFFER_WRITE", "ON_BUFFER_FULL", "ON_BUFFER_WRITE_TIMEOUT",
                                         "ON_BUFFER_OVERWRITE", "ON_BUFFER_READ", "ON_SEND",
                                         "ON_RECEIVED", "ON_RECEIVER_FULL", "ON_RECEIVER_TIMEOUT",
                                         "ON_RECEIVER_ERROR"};
const char *const listenerNames[] = {"ON_BUFFER_EMPTY", "ON_BUFFER_READ_TIMEOUT", "ON_SENDER_EMPTY",
                                     "ON_SENDER_TIMEOUT", "ON_SENDER_ERROR", "ON_CONNECT", "ON_DISCONNECT"};

} // namespace

const char *ConnectorDataListener::toString(ConnectorDataListenerType type)
{
    const auto index = static_cast<size_t>(type);
    return index < std::size(dataListenerNames) ? dataListenerNames[index] : "";
}

ConnectorDataListener::~ConnectorDataListener() = default;

const char *ConnectorListener::toString(ConnectorListenerType type)
{
    const auto index = static_cast<size_t>(type);
    return index < std::size(listenerNames) ? listenerNames[index] : "";
}

ConnectorListener::~ConnectorListener() = default;

struct ConnectorListeners::Private
{
    mutable std::mutex mutex;
    Sdk::ListenerSet<ConnectorDataListener> data[size_t(ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM)];
    Sdk::ListenerSet<ConnectorListener> events[size_t(ConnectorListenerType::CONNECTOR_LISTENER_NUM)];
    std::map<std::string, ConnectorInfo> connectors;

    /// The connection @p connectorId, else any (listeners get some information even so).
    ConnectorInfo &infoOf(const std::string &connectorId);
};

ConnectorListeners::ConnectorListeners()
    : d(new Private)
{
}

ConnectorListeners::~ConnectorListeners()
{
    delete d;
}

void ConnectorListeners::addListener(ConnectorDataListenerType type, ConnectorDataListener *listener, bool autoclean)
{
    if (listener == nullptr || type >= ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM)
        return;
    std::lock_guard lock(d->mutex);
    d->data[size_t(type)].add(listener, autoclean);
}

bool ConnectorListeners::removeListener(ConnectorDataListenerType type, ConnectorDataListener *listener)
{
    if (type >= ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM)
        return false;
    std::lock_guard lock(d->mutex);
    return d->data[size_t(type)].remove(listener);
}

void ConnectorListeners::addListener(ConnectorListenerType type, ConnectorListener *listener, bool autoclean)
{
    if (listener == nullptr || type >= ConnectorListenerType::CONNECTOR_LISTENER_NUM)
        return;
    std::lock_guard lock(d->mutex);
    d->events[size_t(type)].add(listener, autoclean);
}

bool ConnectorListeners::removeListener(ConnectorListenerType type, ConnectorListener *listener)
{
    if (type >= ConnectorListenerType::CONNECTOR_LISTENER_NUM)
        return false;
    std::lock_guard lock(d->mutex);
    return d->events[size_t(type)].remove(listener);
}

bool ConnectorListeners::hasListeners(ConnectorDataListenerType type) const
{
    if (type >= ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM)
        return false;
    std::lock_guard lock(d->mutex);
    return !d->data[size_t(type)].empty();
}

ConnectorInfo &ConnectorListeners::Private::infoOf(const std::string &connectorId)
{
    if (!connectorId.empty() && connectors.count(connectorId))
        return connectors[connectorId];
    return connectors.empty() ? connectors[std::string()] : connectors.begin()->second;
}

void ConnectorListeners::notifyData(ConnectorDataListenerType type, const std::string &connectorId,
                                    const unsigned char *data, unsigned long length, bool littleEndian)
{
    if (type >= ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM)
        return;
    // Listeners run under the lock: a listener removed meanwhile must not be called afterwards.
    std::lock_guard lock(d->mutex);
    auto &listeners = d->data[size_t(type)];
    if (listeners.empty())
        return;
    ConnectorInfo &info = d->infoOf(connectorId);
    info.properties.setProperty("serializer.cdr.endian", littleEndian ? "little" : "big");
    ByteData bytes(data, length);
    listeners.forEach([&](ConnectorDataListener &listener) { listener(info, bytes, "cdr"); });
}

void ConnectorListeners::notifyValue(ConnectorDataListenerType type, const std::string &connectorId, void *value,
                                     const std::type_info &valueType,
                                     const std::function<std::vector<unsigned char>()> &marshal)
{
    if (type >= ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM)
        return;
    std::lock_guard lock(d->mutex);
    auto &listeners = d->data[size_t(type)];
    if (listeners.empty())
        return;
    ConnectorInfo &info = d->infoOf(connectorId);
    ByteData bytes;
    bool marshalled = false;
    listeners.forEach([&](ConnectorDataListener &listener) {
        if (listener.acceptsValue(valueType)) {
            listener.onValue(info, value);
            return;
        }
        if (!marshalled) {
            const std::vector<unsigned char> cdr = marshal();
            bytes.writeData(cdr.data(), static_cast<unsigned long>(cdr.size()));
            info.properties.setProperty("serializer.cdr.endian", "little");
            marshalled = true;
        }
        listener(info, bytes, "cdr");
    });
}

void ConnectorListeners::notify(ConnectorListenerType type, const std::string &connectorId)
{
    if (type >= ConnectorListenerType::CONNECTOR_LISTENER_NUM)
        return;
    std::lock_guard lock(d->mutex);
    auto it = d->connectors.find(connectorId);
    ConnectorInfo info = it == d->connectors.end() ? ConnectorInfo() : it->second;
    d->events[size_t(type)].forEach([&info](ConnectorListener &listener) { listener(info); });
}

void ConnectorListeners::connected(const ConnectorProfile &profile)
{
    ConnectorInfo info;
    info.name = std::string(profile.name);
    info.id = std::string(profile.connector_id);
    // As in OpenRTM-aist, the ports are listed by their references in string form (no remote call).
    int argc = 0;
    CORBA::ORB_var orb = CORBA::ORB_init(argc, nullptr);
    for (CORBA::ULong i = 0; i < profile.ports.length(); ++i) {
        CORBA::String_var ior = orb->object_to_string(profile.ports[i]);
        info.ports.push_back(std::string(ior.in()));
    }
    for (CORBA::ULong i = 0; i < profile.properties.length(); ++i) {
        const char *text = nullptr;
        if (!(profile.properties[i].value >>= text))
            continue;
        std::string key(profile.properties[i].name);
        if (key.compare(0, 9, "dataport.") == 0)
            key = key.substr(9);
        info.properties.setProperty(key, text);
    }
    std::lock_guard lock(d->mutex);
    d->connectors[info.id] = info;
}

void ConnectorListeners::disconnected(const std::string &connectorId)
{
    std::lock_guard lock(d->mutex);
    d->connectors.erase(connectorId);
}

ConnectorInfoList ConnectorListeners::connectorInfos() const
{
    std::lock_guard lock(d->mutex);
    ConnectorInfoList result;
    for (const auto &entry : d->connectors) {
        if (!entry.first.empty())
            result.push_back(entry.second);
    }
    return result;
}

} // namespace RTC

namespace RTC {

namespace {

/// Deletes the listeners of @p entries added with autoclean.
template <typename Entries>
void deleteOwned(Entries &entries)
{
    for (auto &entry : entries) {
        if (entry.second)
            delete entry.first;
    }
    entries.clear();
}

template <typename Entries, typename Listener>
void removeEntry(Entries &entries, Listener *listener)
{
    for (auto it = entries.begin(); it != entries.end(); ++it) {
        if (it->first == listener) {
            if (it->second)
                delete it->first;
            entries.erase(it);
            return;
        }
    }
}

} // namespace

ConnectorDataListenerHolder::ConnectorDataListenerHolder() = default;

ConnectorDataListenerHolder::~ConnectorDataListenerHolder()
{
    std::lock_guard<std::mutex> guard(m_mutex);
    deleteOwned(m_listeners);
}

void ConnectorDataListenerHolder::addListener(ConnectorDataListener *listener, bool autoclean)
{
    std::lock_guard<std::mutex> guard(m_mutex);
    m_listeners.emplace_back(listener, autoclean);
}

void ConnectorDataListenerHolder::removeListener(ConnectorDataListener *listener)
{
    std::lock_guard<std::mutex> guard(m_mutex);
    removeEntry(m_listeners, listener);
}

size_t ConnectorDataListenerHolder::size()
{
    std::lock_guard<std::mutex> guard(m_mutex);
    return m_listeners.size();
}

ConnectorDataListenerHolder::ReturnCode ConnectorDataListenerHolder::notify(ConnectorInfo &info, ByteData &cdrdata,
                                                                            const std::string &marshalingtype)
{
    std::lock_guard<std::mutex> guard(m_mutex);
    ReturnCode ret = NO_CHANGE;
    for (auto &entry : m_listeners)
        ret = ret | (*entry.first)(info, cdrdata, marshalingtype);
    return ret;
}

ConnectorDataListenerHolder::ReturnCode ConnectorDataListenerHolder::notifyIn(ConnectorInfo &info, ByteData &data)
{
    return notify(info, data, marshalingType(info, "inport.marshaling_type"));
}

ConnectorDataListenerHolder::ReturnCode ConnectorDataListenerHolder::notifyOut(ConnectorInfo &info, ByteData &data)
{
    return notify(info, data, marshalingType(info, "outport.marshaling_type"));
}

std::string ConnectorDataListenerHolder::marshalingType(ConnectorInfo &info, const char *sideKey)
{
    // The side's own setting wins over the connector's.
    const std::string common = info.properties.getProperty("marshaling_type", "cdr");
    return coil::eraseBothEndsBlank(info.properties.getProperty(sideKey, common));
}

bool ConnectorDataListenerHolder::isLittleEndian(ConnectorInfo &info)
{
    const std::string endian = coil::normalize(info.properties.getProperty("serializer.cdr.endian", "little"));
    return endian.compare(0, 3, "big") != 0;
}

ConnectorListenerHolder::ConnectorListenerHolder() = default;

ConnectorListenerHolder::~ConnectorListenerHolder()
{
    std::lock_guard<std::mutex> guard(m_mutex);
    deleteOwned(m_listeners);
}

void ConnectorListenerHolder::addListener(ConnectorListener *listener, bool autoclean)
{
    std::lock_guard<std::mutex> guard(m_mutex);
    m_listeners.emplace_back(listener, autoclean);
}

void ConnectorListenerHolder::removeListener(ConnectorListener *listener)
{
    std::lock_guard<std::mutex> guard(m_mutex);
    removeEntry(m_listeners, listener);
}

size_t ConnectorListenerHolder::size()
{
    std::lock_guard<std::mutex> guard(m_mutex);
    return m_listeners.size();
}

ConnectorListenerHolder::ReturnCode ConnectorListenerHolder::notify(ConnectorInfo &info)
{
    std::lock_guard<std::mutex> guard(m_mutex);
    ReturnCode ret = NO_CHANGE;
    for (auto &entry : m_listeners)
        ret = ret | (*entry.first)(info);
    return ret;
}

} // namespace RTC
