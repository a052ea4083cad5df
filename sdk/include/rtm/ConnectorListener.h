// SPDX-License-Identifier: MIT
// Listeners called by data ports for each sample (connector data listeners) and for connection
// changes (connector listeners), with OpenRTM-aist 2.x's names and signatures.
#ifndef RTM_CONNECTORLISTENER_H
#define RTM_CONNECTORLISTENER_H

#include <rtm/ByteData.h>
#include <rtm/ConnectorBase.h>

#include <array>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace RTC
{
/// What a listener did to the data or the connector information it was given.
class ConnectorListenerStatus
{
public:
    enum Enum
    {
        NO_CHANGE = 0,
        INFO_CHANGED = 1 << 0,
        DATA_CHANGED = 1 << 1,
        BOTH_CHANGED = INFO_CHANGED | DATA_CHANGED
    };
};

inline ConnectorListenerStatus::Enum operator|(ConnectorListenerStatus::Enum a, ConnectorListenerStatus::Enum b)
{
    return static_cast<ConnectorListenerStatus::Enum>(static_cast<int>(a) | static_cast<int>(b));
}
inline ConnectorListenerStatus::Enum operator&(ConnectorListenerStatus::Enum a, ConnectorListenerStatus::Enum b)
{
    return static_cast<ConnectorListenerStatus::Enum>(static_cast<int>(a) & static_cast<int>(b));
}

/// Brings ReturnCode and its values into a listener class.
#define USE_CONNLISTENER_STATUS                                                                                \
    using ReturnCode = ::RTC::ConnectorListenerStatus::Enum;                                                   \
    using ::RTC::ConnectorListenerStatus::NO_CHANGE;                                                           \
    using ::RTC::ConnectorListenerStatus::INFO_CHANGED;                                                        \
    using ::RTC::ConnectorListenerStatus::DATA_CHANGED;                                                        \
    using ::RTC::ConnectorListenerStatus::BOTH_CHANGED

/// Points in a sample's way through a connector at which data listeners are called.
enum class ConnectorDataListenerType : uint8_t
{
    ON_BUFFER_WRITE = 0,
    ON_BUFFER_FULL,
    ON_BUFFER_WRITE_TIMEOUT,
    ON_BUFFER_OVERWRITE,
    ON_BUFFER_READ,
    ON_SEND,
    ON_RECEIVED,
    ON_RECEIVER_FULL,
    ON_RECEIVER_TIMEOUT,
    ON_RECEIVER_ERROR,
    CONNECTOR_DATA_LISTENER_NUM
};

/// Connection events for connector listeners.
enum class ConnectorListenerType : uint8_t
{
    ON_BUFFER_EMPTY = 0,
    ON_BUFFER_READ_TIMEOUT,
    ON_SENDER_EMPTY,
    ON_SENDER_TIMEOUT,
    ON_SENDER_ERROR,
    ON_CONNECT,
    ON_DISCONNECT,
    CONNECTOR_LISTENER_NUM
};

// OpenRTM-aist 1.x spelled the values without the enumeration's name; sources of that era still do.
static const ConnectorDataListenerType ON_BUFFER_WRITE = ConnectorDataListenerType::ON_BUFFER_WRITE;
static const ConnectorDataListenerType ON_BUFFER_OVERWRITE = ConnectorDataListenerType::ON_BUFFER_OVERWRITE;
static const ConnectorDataListenerType ON_BUFFER_READ = ConnectorDataListenerType::ON_BUFFER_READ;
static const ConnectorDataListenerType ON_SEND = ConnectorDataListenerType::ON_SEND;
static const ConnectorDataListenerType ON_RECEIVED = ConnectorDataListenerType::ON_RECEIVED;
static const ConnectorDataListenerType ON_RECEIVER_FULL = ConnectorDataListenerType::ON_RECEIVER_FULL;
static const ConnectorDataListenerType ON_RECEIVER_TIMEOUT = ConnectorDataListenerType::ON_RECEIVER_TIMEOUT;
static const ConnectorDataListenerType ON_RECEIVER_ERROR = ConnectorDataListenerType::ON_RECEIVER_ERROR;
static const ConnectorListenerType ON_BUFFER_EMPTY = ConnectorListenerType::ON_BUFFER_EMPTY;
static const ConnectorListenerType ON_BUFFER_READ_TIMEOUT = ConnectorListenerType::ON_BUFFER_READ_TIMEOUT;
static const ConnectorListenerType ON_CONNECT = ConnectorListenerType::ON_CONNECT;
static const ConnectorListenerType ON_DISCONNECT = ConnectorListenerType::ON_DISCONNECT;

/// Called with each marshalled sample at one point of ConnectorDataListenerType.
class ConnectorDataListener : public ConnectorListenerStatus
{
public:
    USE_CONNLISTENER_STATUS;
    static const char *toString(ConnectorDataListenerType type);
    virtual ~ConnectorDataListener();
    /**
     * @p data holds the sample in CDR; @p marshalingtype is "cdr". The byte order is in
     * `info.properties["serializer.cdr.endian"]` ("little" or "big").
     */
    virtual ReturnCode operator()(ConnectorInfo &info, ByteData &data, const std::string &marshalingtype) = 0;

    /// RT Studio: true when the listener takes samples of @p type as they are (no marshalling).
    virtual bool acceptsValue(const std::type_info &type) const
    {
        (void)type;
        return false;
    }
    /// RT Studio: a sample of the type acceptsValue() agreed to, handed over inside one process.
    virtual ReturnCode onValue(ConnectorInfo &info, void *value)
    {
        (void)info;
        (void)value;
        return NO_CHANGE;
    }
};

/**
 * A data listener for samples of type @p DataType: implement operator()(ConnectorInfo&,
 * DataType&). Changes made to the sample are not sent on: listeners observe.
 */
template <class DataType>
class ConnectorDataListenerT : public ConnectorDataListener
{
public:
    ReturnCode operator()(ConnectorInfo &info, ByteData &cdr, const std::string &marshalingtype) override
    {
        if (marshalingtype != "cdr" && !marshalingtype.empty())
            return NO_CHANGE;
        DataType data;
        try {
            cdrMemoryStream stream(cdr.getBuffer(), cdr.getDataLength());
            const std::string endian = info.properties.getProperty("serializer.cdr.endian", "little");
            stream.setByteSwapFlag(endian.compare(0, 6, "little") == 0);
            data <<= stream;
        } catch (const CORBA::Exception &) {
            return NO_CHANGE;
        }
        return this->operator()(info, data);
    }
    virtual ReturnCode operator()(ConnectorInfo &info, DataType &data) = 0;

    bool acceptsValue(const std::type_info &type) const override { return type == typeid(DataType); }
    ReturnCode onValue(ConnectorInfo &info, void *value) override
    {
        return this->operator()(info, *static_cast<DataType *>(value));
    }
};

/// Called when a connection of the port is made or removed (and for buffer events).
class ConnectorListener : public ConnectorListenerStatus
{
public:
    USE_CONNLISTENER_STATUS;
    static const char *toString(ConnectorListenerType type);
    virtual ~ConnectorListener();
    virtual ReturnCode operator()(ConnectorInfo &info) = 0;
};

/// What connectors, publishers, providers and consumers are given to reach a port's listeners.
class ConnectorListenersBase
{
public:
    virtual ~ConnectorListenersBase();
};

/**
 * The listeners of one data port and what the port knows of its connections: the ports call
 * connected()/disconnected() as connections come and go and notify…() at each event.
 * Listeners added with autoclean are deleted with the holder or when removed. Thread-safe.
 */
class ConnectorListeners : public ConnectorListenersBase
{
public:
    ConnectorListeners();
    ~ConnectorListeners() override;
    ConnectorListeners(const ConnectorListeners &) = delete;
    ConnectorListeners &operator=(const ConnectorListeners &) = delete;

    void addListener(ConnectorDataListenerType type, ConnectorDataListener *listener, bool autoclean);
    bool removeListener(ConnectorDataListenerType type, ConnectorDataListener *listener);
    void addListener(ConnectorListenerType type, ConnectorListener *listener, bool autoclean);
    bool removeListener(ConnectorListenerType type, ConnectorListener *listener);
    bool hasListeners(ConnectorDataListenerType type) const;

    /// Calls the data listeners of @p type with one sample that went through @p connectorId
    /// (empty: any connection of the port).
    void notifyData(ConnectorDataListenerType type, const std::string &connectorId, const unsigned char *data,
                    unsigned long length, bool littleEndian);
    /**
     * The same for a sample handed over inside one process: typed listeners of @p type get
     * @p value itself, the others its CDR form from @p marshal (made at most once).
     */
    void notifyValue(ConnectorDataListenerType type, const std::string &connectorId, void *value,
                     const std::type_info &valueType, const std::function<std::vector<unsigned char>()> &marshal);
    void notify(ConnectorListenerType type, const std::string &connectorId);

    /// Remembers a new connection (its properties without the `dataport.` prefix).
    void connected(const ConnectorProfile &profile);
    void disconnected(const std::string &connectorId);
    ConnectorInfoList connectorInfos() const;

private:
    struct Private;
    Private *d;
};

/**
 * Data listeners of one event, called in the order added; a listener added with autoclean is
 * deleted when removed or with the holder. notify() ORs what the listeners answer.
 */
class ConnectorDataListenerHolder : public ConnectorListenerStatus
{
public:
    USE_CONNLISTENER_STATUS;
    ConnectorDataListenerHolder();
    virtual ~ConnectorDataListenerHolder();
    ConnectorDataListenerHolder(const ConnectorDataListenerHolder &) = delete;
    ConnectorDataListenerHolder &operator=(const ConnectorDataListenerHolder &) = delete;

    void addListener(ConnectorDataListener *listener, bool autoclean);
    void removeListener(ConnectorDataListener *listener);
    size_t size();
    /// Calls every listener with the marshalled sample @p cdrdata.
    virtual ReturnCode notify(ConnectorInfo &info, ByteData &cdrdata, const std::string &marshalingtype);
    /// notify() with the marshaling type of the connector's InPort (OutPort) side.
    virtual ReturnCode notifyIn(ConnectorInfo &info, ByteData &data);
    virtual ReturnCode notifyOut(ConnectorInfo &info, ByteData &data);

    template <class DataType>
    ReturnCode notifyIn(ConnectorInfo &info, DataType &typeddata)
    {
        return notify(info, typeddata, marshalingType(info, "inport.marshaling_type"));
    }
    template <class DataType>
    ReturnCode notifyOut(ConnectorInfo &info, DataType &typeddata)
    {
        return notify(info, typeddata, marshalingType(info, "outport.marshaling_type"));
    }
    /**
     * Calls every listener with the sample @p typeddata: listeners of its type get it as it is,
     * the others its CDR form (marshalled once, in the byte order of `serializer.cdr.endian`).
     */
    template <class DataType>
    ReturnCode notify(ConnectorInfo &info, DataType &typeddata, const std::string &marshalingtype)
    {
        (void)marshalingtype; // CDR is the one marshaling this runtime has
        std::lock_guard<std::mutex> guard(m_mutex);
        ReturnCode ret = NO_CHANGE;
        ByteData bytes;
        bool marshalled = false;
        for (size_t i = 0; i < m_listeners.size(); ++i) {
            ConnectorDataListener *listener = m_listeners[i].first;
            if (listener->acceptsValue(typeid(DataType))) {
                ret = ret | listener->onValue(info, &typeddata);
                continue;
            }
            if (!marshalled) {
                cdrMemoryStream stream;
                stream.setByteSwapFlag(isLittleEndian(info));
                typeddata >>= stream;
                bytes.writeData(static_cast<const unsigned char *>(stream.bufPtr()),
                                static_cast<unsigned long>(stream.bufSize()));
                marshalled = true;
            }
            ret = ret | (*listener)(info, bytes, "cdr");
        }
        return ret;
    }

protected:
    static std::string marshalingType(ConnectorInfo &info, const char *sideKey);
    static bool isLittleEndian(ConnectorInfo &info);

    std::vector<std::pair<ConnectorDataListener *, bool>> m_listeners;
    std::mutex m_mutex;
};

/**
 * Data listeners for samples of type @p DataType: notify() with a marshalled sample unmarshals
 * it once for the typed listeners (ConnectorDataListenerT<DataType>); what they change is
 * marshalled back into the sample.
 */
template <class DataType>
class ConnectorDataListenerHolderT : public ConnectorDataListenerHolder
{
public:
    ConnectorDataListenerHolderT() = default;
    ~ConnectorDataListenerHolderT() override = default;

    ReturnCode notify(ConnectorInfo &info, ByteData &cdrdata, const std::string &marshalingtype) override
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ReturnCode ret = NO_CHANGE;
        const bool little = isLittleEndian(info);
        DataType data;
        bool unmarshalled = false;
        for (size_t i = 0; i < m_listeners.size(); ++i) {
            ConnectorDataListener *listener = m_listeners[i].first;
            if (!listener->acceptsValue(typeid(DataType))) {
                ret = ret | (*listener)(info, cdrdata, marshalingtype);
                continue;
            }
            if (!unmarshalled) {
                try {
                    cdrMemoryStream in(cdrdata.getBuffer(), cdrdata.getDataLength());
                    in.setByteSwapFlag(little);
                    data <<= in;
                } catch (const CORBA::Exception &) {
                    continue; // not a sample of this type: the typed listeners cannot see it
                }
                unmarshalled = true;
            }
            const ReturnCode result = listener->onValue(info, &data);
            if ((result & DATA_CHANGED) != NO_CHANGE) {
                cdrMemoryStream out;
                out.setByteSwapFlag(little);
                data >>= out;
                cdrdata.writeData(static_cast<const unsigned char *>(out.bufPtr()),
                                  static_cast<unsigned long>(out.bufSize()));
            }
            ret = ret | result;
        }
        return ret;
    }
};

/// Connector listeners of one event, in the order added; notify() ORs their answers.
class ConnectorListenerHolder : public ConnectorListenerStatus
{
public:
    USE_CONNLISTENER_STATUS;
    ConnectorListenerHolder();
    virtual ~ConnectorListenerHolder();
    ConnectorListenerHolder(const ConnectorListenerHolder &) = delete;
    ConnectorListenerHolder &operator=(const ConnectorListenerHolder &) = delete;

    void addListener(ConnectorListener *listener, bool autoclean);
    void removeListener(ConnectorListener *listener);
    size_t size();
    ReturnCode notify(ConnectorInfo &info);

private:
    std::vector<std::pair<ConnectorListener *, bool>> m_listeners;
    std::mutex m_mutex;
};

/// The listeners of a port of data type @p DataType, one holder per event; a type out of range is refused.
template <class DataType>
class ConnectorListenersT : public ConnectorListenersBase
{
public:
    ConnectorListenersT() {}
    ~ConnectorListenersT() override {}

    ConnectorListenerStatus::Enum notifyIn(ConnectorDataListenerType type, ConnectorInfo &info, ByteData &data)
    {
        return inRange(type) ? dataHolder(type).notifyIn(info, data) : ConnectorListenerStatus::NO_CHANGE;
    }
    ConnectorListenerStatus::Enum notifyOut(ConnectorDataListenerType type, ConnectorInfo &info, ByteData &data)
    {
        return inRange(type) ? dataHolder(type).notifyOut(info, data) : ConnectorListenerStatus::NO_CHANGE;
    }
    ConnectorListenerStatus::Enum notifyIn(ConnectorDataListenerType type, ConnectorInfo &info, DataType &data)
    {
        return inRange(type) ? dataHolder(type).notifyIn(info, data) : ConnectorListenerStatus::NO_CHANGE;
    }
    ConnectorListenerStatus::Enum notifyOut(ConnectorDataListenerType type, ConnectorInfo &info, DataType &data)
    {
        return inRange(type) ? dataHolder(type).notifyOut(info, data) : ConnectorListenerStatus::NO_CHANGE;
    }
    ConnectorListenerStatus::Enum notify(ConnectorListenerType type, ConnectorInfo &info)
    {
        return inRange(type) ? connector_[static_cast<uint8_t>(type)].notify(info) : ConnectorListenerStatus::NO_CHANGE;
    }
    bool addListener(ConnectorDataListenerType type, ConnectorDataListener *listener, bool autoclean = true)
    {
        if (!inRange(type))
            return false;
        dataHolder(type).addListener(listener, autoclean);
        return true;
    }
    bool addListener(ConnectorListenerType type, ConnectorListener *listener, bool autoclean = true)
    {
        if (!inRange(type))
            return false;
        connector_[static_cast<uint8_t>(type)].addListener(listener, autoclean);
        return true;
    }
    bool removeListener(ConnectorDataListenerType type, ConnectorDataListener *listener)
    {
        if (!inRange(type))
            return false;
        dataHolder(type).removeListener(listener);
        return true;
    }
    bool removeListener(ConnectorListenerType type, ConnectorListener *listener)
    {
        if (!inRange(type))
            return false;
        connector_[static_cast<uint8_t>(type)].removeListener(listener);
        return true;
    }
    ConnectorDataListenerHolder *getDataListenerHolder(ConnectorDataListenerType type)
    {
        return inRange(type) ? &dataHolder(type) : nullptr;
    }
    ConnectorListenerHolder *getListenerHolder(ConnectorListenerType type)
    {
        return inRange(type) ? &connector_[static_cast<uint8_t>(type)] : nullptr;
    }

private:
    static bool inRange(ConnectorDataListenerType type)
    {
        return type < ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM;
    }
    static bool inRange(ConnectorListenerType type) { return type < ConnectorListenerType::CONNECTOR_LISTENER_NUM; }
    ConnectorDataListenerHolderT<DataType> &dataHolder(ConnectorDataListenerType type)
    {
        return connectorData_[static_cast<uint8_t>(type)];
    }

    std::array<ConnectorDataListenerHolderT<DataType>,
               static_cast<uint8_t>(ConnectorDataListenerType::CONNECTOR_DATA_LISTENER_NUM)>
        connectorData_;
    std::array<ConnectorListenerHolder, static_cast<uint8_t>(ConnectorListenerType::CONNECTOR_LISTENER_NUM)>
        connector_;
};
} // namespace RTC

#endif // RTM_CONNECTORLISTENER_H
