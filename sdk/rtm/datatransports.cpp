// SPDX-License-Identifier: MIT
// The transports of OpenRTM-aist's data port framework as objects: providers and consumers of
// each interface type. corba_cdr works over OpenRTM::InPortCdr / OutPortCdr; the types the
// runtime does not carry (direct as an object, data_service, shared_memory) refuse every use
// with a logged message naming the type.
#include <rtm/InPortCorbaCdrConsumer.h>
#include <rtm/InPortCorbaCdrProvider.h>
#include <rtm/InPortDSConsumer.h>
#include <rtm/InPortDSProvider.h>
#include <rtm/InPortDirectConsumer.h>
#include <rtm/InPortDirectProvider.h>
#include <rtm/InPortSHMConsumer.h>
#include <rtm/InPortSHMProvider.h>
#include <rtm/OutPortCorbaCdrConsumer.h>
#include <rtm/OutPortCorbaCdrProvider.h>
#include <rtm/OutPortDSConsumer.h>
#include <rtm/OutPortDSProvider.h>
#include <rtm/OutPortDirectConsumer.h>
#include <rtm/OutPortDirectProvider.h>
#include <rtm/OutPortSHMConsumer.h>
#include <rtm/OutPortSHMProvider.h>
#include <rtm/SharedMemoryPort.h>

#include "dataportframework.h"
#include "sdkinternal.h"

#include <corbautil.h>

#include <cstring>

namespace RTC {

namespace {

CORBA::ORB_ptr orb()
{
    int argc = 0;
    return CORBA::ORB_init(argc, nullptr);
}

std::string nvValue(const SDOPackage::NVList &list, const std::string &key)
{
    return Runtime::nvString(list, key);
}

// The object `dataport.corba_cdr.<end>_ior` names, nil when it is missing or unreadable.
CORBA::Object_ptr peerObject(const SDOPackage::NVList &properties, const char *end)
{
    const std::string ior = nvValue(properties, std::string("dataport.corba_cdr.") + end + "_ior");
    if (ior.empty())
        return CORBA::Object::_nil();
    try {
        CORBA::ORB_var theOrb = orb();
        return theOrb->string_to_object(ior.c_str());
    } catch (const CORBA::Exception &) {
        return CORBA::Object::_nil();
    }
}

void offerObject(SDOPackage::NVList &properties, const char *end, CORBA::Object_ptr object)
{
    const std::string key = std::string("dataport.corba_cdr.") + end;
    CORBA::ORB_var theOrb = orb();
    CORBA::String_var ior = theOrb->object_to_string(object);
    Runtime::nvSet(properties, key + "_ior", std::string(ior.in()));
    const CORBA::ULong n = properties.length();
    properties.length(n + 1);
    properties[n].name = CORBA::string_dup((key + "_ref").c_str());
    properties[n].value <<= object;
}

// True when connector properties @p prop ask for @p interfaceType.
bool asksFor(const SDOPackage::NVList &prop, const char *interfaceType)
{
    return coil::normalize(nvValue(prop, "dataport.interface_type")) == interfaceType;
}

// A provider answers a request for its interface type with its properties, and only that one.
bool publishWhenAskedFor(SDOPackage::NVList &prop, const std::string &interfaceType,
                         const SDOPackage::NVList &properties)
{
    if (!asksFor(prop, interfaceType.c_str()))
        return false;
    for (CORBA::ULong i = 0; i < properties.length(); ++i) {
        const CORBA::ULong n = prop.length();
        prop.length(n + 1);
        prop[n] = properties[i];
    }
    return true;
}

DataPortStatus fromPortStatus(OpenRTM::PortStatus status)
{
    switch (status) {
    case OpenRTM::PORT_OK:
        return DataPortStatus::PORT_OK;
    case OpenRTM::BUFFER_FULL:
        return DataPortStatus::SEND_FULL;
    case OpenRTM::BUFFER_TIMEOUT:
        return DataPortStatus::SEND_TIMEOUT;
    case OpenRTM::BUFFER_EMPTY:
        return DataPortStatus::BUFFER_EMPTY;
    case OpenRTM::UNKNOWN_ERROR:
        return DataPortStatus::UNKNOWN_ERROR;
    default:
        return DataPortStatus::PORT_ERROR;
    }
}

template<typename Servant> void activateOnce(Servant *servant)
{
    PortableServer::POA_var poa = Sdk::rootPoa();
    try {
        PortableServer::ObjectId_var id = poa->servant_to_id(servant);
    } catch (const PortableServer::POA::ServantNotActive &) {
        PortableServer::ObjectId_var id = poa->activate_object(servant);
    }
}

template<typename Servant> void deactivate(Servant *servant)
{
    try {
        PortableServer::POA_var poa = Sdk::rootPoa();
        PortableServer::ObjectId_var id = poa->servant_to_id(servant);
        poa->deactivate_object(id);
    } catch (const CORBA::Exception &) {
        // Never activated (or the ORB is gone): nothing to withdraw.
    }
}

} // namespace

void Sdk::logUnavailable(const char *what, const char *interfaceType, const char *operation)
{
    Logger rtclog(what);
    RTC_ERROR(("%s: interface type '%s' is not available (RT Studio's data ports carry corba_cdr "
               "only); %s refused",
               what, interfaceType, operation));
}

// --- provider and consumer bases ---

InPortProvider::InPortProvider()
    : rtclog("InPortProvider")
{ }

InPortProvider::~InPortProvider() = default;

void InPortProvider::publishInterfaceProfile(SDOPackage::NVList &prop)
{
    Runtime::nvSet(prop, "dataport.interface_type", m_interfaceType);
}

bool InPortProvider::publishInterface(SDOPackage::NVList &prop)
{
    return publishWhenAskedFor(prop, m_interfaceType, m_properties);
}

void InPortProvider::setInterfaceType(const char *interface_type)
{
    m_interfaceType = interface_type;
}

void InPortProvider::setDataFlowType(const char *dataflow_type)
{
    m_dataflowType = dataflow_type;
}

void InPortProvider::setSubscriptionType(const char *subs_type)
{
    m_subscriptionType = subs_type;
}

OutPortProvider::~OutPortProvider() = default;

void OutPortProvider::init(coil::Properties &prop)
{
    (void)prop; // providers without settings keep OpenRTM-aist's empty default
}

void OutPortProvider::publishInterfaceProfile(SDOPackage::NVList &prop)
{
    Runtime::nvSet(prop, "dataport.interface_type", m_interfaceType);
}

bool OutPortProvider::publishInterface(SDOPackage::NVList &prop)
{
    return publishWhenAskedFor(prop, m_interfaceType, m_properties);
}

void OutPortProvider::setPortType(const char *port_type)
{
    m_portType = port_type;
}

void OutPortProvider::setDataType(const char *data_type)
{
    m_dataType = data_type;
}

void OutPortProvider::setInterfaceType(const char *interface_type)
{
    m_interfaceType = interface_type;
}

void OutPortProvider::setDataFlowType(const char *dataflow_type)
{
    m_dataflowType = dataflow_type;
}

void OutPortProvider::setSubscriptionType(const char *subs_type)
{
    m_subscriptionType = subs_type;
}

// --- corba_cdr ---

InPortCorbaCdrProvider::InPortCorbaCdrProvider()
    : m_buffer(nullptr)
    , m_listeners(nullptr)
    , m_connector(nullptr)
{
    setInterfaceType("corba_cdr");
    setDataFlowType("push");
    setSubscriptionType("Any");
}

InPortCorbaCdrProvider::~InPortCorbaCdrProvider()
{
    deactivate(this);
}

void InPortCorbaCdrProvider::init(coil::Properties &prop)
{
    (void)prop;
}

void InPortCorbaCdrProvider::setBuffer(BufferBase<ByteData> *buffer)
{
    m_buffer = buffer;
}

void InPortCorbaCdrProvider::setListener(ConnectorInfo &info, ConnectorListenersBase *listeners)
{
    m_profile = info;
    m_listeners = listeners;
}

void InPortCorbaCdrProvider::setConnector(InPortConnector *connector)
{
    m_connector = connector;
}

bool InPortCorbaCdrProvider::publishInterface(SDOPackage::NVList &prop)
{
    if (!InPortProvider::publishInterface(prop))
        return false;
    activateOnce(this);
    OpenRTM::InPortCdr_var self = _this();
    offerObject(prop, "inport", self.in());
    return true;
}

OpenRTM::PortStatus InPortCorbaCdrProvider::put(const OpenRTM::CdrData &data)
{
    if (m_buffer == nullptr)
        return OpenRTM::PORT_ERROR;
    ByteData bytes(data.get_buffer(), data.length());
    const bool littleEndian = Sdk::littleEndianOf(m_profile);
    Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_RECEIVED, m_profile, bytes,
                    littleEndian);
    if (m_buffer->full())
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_FULL, m_profile, bytes,
                        littleEndian);
    const BufferStatus status = m_buffer->write(bytes, std::chrono::nanoseconds(0));
    switch (status) {
    case BufferStatus::OK:
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_WRITE, m_profile, bytes,
                        littleEndian);
        return OpenRTM::PORT_OK;
    case BufferStatus::FULL:
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_RECEIVER_FULL, m_profile, bytes,
                        littleEndian);
        return OpenRTM::BUFFER_FULL;
    case BufferStatus::TIMEOUT:
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_RECEIVER_TIMEOUT, m_profile,
                        bytes, littleEndian);
        return OpenRTM::BUFFER_TIMEOUT;
    default:
        Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_RECEIVER_ERROR, m_profile, bytes,
                        littleEndian);
        return OpenRTM::PORT_ERROR;
    }
}

OutPortCorbaCdrProvider::OutPortCorbaCdrProvider()
    : m_buffer(nullptr)
    , m_listeners(nullptr)
    , m_connector(nullptr)
{
    setPortType("DataOutPort");
    setInterfaceType("corba_cdr");
    setDataFlowType("pull");
    setSubscriptionType("Any");
}

OutPortCorbaCdrProvider::~OutPortCorbaCdrProvider()
{
    deactivate(this);
}

void OutPortCorbaCdrProvider::init(coil::Properties &prop)
{
    (void)prop;
}

void OutPortCorbaCdrProvider::setBuffer(CdrBufferBase *buffer)
{
    m_buffer = buffer;
}

void OutPortCorbaCdrProvider::setListener(ConnectorInfo &info, ConnectorListenersBase *listeners)
{
    m_profile = info;
    m_listeners = listeners;
}

void OutPortCorbaCdrProvider::setConnector(OutPortConnector *connector)
{
    m_connector = connector;
}

bool OutPortCorbaCdrProvider::publishInterface(SDOPackage::NVList &prop)
{
    if (!OutPortProvider::publishInterface(prop))
        return false;
    activateOnce(this);
    OpenRTM::OutPortCdr_var self = _this();
    offerObject(prop, "outport", self.in());
    return true;
}

OpenRTM::PortStatus OutPortCorbaCdrProvider::get(OpenRTM::CdrData_out data)
{
    data = new OpenRTM::CdrData;
    if (m_buffer == nullptr)
        return OpenRTM::UNKNOWN_ERROR;
    ByteData bytes;
    const BufferStatus status = m_buffer->read(bytes, std::chrono::nanoseconds(0));
    if (status == BufferStatus::EMPTY) {
        Sdk::notify(m_listeners, ConnectorListenerType::ON_BUFFER_EMPTY, m_profile);
        return OpenRTM::BUFFER_EMPTY;
    }
    if (status == BufferStatus::TIMEOUT)
        return OpenRTM::BUFFER_TIMEOUT;
    if (status != BufferStatus::OK)
        return OpenRTM::UNKNOWN_ERROR;
    data->length(bytes.getDataLength());
    if (bytes.getDataLength() > 0)
        std::memcpy(data->get_buffer(), bytes.getBuffer(), bytes.getDataLength());
    const bool littleEndian = Sdk::littleEndianOf(m_profile);
    Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_BUFFER_READ, m_profile, bytes,
                    littleEndian);
    Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_SEND, m_profile, bytes,
                    littleEndian);
    return OpenRTM::PORT_OK;
}

InPortCorbaCdrConsumer::InPortCorbaCdrConsumer()
    : rtclog("InPortCorbaCdrConsumer")
{ }

InPortCorbaCdrConsumer::~InPortCorbaCdrConsumer() = default;

void InPortCorbaCdrConsumer::init(coil::Properties &prop)
{
    m_properties = prop;
}

DataPortStatus InPortCorbaCdrConsumer::put(ByteData &data)
{
    OpenRTM::InPortCdr_ptr peer = _ptr();
    if (CORBA::is_nil(peer))
        return DataPortStatus::PRECONDITION_NOT_MET;
    OpenRTM::CdrData cdr;
    cdr.length(data.getDataLength());
    if (data.getDataLength() > 0)
        std::memcpy(cdr.get_buffer(), data.getBuffer(), data.getDataLength());
    try {
        return fromPortStatus(peer->put(cdr));
    } catch (const CORBA::Exception &) {
        return DataPortStatus::CONNECTION_LOST;
    }
}

void InPortCorbaCdrConsumer::publishInterfaceProfile(SDOPackage::NVList &properties)
{
    (void)properties; // the OutPort side offers nothing of its own for a push connection
}

bool InPortCorbaCdrConsumer::subscribeInterface(const SDOPackage::NVList &properties)
{
    CORBA::Object_var peer = peerObject(properties, "inport");
    return !CORBA::is_nil(peer) && setObject(peer);
}

void InPortCorbaCdrConsumer::unsubscribeInterface(const SDOPackage::NVList &properties)
{
    (void)properties;
    releaseObject();
}

OutPortCorbaCdrConsumer::OutPortCorbaCdrConsumer()
    : rtclog("OutPortCorbaCdrConsumer")
    , m_buffer(nullptr)
    , m_listeners(nullptr)
{ }

OutPortCorbaCdrConsumer::~OutPortCorbaCdrConsumer() = default;

void OutPortCorbaCdrConsumer::init(coil::Properties &prop)
{
    (void)prop;
}

void OutPortCorbaCdrConsumer::setBuffer(CdrBufferBase *buffer)
{
    m_buffer = buffer;
}

void OutPortCorbaCdrConsumer::setListener(ConnectorInfo &info, ConnectorListenersBase *listeners)
{
    m_profile = info;
    m_listeners = listeners;
}

DataPortStatus OutPortCorbaCdrConsumer::get(ByteData &data)
{
    OpenRTM::OutPortCdr_ptr peer = _ptr();
    if (CORBA::is_nil(peer))
        return DataPortStatus::PRECONDITION_NOT_MET;
    OpenRTM::CdrData_var cdr;
    OpenRTM::PortStatus status;
    try {
        status = peer->get(cdr.out());
    } catch (const CORBA::Exception &) {
        return DataPortStatus::CONNECTION_LOST;
    }
    if (status != OpenRTM::PORT_OK)
        return status == OpenRTM::BUFFER_EMPTY ? DataPortStatus::BUFFER_EMPTY
                                               : fromPortStatus(status);
    data.writeData(cdr->get_buffer(), cdr->length());
    Sdk::notifyData(m_listeners, ConnectorDataListenerType::ON_RECEIVED, m_profile, data,
                    Sdk::littleEndianOf(m_profile));
    return DataPortStatus::PORT_OK;
}

bool OutPortCorbaCdrConsumer::subscribeInterface(const SDOPackage::NVList &properties)
{
    CORBA::Object_var peer = peerObject(properties, "outport");
    return !CORBA::is_nil(peer) && setObject(peer);
}

void OutPortCorbaCdrConsumer::unsubscribeInterface(const SDOPackage::NVList &properties)
{
    (void)properties;
    releaseObject();
}

// --- interface types the runtime does not carry ---

// Each class names its interface type in every refusal; its buffer and listeners are kept only
// so that the setters do what they say.
#define RTC_UNAVAILABLE_TRANSPORT(Prefix, Type)                                                    \
    InPort##Prefix##Provider::InPort##Prefix##Provider()                                           \
        : m_buffer(nullptr)                                                                        \
        , m_listeners(nullptr)                                                                     \
        , m_connector(nullptr)                                                                     \
    {                                                                                              \
        setInterfaceType(Type);                                                                    \
        setDataFlowType("push");                                                                   \
        setSubscriptionType("Any");                                                                \
    }                                                                                              \
    InPort##Prefix##Provider::~InPort##Prefix##Provider() = default;                               \
    void InPort##Prefix##Provider::init(coil::Properties &prop)                                    \
    {                                                                                              \
        (void)prop;                                                                                \
        Sdk::logUnavailable("InPort" #Prefix "Provider", Type, "init");                            \
    }                                                                                              \
    void InPort##Prefix##Provider::setBuffer(BufferBase<ByteData> *buffer)                         \
    {                                                                                              \
        m_buffer = buffer;                                                                         \
    }                                                                                              \
    void InPort##Prefix##Provider::setListener(ConnectorInfo &info,                                \
                                               ConnectorListenersBase *listeners)                  \
    {                                                                                              \
        m_profile = info;                                                                          \
        m_listeners = listeners;                                                                   \
    }                                                                                              \
    void InPort##Prefix##Provider::setConnector(InPortConnector *connector)                        \
    {                                                                                              \
        m_connector = connector;                                                                   \
    }                                                                                              \
    bool InPort##Prefix##Provider::publishInterface(SDOPackage::NVList &prop)                      \
    {                                                                                              \
        (void)prop;                                                                                \
        Sdk::logUnavailable("InPort" #Prefix "Provider", Type, "publishInterface");                \
        return false;                                                                              \
    }                                                                                              \
    OutPort##Prefix##Provider::OutPort##Prefix##Provider()                                         \
        : m_buffer(nullptr)                                                                        \
        , m_listeners(nullptr)                                                                     \
        , m_connector(nullptr)                                                                     \
    {                                                                                              \
        setPortType("DataOutPort");                                                                \
        setInterfaceType(Type);                                                                    \
        setDataFlowType("pull");                                                                   \
        setSubscriptionType("Any");                                                                \
    }                                                                                              \
    OutPort##Prefix##Provider::~OutPort##Prefix##Provider() = default;                             \
    void OutPort##Prefix##Provider::init(coil::Properties &prop)                                   \
    {                                                                                              \
        (void)prop;                                                                                \
        Sdk::logUnavailable("OutPort" #Prefix "Provider", Type, "init");                           \
    }                                                                                              \
    void OutPort##Prefix##Provider::setBuffer(CdrBufferBase *buffer)                               \
    {                                                                                              \
        m_buffer = buffer;                                                                         \
    }                                                                                              \
    void OutPort##Prefix##Provider::setListener(ConnectorInfo &info,                               \
                                                ConnectorListenersBase *listeners)                 \
    {                                                                                              \
        m_profile = info;                                                                          \
        m_listeners = listeners;                                                                   \
    }                                                                                              \
    void OutPort##Prefix##Provider::setConnector(OutPortConnector *connector)                      \
    {                                                                                              \
        m_connector = connector;                                                                   \
    }                                                                                              \
    bool OutPort##Prefix##Provider::publishInterface(SDOPackage::NVList &prop)                     \
    {                                                                                              \
        (void)prop;                                                                                \
        Sdk::logUnavailable("OutPort" #Prefix "Provider", Type, "publishInterface");               \
        return false;                                                                              \
    }                                                                                              \
    InPort##Prefix##Consumer::InPort##Prefix##Consumer()                                           \
        : rtclog("InPort" #Prefix "Consumer")                                                      \
    { }                                                                                            \
    InPort##Prefix##Consumer::~InPort##Prefix##Consumer() = default;                               \
    void InPort##Prefix##Consumer::init(coil::Properties &prop)                                    \
    {                                                                                              \
        m_properties = prop;                                                                       \
    }                                                                                              \
    DataPortStatus InPort##Prefix##Consumer::put(ByteData &data)                                   \
    {                                                                                              \
        (void)data;                                                                                \
        Sdk::logUnavailable("InPort" #Prefix "Consumer", Type, "put");                             \
        return DataPortStatus::PORT_ERROR;                                                         \
    }                                                                                              \
    void InPort##Prefix##Consumer::publishInterfaceProfile(SDOPackage::NVList &properties)         \
    {                                                                                              \
        (void)properties;                                                                          \
    }                                                                                              \
    bool InPort##Prefix##Consumer::subscribeInterface(const SDOPackage::NVList &properties)        \
    {                                                                                              \
        (void)properties;                                                                          \
        Sdk::logUnavailable("InPort" #Prefix "Consumer", Type, "subscribeInterface");              \
        return false;                                                                              \
    }                                                                                              \
    void InPort##Prefix##Consumer::unsubscribeInterface(const SDOPackage::NVList &properties)      \
    {                                                                                              \
        (void)properties;                                                                          \
    }                                                                                              \
    OutPort##Prefix##Consumer::OutPort##Prefix##Consumer()                                         \
        : rtclog("OutPort" #Prefix "Consumer")                                                     \
        , m_buffer(nullptr)                                                                        \
        , m_listeners(nullptr)                                                                     \
    { }                                                                                            \
    OutPort##Prefix##Consumer::~OutPort##Prefix##Consumer() = default;                             \
    void OutPort##Prefix##Consumer::init(coil::Properties &prop)                                   \
    {                                                                                              \
        (void)prop;                                                                                \
    }                                                                                              \
    void OutPort##Prefix##Consumer::setBuffer(CdrBufferBase *buffer)                               \
    {                                                                                              \
        m_buffer = buffer;                                                                         \
    }                                                                                              \
    void OutPort##Prefix##Consumer::setListener(ConnectorInfo &info,                               \
                                                ConnectorListenersBase *listeners)                 \
    {                                                                                              \
        m_profile = info;                                                                          \
        m_listeners = listeners;                                                                   \
    }                                                                                              \
    DataPortStatus OutPort##Prefix##Consumer::get(ByteData &data)                                  \
    {                                                                                              \
        (void)data;                                                                                \
        Sdk::logUnavailable("OutPort" #Prefix "Consumer", Type, "get");                            \
        return DataPortStatus::PORT_ERROR;                                                         \
    }                                                                                              \
    bool OutPort##Prefix##Consumer::subscribeInterface(const SDOPackage::NVList &properties)       \
    {                                                                                              \
        (void)properties;                                                                          \
        Sdk::logUnavailable("OutPort" #Prefix "Consumer", Type, "subscribeInterface");             \
        return false;                                                                              \
    }                                                                                              \
    void OutPort##Prefix##Consumer::unsubscribeInterface(const SDOPackage::NVList &properties)     \
    {                                                                                              \
        (void)properties;                                                                          \
    }

// In-process delivery happens between the SDK's ports themselves (on corba_cdr connections of
// one process), not through transport objects.
RTC_UNAVAILABLE_TRANSPORT(Direct, "direct")
RTC_UNAVAILABLE_TRANSPORT(DS, "data_service")
RTC_UNAVAILABLE_TRANSPORT(SHM, "shared_memory")

#undef RTC_UNAVAILABLE_TRANSPORT

// --- shared memory ---

SharedMemoryPort::SharedMemoryPort()
    : m_endian(true)
    , rtclog("SharedMemoryPort")
{ }

SharedMemoryPort::~SharedMemoryPort() = default;

int SharedMemoryPort::string_to_MemorySize(std::string size_str)
{
    // Sizes read as OpenRTM-aist writes them: a number with an optional k, M or G.
    if (size_str.empty())
        return 0;
    int factor = 1;
    switch (size_str.back()) {
    case 'k':
    case 'K':
        factor = 1024;
        break;
    case 'm':
    case 'M':
        factor = 1024 * 1024;
        break;
    case 'g':
    case 'G':
        factor = 1024 * 1024 * 1024;
        break;
    default:
        break;
    }
    if (factor != 1)
        size_str.pop_back();
    int value = 0;
    return coil::stringTo(value, size_str.c_str()) ? value * factor : 0;
}

void SharedMemoryPort::create_memory(::CORBA::ULongLong memory_size, const char *shm_address)
{
    (void)memory_size;
    (void)shm_address;
    Sdk::logUnavailable("SharedMemoryPort", "shared_memory", "create_memory");
}

void SharedMemoryPort::open_memory(::CORBA::ULongLong memory_size, const char *shm_address)
{
    (void)memory_size;
    (void)shm_address;
    Sdk::logUnavailable("SharedMemoryPort", "shared_memory", "open_memory");
}

void SharedMemoryPort::close_memory(::CORBA::Boolean unlink)
{
    (void)unlink; // nothing was ever opened
}

void SharedMemoryPort::write(ByteData &data)
{
    (void)data;
    Sdk::logUnavailable("SharedMemoryPort", "shared_memory", "write");
}

void SharedMemoryPort::read(ByteData &data)
{
    (void)data;
    Sdk::logUnavailable("SharedMemoryPort", "shared_memory", "read");
}

void SharedMemoryPort::setEndian(::CORBA::Boolean endian)
{
    m_endian = endian;
}

::OpenRTM::PortStatus SharedMemoryPort::put()
{
    Sdk::logUnavailable("SharedMemoryPort", "shared_memory", "put");
    return OpenRTM::PORT_ERROR;
}

::OpenRTM::PortStatus SharedMemoryPort::get()
{
    Sdk::logUnavailable("SharedMemoryPort", "shared_memory", "get");
    return OpenRTM::PORT_ERROR;
}

} // namespace RTC

// Each transport registers under its interface type, as OpenRTM-aist's module init functions do.
namespace {
template<class Factory, class Abstract, class Concrete> void registerIn(const char *interfaceType)
{
    Factory::instance().addFactory(interfaceType, ::coil::Creator<Abstract, Concrete>,
                                   ::coil::Destructor<Abstract, Concrete>);
}
} // namespace

#define RTC_TRANSPORT_INIT(Prefix, Type)                                                           \
    void InPort##Prefix##ProviderInit()                                                            \
    {                                                                                              \
        registerIn<RTC::InPortProviderFactory, RTC::InPortProvider,                                \
                   RTC::InPort##Prefix##Provider>(Type);                                           \
    }                                                                                              \
    void InPort##Prefix##ConsumerInit()                                                            \
    {                                                                                              \
        registerIn<RTC::InPortConsumerFactory, RTC::InPortConsumer,                                \
                   RTC::InPort##Prefix##Consumer>(Type);                                           \
    }                                                                                              \
    void OutPort##Prefix##ProviderInit()                                                           \
    {                                                                                              \
        registerIn<RTC::OutPortProviderFactory, RTC::OutPortProvider,                              \
                   RTC::OutPort##Prefix##Provider>(Type);                                          \
    }                                                                                              \
    void OutPort##Prefix##ConsumerInit()                                                           \
    {                                                                                              \
        registerIn<RTC::OutPortConsumerFactory, RTC::OutPortConsumer,                              \
                   RTC::OutPort##Prefix##Consumer>(Type);                                          \
    }

RTC_TRANSPORT_INIT(CorbaCdr, "corba_cdr")
RTC_TRANSPORT_INIT(Direct, "direct")
RTC_TRANSPORT_INIT(DS, "data_service")
RTC_TRANSPORT_INIT(SHM, "shared_memory")

#undef RTC_TRANSPORT_INIT
