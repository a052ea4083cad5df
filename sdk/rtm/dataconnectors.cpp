// SPDX-License-Identifier: MIT
// OpenRTM-aist's data port framework as objects: connectors, their buffers and the streams
// samples travel in.
#include <rtm/ByteDataStreamBase.h>
#include <rtm/CdrRingBuffer.h>
#include <rtm/InPortConnector.h>
#include <rtm/InPortConsumer.h>
#include <rtm/InPortProvider.h>
#include <rtm/InPortPullConnector.h>
#include <rtm/InPortPushConnector.h>
#include <rtm/OutPortBase.h>
#include <rtm/OutPortConnector.h>
#include <rtm/OutPortConsumer.h>
#include <rtm/OutPortProvider.h>
#include <rtm/OutPortPullConnector.h>
#include <rtm/OutPortPushConnector.h>
#include <rtm/PublisherFlush.h>
#include <rtm/PublisherNew.h>
#include <rtm/PublisherPeriodic.h>

#include "dataportframework.h"

#include <corbautil.h>

namespace RTC {

// --- shared helpers ---

namespace Sdk {

DataPortStatus toDataPortStatus(BufferStatus status)
{
    switch (status) {
    case BufferStatus::OK:
        return DataPortStatus::PORT_OK;
    case BufferStatus::EMPTY:
        return DataPortStatus::BUFFER_EMPTY;
    case BufferStatus::FULL:
        return DataPortStatus::BUFFER_FULL;
    case BufferStatus::TIMEOUT:
        return DataPortStatus::BUFFER_TIMEOUT;
    case BufferStatus::PRECONDITION_NOT_MET:
        return DataPortStatus::PRECONDITION_NOT_MET;
    default:
        return DataPortStatus::BUFFER_ERROR;
    }
}

void notifyData(ConnectorListenersBase *listeners, ConnectorDataListenerType type,
                const ConnectorInfo &info, const ByteData &data, bool littleEndian)
{
    auto *holder = dynamic_cast<ConnectorListeners *>(listeners);
    if (holder != nullptr && holder->hasListeners(type))
        holder->notifyData(type, info.id, data.getBuffer(), data.getDataLength(), littleEndian);
}

void notify(ConnectorListenersBase *listeners, ConnectorListenerType type,
            const ConnectorInfo &info)
{
    if (auto *holder = dynamic_cast<ConnectorListeners *>(listeners))
        holder->notify(type, info.id);
}

ByteData bytesOf(const ByteDataStreamBase &stream)
{
    ByteData bytes;
    bytes.setDataLength(stream.getDataLength());
    stream.readData(bytes.getBuffer(), bytes.getDataLength());
    return bytes;
}

bool littleEndianOf(const ConnectorInfo &info)
{
    return info.properties.getProperty("serializer.cdr.endian", "little").compare(0, 3, "big") != 0;
}

CdrBufferBase *newRingBuffer(ConnectorInfo &info, const char *side)
{
    auto *buffer = new CdrRingBuffer();
    // `buffer.*` for the connection, overlaid with `<side>.buffer.*` as OpenRTM-aist reads them.
    coil::Properties prop(info.properties.getNode("buffer"));
    if (coil::Properties *own = info.properties.findNode(std::string(side) + ".buffer"))
        prop << *own;
    buffer->init(prop);
    return buffer;
}

/**
 * Gives a connection's transport object (a provider or a consumer) what every connector hands
 * it on construction, in OpenRTM-aist's order: the connector's properties, its buffer and the
 * port's listeners. Null transports (a connector made without one) are skipped.
 */
template <class Transport>
void prepareTransport(Transport *transport, ConnectorInfo &profile, CdrBufferBase *buffer,
                      ConnectorListenersBase *listeners)
{
    if (transport == nullptr)
        return;
    transport->init(profile.properties);
    transport->setBuffer(buffer);
    transport->setListener(profile, listeners);
}

SDOPackage::NVList toNVList(const coil::Properties &prop)
{
    SDOPackage::NVList list;
    for (const std::string &key : prop.propertyNames())
        Runtime::nvSet(list, key, prop.getProperty(key));
    return list;
}

} // namespace Sdk

ConnectorListenersBase::~ConnectorListenersBase() = default;

// --- InPortConnector ---

InPortConnector::InPortConnector(ConnectorInfo &info, ConnectorListenersBase *listeners,
                                 CdrBufferBase *buffer)
    : rtclog("InPortConnector")
    , m_profile(info)
    , m_listeners(listeners)
    , m_buffer(buffer)
    , m_littleEndian(Sdk::littleEndianOf(info))
    , m_marshaling_type(info.properties.getProperty("marshaling_type", "cdr"))
    , m_cdr(nullptr)
    , m_directOutPort(nullptr)
{ }

InPortConnector::~InPortConnector() = default;

bool InPortConnector::setOutPort(OutPortBase *directOutPort)
{
    if (directOutPort == nullptr)
        return false;
    // Kept as the direct-port side, which getDirectData() narrows to the sample type.
    m_directOutPort = dynamic_cast<DirectPortBase *>(directOutPort);
    return m_directOutPort != nullptr;
}

const ConnectorInfo &InPortConnector::profile()
{
    return m_profile;
}

const char *InPortConnector::id()
{
    return m_profile.id.c_str();
}

const char *InPortConnector::name()
{
    return m_profile.name.c_str();
}

CdrBufferBase *InPortConnector::getBuffer()
{
    return m_buffer;
}

void InPortConnector::setEndian(bool endian_type)
{
    m_littleEndian = endian_type;
}

bool InPortConnector::isLittleEndian()
{
    return m_littleEndian;
}

BufferStatus InPortConnector::write(ByteData &cdr)
{
    if (m_buffer == nullptr)
        return BufferStatus::PRECONDITION_NOT_MET;
    const BufferStatus status = m_buffer->write(cdr, std::chrono::nanoseconds(0));
    if (status == BufferStatus::OK)
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_WRITE, m_profile, cdr,
                        m_littleEndian);
    else if (status == BufferStatus::FULL)
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_FULL, m_profile, cdr,
                        m_littleEndian);
    return status;
}

void InPortConnector::unsubscribeInterface(const coil::Properties &prop)
{
    (void)prop; // push connections subscribe to nothing; pull connections override this
}

// --- OutPortConnector ---

OutPortConnector::OutPortConnector(ConnectorInfo &info, ConnectorListenersBase *listeners)
    : rtclog("OutPortConnector")
    , m_profile(info)
    , m_littleEndian(Sdk::littleEndianOf(info))
    , m_listeners(listeners)
    , m_marshaling_type(info.properties.getProperty("marshaling_type", "cdr"))
    , m_cdr(nullptr)
    , m_directInPort(nullptr)
    , m_directMode(false)
{ }

OutPortConnector::~OutPortConnector() = default;

bool OutPortConnector::setInPort(InPortBase *directInPort)
{
    m_directInPort = directInPort;
    return directInPort != nullptr;
}

void OutPortConnector::setPullDirectMode()
{
    m_directMode = true;
}

bool OutPortConnector::pullDirectMode()
{
    return m_directMode;
}

const ConnectorInfo &OutPortConnector::profile()
{
    return m_profile;
}

const char *OutPortConnector::id()
{
    return m_profile.id.c_str();
}

const char *OutPortConnector::name()
{
    return m_profile.name.c_str();
}

void OutPortConnector::setEndian(bool endian_type)
{
    m_littleEndian = endian_type;
}

bool OutPortConnector::isLittleEndian()
{
    return m_littleEndian;
}

BufferStatus OutPortConnector::read(ByteData &data)
{
    (void)data;
    return BufferStatus::PRECONDITION_NOT_MET;
}

void OutPortConnector::unsubscribeInterface(const coil::Properties &prop)
{
    (void)prop;
}

// --- InPortPushConnector ---

InPortPushConnector::InPortPushConnector(ConnectorInfo info, InPortProvider *provider,
                                         ConnectorListenersBase *listeners, CdrBufferBase *buffer)
    : InPortConnector(info, listeners, buffer)
    , m_provider(provider)
    , m_deleteBuffer(buffer == nullptr)
{
    if (m_buffer == nullptr)
        m_buffer = createBuffer(m_profile);
    Sdk::prepareTransport(m_provider, m_profile, m_buffer, m_listeners);
    if (m_provider != nullptr)
        m_provider->setConnector(this);
    onConnect();
}

InPortPushConnector::~InPortPushConnector()
{
    disconnect();
    if (m_deleteBuffer)
        delete m_buffer;
}

CdrBufferBase *InPortPushConnector::createBuffer(ConnectorInfo &info)
{
    return Sdk::newRingBuffer(info, "inport");
}

DataPortStatus InPortPushConnector::read(ByteDataStreamBase *data)
{
    if (data == nullptr || m_buffer == nullptr)
        return DataPortStatus::PRECONDITION_NOT_MET;
    ByteData bytes;
    const BufferStatus status = m_buffer->read(bytes, std::chrono::nanoseconds(0));
    if (status == BufferStatus::OK) {
        data->isLittleEndian(m_littleEndian);
        data->writeData(bytes.getBuffer(), bytes.getDataLength());
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_READ, m_profile, bytes,
                        m_littleEndian);
    } else if (status == BufferStatus::EMPTY) {
        Sdk::notify(m_listeners, ConnectorListenerType::ON_BUFFER_EMPTY, m_profile);
    } else if (status == BufferStatus::TIMEOUT) {
        Sdk::notify(m_listeners, ConnectorListenerType::ON_BUFFER_READ_TIMEOUT, m_profile);
    }
    return Sdk::toDataPortStatus(status);
}

DataPortStatus InPortPushConnector::disconnect()
{
    if (m_provider == nullptr)
        return DataPortStatus::PORT_OK;
    onDisconnect();
    delete m_provider;
    m_provider = nullptr;
    return DataPortStatus::PORT_OK;
}

void InPortPushConnector::onConnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_CONNECT, m_profile);
}

void InPortPushConnector::onDisconnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_DISCONNECT, m_profile);
}

// --- InPortPullConnector ---

InPortPullConnector::InPortPullConnector(ConnectorInfo info, OutPortConsumer *consumer,
                                         ConnectorListenersBase *listeners, CdrBufferBase *buffer)
    : InPortConnector(info, listeners, buffer)
    , m_consumer(consumer)
    , m_deleteBuffer(buffer == nullptr)
{
    if (m_buffer == nullptr)
        m_buffer = createBuffer(m_profile);
    Sdk::prepareTransport(m_consumer, m_profile, m_buffer, m_listeners);
    onConnect();
}

InPortPullConnector::~InPortPullConnector()
{
    disconnect();
    if (m_deleteBuffer)
        delete m_buffer;
}

CdrBufferBase *InPortPullConnector::createBuffer(ConnectorInfo &info)
{
    return Sdk::newRingBuffer(info, "inport");
}

DataPortStatus InPortPullConnector::read(ByteDataStreamBase *data)
{
    if (data == nullptr || m_consumer == nullptr)
        return DataPortStatus::PRECONDITION_NOT_MET;
    ByteData bytes;
    const DataPortStatus status = m_consumer->get(bytes);
    if (status == DataPortStatus::PORT_OK) {
        data->isLittleEndian(m_littleEndian);
        data->writeData(bytes.getBuffer(), bytes.getDataLength());
    }
    return status;
}

DataPortStatus InPortPullConnector::disconnect()
{
    if (m_consumer == nullptr)
        return DataPortStatus::PORT_OK;
    onDisconnect();
    delete m_consumer;
    m_consumer = nullptr;
    return DataPortStatus::PORT_OK;
}

void InPortPullConnector::unsubscribeInterface(const coil::Properties &prop)
{
    if (m_consumer != nullptr)
        m_consumer->unsubscribeInterface(Sdk::toNVList(prop));
}

void InPortPullConnector::onConnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_CONNECT, m_profile);
}

void InPortPullConnector::onDisconnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_DISCONNECT, m_profile);
}

// --- OutPortPushConnector ---

OutPortPushConnector::OutPortPushConnector(ConnectorInfo info, InPortConsumer *consumer,
                                           ConnectorListenersBase *listeners, CdrBufferBase *buffer)
    : OutPortConnector(info, listeners)
    , m_consumer(consumer)
    , m_publisher(nullptr)
    , m_buffer(buffer)
    , m_deleteBuffer(buffer == nullptr)
{
    if (m_buffer == nullptr)
        m_buffer = createBuffer(m_profile);
    m_publisher = createPublisher(m_profile);
    if (m_publisher == nullptr) {
        RTC_ERROR(("connector '%s': unknown subscription_type '%s'", m_profile.name.c_str(),
                   m_profile.properties.getProperty("subscription_type").c_str()));
    } else {
        m_publisher->setConsumer(m_consumer);
        m_publisher->setBuffer(m_buffer);
        m_publisher->setListener(m_profile, m_listeners);
        m_publisher->init(m_profile.properties);
    }
    if (m_consumer != nullptr)
        m_consumer->init(m_profile.properties);
    onConnect();
}

OutPortPushConnector::~OutPortPushConnector()
{
    disconnect();
    if (m_deleteBuffer)
        delete m_buffer;
}

PublisherBase *OutPortPushConnector::createPublisher(ConnectorInfo &info)
{
    const std::string type
        = coil::normalize(info.properties.getProperty("subscription_type", "flush"));
    if (type == "flush")
        return new PublisherFlush();
    if (type == "new")
        return new PublisherNew();
    if (type == "periodic")
        return new PublisherPeriodic();
    return nullptr;
}

CdrBufferBase *OutPortPushConnector::createBuffer(ConnectorInfo &info)
{
    return Sdk::newRingBuffer(info, "outport");
}

DataPortStatus OutPortPushConnector::write(ByteDataStreamBase *data)
{
    if (m_publisher == nullptr || data == nullptr)
        return DataPortStatus::PRECONDITION_NOT_MET;
    return m_publisher->write(data, std::chrono::nanoseconds(-1));
}

DataPortStatus OutPortPushConnector::disconnect()
{
    if (m_publisher == nullptr && m_consumer == nullptr)
        return DataPortStatus::PORT_OK;
    onDisconnect();
    // The publisher may still be sending through the consumer: it goes first.
    delete m_publisher;
    m_publisher = nullptr;
    delete m_consumer;
    m_consumer = nullptr;
    return DataPortStatus::PORT_OK;
}

void OutPortPushConnector::activate()
{
    if (m_publisher != nullptr)
        m_publisher->activate();
}

void OutPortPushConnector::deactivate()
{
    if (m_publisher != nullptr)
        m_publisher->deactivate();
}

CdrBufferBase *OutPortPushConnector::getBuffer()
{
    return m_buffer;
}

void OutPortPushConnector::unsubscribeInterface(const coil::Properties &prop)
{
    if (m_consumer != nullptr)
        m_consumer->unsubscribeInterface(Sdk::toNVList(prop));
}

void OutPortPushConnector::onConnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_CONNECT, m_profile);
}

void OutPortPushConnector::onDisconnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_DISCONNECT, m_profile);
}

// --- OutPortPullConnector ---

OutPortPullConnector::OutPortPullConnector(ConnectorInfo info, OutPortProvider *provider,
                                           ConnectorListenersBase *listeners, CdrBufferBase *buffer)
    : OutPortConnector(info, listeners)
    , m_provider(provider)
    , m_buffer(buffer)
    , m_deleteBuffer(buffer == nullptr)
{
    if (m_buffer == nullptr)
        m_buffer = createBuffer(m_profile);
    Sdk::prepareTransport(m_provider, m_profile, m_buffer, m_listeners);
    if (m_provider != nullptr)
        m_provider->setConnector(this);
    onConnect();
}

OutPortPullConnector::~OutPortPullConnector()
{
    disconnect();
    if (m_deleteBuffer)
        delete m_buffer;
}

CdrBufferBase *OutPortPullConnector::createBuffer(ConnectorInfo &info)
{
    return Sdk::newRingBuffer(info, "outport");
}

DataPortStatus OutPortPullConnector::write(ByteDataStreamBase *data)
{
    if (data == nullptr || m_buffer == nullptr)
        return DataPortStatus::PRECONDITION_NOT_MET;
    ByteData bytes = Sdk::bytesOf(*data);
    const BufferStatus status = m_buffer->write(bytes, std::chrono::nanoseconds(0));
    if (status == BufferStatus::OK)
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_WRITE, m_profile, bytes,
                        m_littleEndian);
    else if (status == BufferStatus::FULL)
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_FULL, m_profile, bytes,
                        m_littleEndian);
    return Sdk::toDataPortStatus(status);
}

BufferStatus OutPortPullConnector::read(ByteData &data)
{
    if (m_buffer == nullptr)
        return BufferStatus::PRECONDITION_NOT_MET;
    return m_buffer->read(data, std::chrono::nanoseconds(0));
}

DataPortStatus OutPortPullConnector::disconnect()
{
    if (m_provider == nullptr)
        return DataPortStatus::PORT_OK;
    onDisconnect();
    delete m_provider;
    m_provider = nullptr;
    return DataPortStatus::PORT_OK;
}

CdrBufferBase *OutPortPullConnector::getBuffer()
{
    return m_buffer;
}

void OutPortPullConnector::onConnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_CONNECT, m_profile);
}

void OutPortPullConnector::onDisconnect()
{
    Sdk::notify(m_listeners, ConnectorListenerType::ON_DISCONNECT, m_profile);
}

} // namespace RTC

void CdrRingBufferInit()
{
    RTC::CdrBufferFactory::instance().addFactory(
        "ring_buffer", ::coil::Creator<RTC::CdrBufferBase, RTC::CdrRingBuffer>,
        ::coil::Destructor<RTC::CdrBufferBase, RTC::CdrRingBuffer>);
}
