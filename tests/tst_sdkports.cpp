// SPDX-License-Identifier: MIT
// Data ports and components of the SDK as older and hand-written OpenRTM-aist components use
// them: the port callbacks (OnWrite, OnWriteConvert, OnRead, OnReadConvert, OnUnderflow,
// OnOverflow), the port API (names, profile, connectors), the component action listeners and
// the port connect listeners, each at the moment OpenRTM-aist calls it, over real connections
// between components of one manager.
#include "sdkinprocess.h"

#include <rtm/BufferBase.h>
#include <rtm/CdrRingBuffer.h>
#include <rtm/ComponentActionListener.h>
#include <rtm/ConfigAdmin.h>
#include <rtm/ConnectorListener.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>
#include <rtm/Factory.h>
#include <rtm/FsmActionListener.h>
#include <rtm/InPortCorbaCdrConsumer.h>
#include <rtm/InPortCorbaCdrProvider.h>
#include <rtm/InPortDSConsumer.h>
#include <rtm/InPortPullConnector.h>
#include <rtm/InPortPushConnector.h>
#include <rtm/InPortSHMConsumer.h>
#include <rtm/Manager.h>
#include <rtm/ManagerServant.h>
#include <rtm/OutPortCorbaCdrConsumer.h>
#include <rtm/OutPortCorbaCdrProvider.h>
#include <rtm/OutPortPullConnector.h>
#include <rtm/OutPortPushConnector.h>
#include <rtm/PortAdmin.h>
#include <rtm/PortCallback.h>
#include <rtm/PortConnectListener.h>
#include <rtm/PublisherNew.h>
#include <rtm/SdoServiceConsumerBase.h>
#include <rtm/SdoServiceProviderBase.h>
#include <rtm/SharedMemoryPort.h>
#include <rtm/SystemLogger.h>

#include <corbautil.h>

#include "loggersink.h"

#include <QtTest>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace {

/// What happened, in order, across the components and callbacks of one test.
class EventLog
{
public:
    void add(const std::string &event)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_events.push_back(event);
    }
    std::vector<std::string> events()
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_events;
    }
    void clear()
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_events.clear();
    }
    /// The events that start with @p prefix.
    QStringList matching(const std::string &prefix)
    {
        QStringList found;
        for (const std::string &event : events()) {
            if (event.compare(0, prefix.size(), prefix) == 0)
                found << QString::fromStdString(event);
        }
        return found;
    }

private:
    std::mutex m_mutex;
    std::vector<std::string> m_events;
};

EventLog &eventLog()
{
    static EventLog log;
    return log;
}

std::string number(long value)
{
    return std::to_string(value);
}

// --- port callbacks ---

struct RecordWrite : RTC::OnWrite<RTC::TimedLong>
{
    void operator()(const RTC::TimedLong &value) override
    {
        eventLog().add("write " + number(value.data));
    }
};

struct TimesTen : RTC::OnWriteConvert<RTC::TimedLong>
{
    RTC::TimedLong operator()(const RTC::TimedLong &value) override
    {
        eventLog().add("wconvert " + number(value.data));
        RTC::TimedLong converted = value;
        converted.data = value.data * 10;
        return converted;
    }
};

struct RecordRead : RTC::OnRead<RTC::TimedLong>
{
    void operator()() override { eventLog().add("read"); }
};

struct PlusOne : RTC::OnReadConvert<RTC::TimedLong>
{
    RTC::TimedLong operator()(const RTC::TimedLong &value) override
    {
        eventLog().add("rconvert " + number(value.data));
        RTC::TimedLong converted = value;
        converted.data = value.data + 1;
        return converted;
    }
};

struct SupplyOnUnderflow : RTC::OnUnderflow<RTC::TimedLong>
{
    RTC::TimedLong operator()() override
    {
        eventLog().add("underflow");
        RTC::TimedLong supplied;
        supplied.tm.sec = 0;
        supplied.tm.nsec = 0;
        supplied.data = -7;
        return supplied;
    }
};

struct RecordOverflow : RTC::OnOverflow<RTC::TimedLong>
{
    void operator()(const RTC::TimedLong &value) override
    {
        eventLog().add("overflow " + number(value.data));
    }
};

/// A PortBase callback that logs its name and the connector's.
struct RecordConnection : RTC::ConnectionCallback
{
    explicit RecordConnection(const char *what)
        : m_what(what)
    { }
    void operator()(RTC::ConnectorProfile &profile) override
    {
        eventLog().add(std::string("callback ") + m_what + " " + profile.name.in());
    }
    std::string m_what;
};

// --- components ---

const char *const writerSpec[] = {"implementation_id",
                                  "PortsWriter",
                                  "type_name",
                                  "PortsWriter",
                                  "description",
                                  "writer",
                                  "version",
                                  "1.0.0",
                                  "vendor",
                                  "RTStudioTests",
                                  "category",
                                  "test",
                                  "activity_type",
                                  "PERIODIC",
                                  "kind",
                                  "DataFlowComponent",
                                  "max_instance",
                                  "0",
                                  "language",
                                  "C++",
                                  "lang_type",
                                  "compile",
                                  "exec_cxt.periodic.rate",
                                  "200",
                                  ""};
const char *const readerSpec[] = {"implementation_id",
                                  "PortsReader",
                                  "type_name",
                                  "PortsReader",
                                  "description",
                                  "reader",
                                  "version",
                                  "1.0.0",
                                  "vendor",
                                  "RTStudioTests",
                                  "category",
                                  "test",
                                  "activity_type",
                                  "PERIODIC",
                                  "kind",
                                  "DataFlowComponent",
                                  "max_instance",
                                  "0",
                                  "language",
                                  "C++",
                                  "lang_type",
                                  "compile",
                                  "exec_cxt.periodic.rate",
                                  "200",
                                  ""};

/// Writes when the test says so; its listeners (added before onInitialize) log every action.
class PortsWriter : public RTC::DataFlowComponentBase
{
public:
    explicit PortsWriter(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_outOut("out", m_out)
        , m_servicePort("service")
    {
        using Pre = RTC::PreComponentActionListenerType;
        using Post = RTC::PostComponentActionListenerType;
        // The member-function forms, as components write them.
        addPreComponentActionListener(Pre::PRE_ON_INITIALIZE, *this, &PortsWriter::preInitialize);
        addPostComponentActionListener(Post::POST_ON_INITIALIZE, *this,
                                       &PortsWriter::postInitialize);
        addPreComponentActionListener(Pre::PRE_ON_ACTIVATED, *this, &PortsWriter::preActivated);
        addPostComponentActionListener(Post::POST_ON_ACTIVATED, *this, &PortsWriter::postActivated);
        addPreComponentActionListener(Pre::PRE_ON_EXECUTE, *this, &PortsWriter::preExecute);
        addPostComponentActionListener(Post::POST_ON_EXECUTE, *this, &PortsWriter::postExecute);
        addPreComponentActionListener(Pre::PRE_ON_DEACTIVATED, *this, &PortsWriter::preDeactivated);
        addPreComponentActionListener(Pre::PRE_ON_FINALIZE, *this, &PortsWriter::preFinalize);
        addPostComponentActionListener(Post::POST_ON_FINALIZE, *this, &PortsWriter::postFinalize);
        addPostComponentActionListener(Post::POST_ON_DEACTIVATED, *this,
                                       &PortsWriter::postDeactivated);
        addPortActionListener(RTC::PortActionListenerType::ADD_PORT, *this,
                              &PortsWriter::portAdded);
        addPortActionListener(RTC::PortActionListenerType::REMOVE_PORT, *this,
                              &PortsWriter::portRemoved);
        addExecutionContextActionListener(RTC::ExecutionContextActionListenerType::EC_ATTACHED,
                                          *this, &PortsWriter::attached);
        addExecutionContextActionListener(RTC::ExecutionContextActionListenerType::EC_DETACHED,
                                          *this, &PortsWriter::detached);
        using Connect = RTC::PortConnectListenerType;
        using Ret = RTC::PortConnectRetListenerType;
        for (Connect type : {Connect::ON_NOTIFY_CONNECT, Connect::ON_NOTIFY_DISCONNECT,
                             Connect::ON_UNSUBSCRIBE_INTERFACES})
            addPortConnectListener(type, new ConnectStep(type));
        for (Ret type :
             {Ret::ON_PUBLISH_INTERFACES, Ret::ON_CONNECT_NEXTPORT, Ret::ON_SUBSCRIBE_INTERFACES,
              Ret::ON_CONNECTED, Ret::ON_DISCONNECT_NEXT, Ret::ON_DISCONNECTED})
            addPortConnectRetListener(type, new ConnectRetStep(type));
    }
    RTC::ReturnCode_t onInitialize() override
    {
        eventLog().add("onInitialize");
        m_out.data = 0;
        addOutPort("out", m_outOut);
        addPort(m_servicePort);
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onActivated(RTC::UniqueId) override
    {
        eventLog().add("onActivated");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        eventLog().add("onExecute");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onDeactivated(RTC::UniqueId) override
    {
        eventLog().add("onDeactivated");
        return RTC::RTC_OK;
    }

    bool write(long value)
    {
        m_out.data = value;
        return m_outOut.write();
    }
    RTC::OutPort<RTC::TimedLong> &outPort() { return m_outOut; }
    RTC::CorbaPort &servicePort() { return m_servicePort; }
    void dropPort() { removeOutPort(m_outOut); }

private:
    class ConnectStep : public RTC::PortConnectListener
    {
    public:
        explicit ConnectStep(RTC::PortConnectListenerType type)
            : m_type(type)
        { }
        void operator()(const char *portname, RTC::ConnectorProfile &) override
        {
            eventLog().add(std::string("port ") + toString(m_type) + " " + portname);
        }

    private:
        RTC::PortConnectListenerType m_type;
    };
    class ConnectRetStep : public RTC::PortConnectRetListener
    {
    public:
        explicit ConnectRetStep(RTC::PortConnectRetListenerType type)
            : m_type(type)
        { }
        void operator()(const char *portname, RTC::ConnectorProfile &,
                        RTC::ReturnCode_t ret) override
        {
            eventLog().add(std::string("port ") + toString(m_type) + " " + portname + " "
                           + number(long(ret)));
        }

    private:
        RTC::PortConnectRetListenerType m_type;
    };

    void preInitialize(RTC::UniqueId id) { eventLog().add("pre initialize " + number(long(id))); }
    void postInitialize(RTC::UniqueId id, RTC::ReturnCode_t ret)
    {
        eventLog().add("post initialize " + number(long(id)) + " " + number(long(ret)));
    }
    void preActivated(RTC::UniqueId id) { eventLog().add("pre activated " + number(long(id))); }
    void postActivated(RTC::UniqueId id, RTC::ReturnCode_t ret)
    {
        eventLog().add("post activated " + number(long(id)) + " " + number(long(ret)));
    }
    void preExecute(RTC::UniqueId) { eventLog().add("pre execute"); }
    void postExecute(RTC::UniqueId, RTC::ReturnCode_t) { eventLog().add("post execute"); }
    void preDeactivated(RTC::UniqueId) { eventLog().add("pre deactivated"); }
    void postDeactivated(RTC::UniqueId, RTC::ReturnCode_t) { eventLog().add("post deactivated"); }
    void preFinalize(RTC::UniqueId id) { eventLog().add("pre finalize " + number(long(id))); }
    void postFinalize(RTC::UniqueId id, RTC::ReturnCode_t ret)
    {
        eventLog().add("post finalize " + number(long(id)) + " " + number(long(ret)));
    }
    void portAdded(const RTC::PortProfile &profile)
    {
        eventLog().add(std::string("add port ") + profile.name.in());
    }
    void portRemoved(const RTC::PortProfile &profile)
    {
        eventLog().add(std::string("remove port ") + profile.name.in());
    }
    void attached(RTC::UniqueId id) { eventLog().add("attached " + number(long(id))); }
    void detached(RTC::UniqueId id) { eventLog().add("detached " + number(long(id))); }

    RTC::TimedLong m_out;
    RTC::OutPort<RTC::TimedLong> m_outOut;
    RTC::CorbaPort m_servicePort;
};

/// Reads when the test says so.
class PortsReader : public RTC::DataFlowComponentBase
{
public:
    explicit PortsReader(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_inIn("in", m_in)
    { }
    RTC::ReturnCode_t onInitialize() override
    {
        m_in.data = 0;
        addInPort("in", m_inIn);
        return RTC::RTC_OK;
    }
    bool read(long *value, const std::string &connector = std::string())
    {
        const bool ok = m_inIn.read(connector);
        *value = m_in.data;
        return ok;
    }
    RTC::InPort<RTC::TimedLong> &inPort() { return m_inIn; }

private:
    RTC::TimedLong m_in;
    RTC::InPort<RTC::TimedLong> m_inIn;
};

/// An SDO service a component offers; it counts how often it was finalized.
class CountingSdoService : public RTC::SdoServiceProviderBase
{
public:
    bool init(RTC::RTObject_impl &, const SDOPackage::ServiceProfile &profile) override
    {
        m_profile = profile;
        return true;
    }
    bool reinit(const SDOPackage::ServiceProfile &profile) override
    {
        m_profile = profile;
        return true;
    }
    const SDOPackage::ServiceProfile &getProfile() const override { return m_profile; }
    void finalize() override { ++finalized; }

    int finalized = 0;

private:
    SDOPackage::ServiceProfile m_profile;
};

/// An SDO service consumer the factory makes; it logs what happens to it.
class LoggingSdoConsumer : public RTC::SdoServiceConsumerBase
{
public:
    bool init(RTC::RTObject_impl &, const SDOPackage::ServiceProfile &profile) override
    {
        m_profile = profile;
        eventLog().add(std::string("consumer init ") + profile.id.in());
        return true;
    }
    bool reinit(const SDOPackage::ServiceProfile &profile) override
    {
        m_profile = profile;
        eventLog().add(std::string("consumer reinit ") + profile.id.in());
        return true;
    }
    const SDOPackage::ServiceProfile &getProfile() const override { return m_profile; }
    void finalize() override
    {
        eventLog().add(std::string("consumer finalize ") + m_profile.id.in());
    }

private:
    SDOPackage::ServiceProfile m_profile;
};

/// A stream of plain bytes, as serializers fill them.
class BytesStream : public RTC::ByteDataStreamBase
{
public:
    BytesStream() = default;
    explicit BytesStream(const std::vector<unsigned char> &bytes)
        : m_bytes(bytes)
    { }
    void writeData(const unsigned char *buffer, unsigned long length) override
    {
        m_bytes.assign(buffer, buffer + length);
    }
    void readData(unsigned char *buffer, unsigned long length) const override
    {
        std::memcpy(buffer, m_bytes.data(), std::min<size_t>(length, m_bytes.size()));
    }
    unsigned long getDataLength() const override
    {
        return static_cast<unsigned long>(m_bytes.size());
    }

    std::vector<unsigned char> m_bytes;
};

// QTest would take RTC::toString(DataPortStatus) for its own (and free its static text): names
// compare instead.
QString status(RTC::DataPortStatus value)
{
    return QString::fromLatin1(RTC::toString(value));
}

std::vector<unsigned char> marshalled(long value)
{
    RTC::TimedLong sample;
    sample.tm.sec = 1;
    sample.tm.nsec = 2;
    sample.data = value;
    return Runtime::marshal(sample, true);
}

long unmarshalled(const std::vector<unsigned char> &bytes)
{
    RTC::TimedLong sample;
    sample.data = -1;
    Runtime::unmarshal(Runtime::CdrView(bytes.data(), bytes.size()), true, &sample);
    return sample.data;
}

/// Connection information as a port gives it to its connectors (no `dataport.` prefix).
RTC::ConnectorInfo framedInfo(const char *subscription)
{
    coil::Properties prop;
    prop.setProperty("interface_type", "corba_cdr");
    prop.setProperty("subscription_type", subscription);
    prop.setProperty("buffer.read.empty_policy", "do_nothing");
    return RTC::ConnectorInfo("framed", "framed-id", coil::vstring(), prop);
}

SDOPackage::NVList corbaCdrProperties()
{
    SDOPackage::NVList properties;
    Runtime::nvSet(properties, "dataport.interface_type", "corba_cdr");
    return properties;
}

RTC::ConnectorProfile dataConnector(RTC::PortBase &out, RTC::PortBase &in,
                                    const char *interfaceType)
{
    RTC::ConnectorProfile profile;
    profile.name = CORBA::string_dup("wire");
    profile.connector_id = CORBA::string_dup("");
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(out.getPortRef());
    profile.ports[1] = RTC::PortService::_duplicate(in.getPortRef());
    const char *const pairs[][2] = {{"dataport.interface_type", interfaceType},
                                    {"dataport.dataflow_type", "push"},
                                    {"dataport.subscription_type", "flush"},
                                    {"dataport.data_type", "IDL:RTC/TimedLong:1.0"}};
    profile.properties.length(4);
    for (CORBA::ULong i = 0; i < 4; ++i) {
        profile.properties[i].name = CORBA::string_dup(pairs[i][0]);
        profile.properties[i].value <<= pairs[i][1];
    }
    return profile;
}

/// A typed data listener that records the value and adds 100 to it (DATA_CHANGED).
class AddHundred : public RTC::ConnectorDataListenerT<RTC::TimedLong>
{
public:
    ReturnCode operator()(RTC::ConnectorInfo &, RTC::TimedLong &data) override
    {
        seen.push_back(data.data);
        data.data += 100;
        return DATA_CHANGED;
    }
    std::vector<long> seen;
};

/// A data listener that sees marshalled samples only and records their sizes.
class RawSizes : public RTC::ConnectorDataListener
{
public:
    ReturnCode operator()(RTC::ConnectorInfo &, RTC::ByteData &data, const std::string &) override
    {
        sizes.push_back(data.getDataLength());
        return NO_CHANGE;
    }
    std::vector<unsigned long> sizes;
};

class CountConnects : public RTC::ConnectorListener
{
public:
    ReturnCode operator()(RTC::ConnectorInfo &) override
    {
        ++count;
        return INFO_CHANGED;
    }
    int count = 0;
};

class RecordProfile : public RTC::FsmProfileListener
{
public:
    void operator()(const RTC::FsmProfile &) override { ++calls; }
    int calls = 0;
};

class CountNotifyConnect : public RTC::PortConnectListener
{
public:
    void operator()(const char *, RTC::ConnectorProfile &) override { ++count; }
    int count = 0;
};

class RecordSetName : public RTC::ConfigurationSetNameListener
{
public:
    void operator()(const char *config_set_name) override { names.push_back(config_set_name); }
    std::vector<std::string> names;
};

RTC::TimedLong timedLong(long value)
{
    RTC::TimedLong sample;
    sample.tm.sec = 0;
    sample.tm.nsec = 0;
    sample.data = value;
    return sample;
}

RTC::ByteData marshalled(const RTC::TimedLong &sample)
{
    cdrMemoryStream stream;
    stream.setByteSwapFlag(true);
    sample >>= stream;
    return RTC::ByteData(static_cast<const unsigned char *>(stream.bufPtr()),
                         static_cast<unsigned long>(stream.bufSize()));
}

} // namespace

class TestSdkPorts : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cleanupTestCase();
    void callbacksAtTheirMoments();
    void underflowSuppliesData();
    void overflowSeesTheSampleThatDidNotFit();
    void portApiAfterConnect();
    void componentActionListenersInOrder();
    void executionContextListeners();
    void portConnectListenersOnConnectAndDisconnect();
    void portCallbacksOnConnectAndDisconnect();
    void connectorObjectsOfPorts();
    void transportObjectsPushOverCorbaCdr_data();
    void transportObjectsPushOverCorbaCdr();
    void transportObjectsPullOverCorbaCdr();
    void transportsRegisterInTheirFactories();
    void unavailableTransportObjectsRefuse();
    void sdoServiceProvidersListed();
    void portAdminByName();
    void unsupportedInterfaceTypeRefused_data();
    void unsupportedInterfaceTypeRefused();
    void userSerializerRefusedByTypedPorts();
    void outPortStatusAndLatestValue();
    void componentPortRegistrationAndProfile();
    void corbaPortConnectionLimit();
    void listenerHoldersCallInOrder();
    void configAdminChangesAndUnbinding();
    void factoryNumbersInstances();
    void nullBufferKeepsTheLatest();
    void loggerWriteAndCompParam();
    void directConnectorsAndPortBase();

private:
    QString logText();
    RTC::ReturnCode_t connectWire(const char *interfaceType = "corba_cdr");

    RTC::Manager *m_manager = nullptr;
    QTemporaryDir m_logDir;
    PortsWriter *m_writer = nullptr;
    PortsReader *m_reader = nullptr;
    std::string m_connectorId;
};

void TestSdkPorts::initTestCase()
{
    QVERIFY(m_logDir.isValid());
    const QByteArray logFile = "logger.file_name:" + m_logDir.filePath("ports.log").toUtf8();
    m_manager = SdkTest::startInProcessManager("tst_sdkports", {logFile});
    QVERIFY(m_manager != nullptr);
    coil::Properties writer(writerSpec), reader(readerSpec);
    QVERIFY(m_manager->registerFactory(writer, RTC::Create<PortsWriter>, RTC::Delete<PortsWriter>));
    QVERIFY(m_manager->registerFactory(reader, RTC::Create<PortsReader>, RTC::Delete<PortsReader>));
}

void TestSdkPorts::init()
{
    eventLog().clear();
    m_writer = dynamic_cast<PortsWriter *>(m_manager->createComponent("PortsWriter"));
    m_reader = dynamic_cast<PortsReader *>(m_manager->createComponent("PortsReader"));
    QVERIFY(m_writer && m_reader);
}

void TestSdkPorts::cleanup()
{
    if (m_writer)
        m_manager->deleteComponent(m_writer);
    if (m_reader)
        m_manager->deleteComponent(m_reader);
    m_writer = nullptr;
    m_reader = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT(m_manager->getComponents().empty(), 5000);
}

void TestSdkPorts::cleanupTestCase()
{
    QVERIFY(SdkTest::stopInProcessManager(m_manager));
}

QString TestSdkPorts::logText()
{
    QFile file(m_logDir.filePath("ports.log"));
    if (!file.open(QIODevice::ReadOnly))
        return QString();
    return QString::fromUtf8(file.readAll());
}

RTC::ReturnCode_t TestSdkPorts::connectWire(const char *interfaceType)
{
    RTC::ConnectorProfile profile
        = dataConnector(m_writer->outPort(), m_reader->inPort(), interfaceType);
    const RTC::ReturnCode_t result = m_writer->outPort().connect(profile);
    m_connectorId = profile.connector_id.in();
    return result;
}

void TestSdkPorts::callbacksAtTheirMoments()
{
    RecordWrite onWrite;
    TimesTen onWriteConvert;
    RecordRead onRead;
    PlusOne onReadConvert;
    m_writer->outPort().setOnWrite(&onWrite);
    m_writer->outPort().setOnWriteConvert(&onWriteConvert);
    m_reader->inPort().setOnRead(&onRead);
    m_reader->inPort().setOnReadConvert(&onReadConvert);
    QCOMPARE(connectWire(), RTC::RTC_OK);
    eventLog().clear();

    QVERIFY(m_writer->write(3));
    long value = 0;
    QVERIFY(m_reader->read(&value));
    // OnWrite sees the value written, OnWriteConvert's result is what travels, OnRead comes
    // before the read and OnReadConvert's result is what the component gets.
    QCOMPARE(value, 31L);
    QCOMPARE(eventLog().events(),
             (std::vector<std::string> {"write 3", "wconvert 3", "read", "rconvert 30"}));
    QCOMPARE(status(m_reader->inPort().getStatus(0)), status(RTC::DataPortStatus::PORT_OK));

    eventLog().clear();
    QVERIFY(!m_reader->read(&value));
    QCOMPARE(eventLog().events(), (std::vector<std::string> {"read"}));
    QCOMPARE(m_reader->inPort().getStatusList(),
             RTC::DataPortStatusList(1, RTC::DataPortStatus::BUFFER_EMPTY));

    // Callbacks taken away are no longer called.
    m_writer->outPort().setOnWriteConvert(nullptr);
    m_reader->inPort().setOnReadConvert(nullptr);
    eventLog().clear();
    QVERIFY(m_writer->write(4));
    QVERIFY(m_reader->read(&value));
    QCOMPARE(value, 4L);
    QCOMPARE(eventLog().events(), (std::vector<std::string> {"write 4", "read"}));
}

void TestSdkPorts::underflowSuppliesData()
{
    SupplyOnUnderflow onUnderflow;
    QCOMPARE(connectWire(), RTC::RTC_OK);
    long value = 0;
    QVERIFY(!m_reader->read(&value));
    m_reader->inPort().setOnUnderflow(&onUnderflow);
    QVERIFY(m_reader->read(&value));
    QCOMPARE(value, -7L);
    QCOMPARE(eventLog().matching("underflow").size(), 1);
    // A sample that waits is read as it is: no underflow.
    QVERIFY(m_writer->write(5));
    QVERIFY(m_reader->read(&value));
    QCOMPARE(value, 5L);
    QCOMPARE(eventLog().matching("underflow").size(), 1);
}

void TestSdkPorts::overflowSeesTheSampleThatDidNotFit()
{
    RecordOverflow onOverflow;
    m_reader->inPort().setOnOverflow(&onOverflow);
    QCOMPARE(connectWire(), RTC::RTC_OK);
    for (long i = 1; i <= 8; ++i)
        QVERIFY(m_writer->write(i));
    QVERIFY(eventLog().matching("overflow").isEmpty());
    QVERIFY(m_writer->write(9));
    QCOMPARE(eventLog().matching("overflow"), QStringList {"overflow 9"});
    // The oldest sample made room for the new one.
    long value = 0;
    QVERIFY(m_reader->read(&value));
    QCOMPARE(value, 2L);
}

void TestSdkPorts::portApiAfterConnect()
{
    RTC::OutPort<RTC::TimedLong> &out = m_writer->outPort();
    RTC::InPort<RTC::TimedLong> &in = m_reader->inPort();
    const std::string writerName = m_writer->getInstanceName();
    QCOMPARE(std::string(out.getName()), writerName + ".out");
    QCOMPARE(std::string(out.name()), std::string("out"));
    QCOMPARE(std::string(in.getName()), std::string(m_reader->getInstanceName()) + ".in");
    // The same through the base class, as PortAdmin-style code sees ports.
    RTC::PortBase &base = out;
    QCOMPARE(std::string(base.getPortProfile().name), writerName + ".out");
    QCOMPARE(std::string(base.getProfile().name), writerName + ".out");
    QVERIFY(!CORBA::is_nil(base.getPortRef()));
    RTC::RTObject_var owner = m_writer->getObjRef();
    QVERIFY(owner->_is_equivalent(base.getPortProfile().owner));
    QVERIFY(out.getConnectorIds().empty());
    // Service ports answer the same.
    RTC::CorbaPort &service = m_writer->servicePort();
    QCOMPARE(std::string(service.getName()), writerName + ".service");
    QCOMPARE(std::string(service.getProfile().name), writerName + ".service");
    RTC::PortProfile_var remoteProfile = service.getPortRef()->get_port_profile();
    QCOMPARE(std::string(remoteProfile->name), writerName + ".service");

    QCOMPARE(connectWire(), RTC::RTC_OK);
    QVERIFY(!m_connectorId.empty());
    for (RTC::DataPortListeners *port : {static_cast<RTC::DataPortListeners *>(&out),
                                         static_cast<RTC::DataPortListeners *>(&in)}) {
        QCOMPARE(port->getConnectorIds(), coil::vstring {m_connectorId});
        QCOMPARE(port->getConnectorNames(), coil::vstring {"wire"});
        RTC::ConnectorInfo info;
        QVERIFY(port->getConnectorProfileById(m_connectorId.c_str(), info));
        QCOMPARE(info.name, std::string("wire"));
        QCOMPARE(info.properties.getProperty("data_type"), std::string("IDL:RTC/TimedLong:1.0"));
        QCOMPARE(info.properties.getProperty("subscription_type"), std::string("flush"));
        QCOMPARE(info.ports.size(), size_t(2));
        QVERIFY(port->getConnectorProfileByName("wire", info));
        QCOMPARE(info.id, m_connectorId);
        QVERIFY(!port->getConnectorProfileByName("nothing", info));
        QVERIFY(!port->getConnectorProfileById("nothing", info));
        QVERIFY(port->isLittleEndian());
    }
    RTC::ConnectorProfileList_var profiles = out.get_connector_profiles();
    QCOMPARE(profiles->length(), CORBA::ULong(1));
    QCOMPARE(out.getPortProfile().connector_profiles.length(), CORBA::ULong(1));

    // Reading by connection name: the one connection, or nothing for a name the port does not have.
    long value = 0;
    QVERIFY(m_writer->write(8));
    QVERIFY(m_reader->inPort().isNew("wire"));
    QVERIFY(!m_reader->inPort().isNew("nothing"));
    QVERIFY(!m_reader->read(&value, "nothing"));
    QVERIFY(m_reader->read(&value, "wire"));
    QCOMPARE(value, 8L);
    QVERIFY(m_reader->inPort().isEmpty("wire"));

    QCOMPARE(out.disconnect(m_connectorId.c_str()), RTC::RTC_OK);
    QVERIFY(out.getConnectorIds().empty());
    QVERIFY(in.getConnectorNames().empty());

    // An InPort takes samples handed to it directly, as OpenRTM-aist's direct connections do.
    RTC::DirectInPortBase<RTC::TimedLong> &direct = in;
    QVERIFY(direct.isEmpty());
    RTC::TimedLong sample;
    sample.tm.sec = 0;
    sample.tm.nsec = 0;
    sample.data = 77;
    direct.write(sample);
    QVERIFY(direct.isNew());
    QVERIFY(m_reader->read(&value));
    QCOMPARE(value, 77L);
}

void TestSdkPorts::componentActionListenersInOrder()
{
    // initialize() ran in createComponent(): the listeners added in the constructor saw it,
    // and the port added in onInitialize.
    const QStringList initialization = eventLog().matching("");
    const QString portName
        = QString::fromStdString(std::string(m_writer->getInstanceName()) + ".out");
    const QString servicePortName
        = QString::fromStdString(std::string(m_writer->getInstanceName()) + ".service");
    QCOMPARE(initialization.mid(0, 5),
             (QStringList {"pre initialize 0", "onInitialize", "add port " + portName,
                           "add port " + servicePortName, "post initialize 0 0"}));

    eventLog().clear();
    QCOMPARE(m_writer->activate(0), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(eventLog().matching("post execute").size() >= 2, 5000);
    QCOMPARE(m_writer->deactivate(0), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(!eventLog().matching("post deactivated").isEmpty(), 5000);
    const QStringList events = eventLog().matching("");
    QCOMPARE(events.mid(0, 6),
             (QStringList {"pre activated 0", "onActivated", "post activated 0 0", "pre execute",
                           "onExecute", "post execute"}));
    QCOMPARE(events.mid(events.size() - 3),
             (QStringList {"pre deactivated", "onDeactivated", "post deactivated"}));

    eventLog().clear();
    m_writer->dropPort();
    QCOMPARE(eventLog().matching("remove port"), QStringList {"remove port " + portName});

    eventLog().clear();
    m_manager->deleteComponent(m_writer);
    m_writer = nullptr;
    QTRY_COMPARE_WITH_TIMEOUT(eventLog().matching("post finalize"),
                              QStringList {"post finalize 0 0"}, 5000);
    QCOMPARE(eventLog().matching("pre finalize"), QStringList {"pre finalize 0"});
}

void TestSdkPorts::executionContextListeners()
{
    // The reader's own context takes the writer in: the writer is attached under a new id.
    eventLog().clear();
    RTC::ExecutionContext_var context = m_reader->getExecutionContext(0);
    QVERIFY(!CORBA::is_nil(context));
    RTC::RTObject_var writer = m_writer->getObjRef();
    QCOMPARE(context->add_component(writer), RTC::RTC_OK);
    const QStringList attached = eventLog().matching("attached ");
    QCOMPARE(attached.size(), 1);
    const RTC::UniqueId id = attached.first().section(' ', 1).toInt();
    QVERIFY(id != 0);
    RTC::ExecutionContext_var known = m_writer->get_context(id);
    QVERIFY(context->_is_equivalent(known));
    QCOMPARE(context->remove_component(writer), RTC::RTC_OK);
    QCOMPARE(eventLog().matching("detached "), QStringList {"detached " + QString::number(id)});
}

void TestSdkPorts::portConnectListenersOnConnectAndDisconnect()
{
    const std::string port = std::string(m_writer->getInstanceName()) + ".out";
    eventLog().clear();
    QCOMPARE(connectWire(), RTC::RTC_OK);
    // The writer's port is the first of the connector: it publishes, passes the profile on to
    // the reader's port, then subscribes.
    QCOMPARE(eventLog().matching("port "),
             (QStringList {QString::fromStdString("port ON_NOTIFY_CONNECT " + port),
                           QString::fromStdString("port ON_PUBLISH_INTERFACES " + port + " 0"),
                           QString::fromStdString("port ON_CONNECT_NEXTPORT " + port + " 0"),
                           QString::fromStdString("port ON_SUBSCRIBE_INTERFACES " + port + " 0"),
                           QString::fromStdString("port ON_CONNECTED " + port + " 0")}));
    eventLog().clear();
    QCOMPARE(m_reader->inPort().disconnect(m_connectorId.c_str()), RTC::RTC_OK);
    QCOMPARE(eventLog().matching("port "),
             (QStringList {QString::fromStdString("port ON_NOTIFY_DISCONNECT " + port),
                           QString::fromStdString("port ON_UNSUBSCRIBE_INTERFACES " + port),
                           QString::fromStdString("port ON_DISCONNECT_NEXT " + port + " 0"),
                           QString::fromStdString("port ON_DISCONNECTED " + port + " 0")}));
}

void TestSdkPorts::connectorObjectsOfPorts()
{
    RTC::OutPort<RTC::TimedLong> &out = m_writer->outPort();
    RTC::InPort<RTC::TimedLong> &in = m_reader->inPort();
    QVERIFY(out.connectors().empty());
    QCOMPARE(connectWire(), RTC::RTC_OK);
    QCOMPARE(out.connectors().size(), size_t(1));
    QCOMPARE(in.connectors().size(), size_t(1));
    RTC::OutPortConnector *sending = out.getConnectorByName("wire");
    RTC::InPortConnector *receiving = in.getConnectorById(m_connectorId.c_str());
    QVERIFY(sending && receiving);
    QCOMPARE(out.getConnectorById(m_connectorId.c_str()), sending);
    QVERIFY(!in.getConnectorByName("nothing"));
    QCOMPARE(std::string(sending->id()), m_connectorId);
    QCOMPARE(std::string(receiving->name()), std::string("wire"));
    QCOMPARE(receiving->profile().properties.getProperty("data_type"),
             std::string("IDL:RTC/TimedLong:1.0"));
    QVERIFY(receiving->isLittleEndian());

    // A sample written by the port is read through the connector, one written through the
    // connector is read by the port.
    QVERIFY(m_writer->write(12));
    BytesStream stream;
    QCOMPARE(status(receiving->read(&stream)), status(RTC::DataPortStatus::PORT_OK));
    QCOMPARE(unmarshalled(stream.m_bytes), 12L);
    QCOMPARE(status(receiving->read(&stream)), status(RTC::DataPortStatus::BUFFER_EMPTY));
    BytesStream thirteen(marshalled(13));
    QCOMPARE(status(sending->write(&thirteen)), status(RTC::DataPortStatus::PORT_OK));
    long value = 0;
    QVERIFY(m_reader->read(&value));
    QCOMPARE(value, 13L);
    QVERIFY(receiving->getBuffer() == nullptr);

    QCOMPARE(status(sending->disconnect()), status(RTC::DataPortStatus::PORT_OK));
    QVERIFY(out.connectors().empty());
    QVERIFY(in.connectors().empty());
}

void TestSdkPorts::transportObjectsPushOverCorbaCdr_data()
{
    QTest::addColumn<QByteArray>("subscription");
    QTest::newRow("flush") << QByteArray("flush");
    QTest::newRow("new") << QByteArray("new");
    QTest::newRow("periodic") << QByteArray("periodic");
}

void TestSdkPorts::transportObjectsPushOverCorbaCdr()
{
    QFETCH(QByteArray, subscription);
    RTC::ConnectorInfo info = framedInfo(subscription.constData());
    auto *provider = new RTC::InPortCorbaCdrProvider;
    RTC::InPortPushConnector receiving(info, provider, nullptr);
    // The provider offers its InPortCdr object; the consumer finds it in the same properties.
    SDOPackage::NVList properties = corbaCdrProperties();
    QVERIFY(provider->publishInterface(properties));
    QVERIFY(!Runtime::nvString(properties, "dataport.corba_cdr.inport_ior").empty());
    auto *consumer = new RTC::InPortCorbaCdrConsumer;
    QVERIFY(consumer->subscribeInterface(properties));
    RTC::OutPortPushConnector sending(info, consumer, nullptr);
    BytesStream sample(marshalled(21));
    // An inactive publisher sends nothing.
    QCOMPARE(status(sending.write(&sample)), status(RTC::DataPortStatus::PRECONDITION_NOT_MET));
    sending.activate();
    QCOMPARE(status(sending.write(&sample)), status(RTC::DataPortStatus::PORT_OK));
    BytesStream received;
    // Once read, a sample is gone: the condition remembers that it came.
    bool arrived = false;
    QTRY_VERIFY_WITH_TIMEOUT(
        arrived || (arrived = receiving.read(&received) == RTC::DataPortStatus::PORT_OK), 5000);
    QCOMPARE(unmarshalled(received.m_bytes), 21L);
    QCOMPARE(status(receiving.read(&received)), status(RTC::DataPortStatus::BUFFER_EMPTY));
    QCOMPARE(status(sending.disconnect()), status(RTC::DataPortStatus::PORT_OK));
}

void TestSdkPorts::transportObjectsPullOverCorbaCdr()
{
    RTC::ConnectorInfo info = framedInfo("flush");
    auto *provider = new RTC::OutPortCorbaCdrProvider;
    RTC::OutPortPullConnector sending(info, provider, nullptr);
    SDOPackage::NVList properties = corbaCdrProperties();
    QVERIFY(provider->publishInterface(properties));
    auto *consumer = new RTC::OutPortCorbaCdrConsumer;
    QVERIFY(consumer->subscribeInterface(properties));
    RTC::InPortPullConnector receiving(info, consumer, nullptr);
    BytesStream received;
    QCOMPARE(status(receiving.read(&received)), status(RTC::DataPortStatus::BUFFER_EMPTY));
    BytesStream sample(marshalled(34));
    QCOMPARE(status(sending.write(&sample)), status(RTC::DataPortStatus::PORT_OK));
    QCOMPARE(status(receiving.read(&received)), status(RTC::DataPortStatus::PORT_OK));
    QCOMPARE(unmarshalled(received.m_bytes), 34L);
}

void TestSdkPorts::transportsRegisterInTheirFactories()
{
    InPortCorbaCdrProviderInit();
    InPortSHMConsumerInit();
    PublisherNewInit();
    CdrRingBufferInit();
    RTC::InPortProvider *provider
        = RTC::InPortProviderFactory::instance().createObject("corba_cdr");
    QVERIFY(dynamic_cast<RTC::InPortCorbaCdrProvider *>(provider));
    RTC::InPortProviderFactory::instance().deleteObject(provider);
    RTC::InPortConsumer *shm = RTC::InPortConsumerFactory::instance().createObject("shared_memory");
    QVERIFY(dynamic_cast<RTC::InPortSHMConsumer *>(shm));
    RTC::InPortConsumerFactory::instance().deleteObject(shm);
    RTC::PublisherBase *publisher = RTC::PublisherFactory::instance().createObject("new");
    QVERIFY(dynamic_cast<RTC::PublisherNew *>(publisher));
    RTC::PublisherFactory::instance().deleteObject(publisher);
    RTC::CdrBufferBase *buffer = RTC::CdrBufferFactory::instance().createObject("ring_buffer");
    QVERIFY(dynamic_cast<RTC::CdrRingBuffer *>(buffer));
    RTC::CdrBufferFactory::instance().deleteObject(buffer);
    QVERIFY(!RTC::PublisherFactory::instance().createObject("nothing"));
}

void TestSdkPorts::unavailableTransportObjectsRefuse()
{
    RTC::ByteData data;
    RTC::InPortSHMConsumer shm;
    QCOMPARE(status(shm.put(data)), status(RTC::DataPortStatus::PORT_ERROR));
    QTRY_VERIFY2_WITH_TIMEOUT(logText().contains("interface type 'shared_memory' is not available"),
                              qPrintable(logText()), 5000);
    RTC::InPortDSConsumer ds;
    QVERIFY(!ds.subscribeInterface(corbaCdrProperties()));
    QTRY_VERIFY2_WITH_TIMEOUT(logText().contains("interface type 'data_service' is not available"),
                              qPrintable(logText()), 5000);
    RTC::SharedMemoryPort memory;
    QCOMPARE(memory.put(), OpenRTM::PORT_ERROR);
    QCOMPARE(memory.string_to_MemorySize("2M"), 2 * 1024 * 1024);
}

void TestSdkPorts::sdoServiceProvidersListed()
{
    CountingSdoService service;
    SDOPackage::ServiceProfile profile;
    profile.id = CORBA::string_dup("counting");
    profile.interface_type = CORBA::string_dup("IDL:RTStudioTests/Counting:1.0");
    QVERIFY(m_writer->addSdoServiceProvider(profile, &service));
    QVERIFY(!m_writer->addSdoServiceProvider(profile, &service));
    RTC::RTObject_var self = m_writer->getObjRef();
    SDOPackage::ServiceProfileList_var listed = self->get_service_profiles();
    QCOMPARE(listed->length(), CORBA::ULong(1));
    QCOMPARE(std::string(listed[0].id), std::string("counting"));
    SDOPackage::SDOService_var reached = self->get_sdo_service("counting");
    SDOPackage::SDOService_var own = service._this();
    QVERIFY(own->_is_equivalent(reached));

    QVERIFY(m_writer->removeSdoServiceProvider("counting"));
    QCOMPARE(service.finalized, 1);
    QVERIFY(!m_writer->removeSdoServiceProvider("counting"));
    listed = self->get_service_profiles();
    QCOMPARE(listed->length(), CORBA::ULong(0));
    PortableServer::POA_var poa = service._default_POA();
    PortableServer::ObjectId_var id = poa->servant_to_id(&service);
    poa->deactivate_object(id);

    // Consumers come from their factory by interface type: an unknown type is refused, saying
    // which.
    QVERIFY(!m_writer->addSdoServiceConsumer(profile));
    QTRY_VERIFY2_WITH_TIMEOUT(logText().contains("interface type 'IDL:RTStudioTests/Counting:1.0'"),
                              qPrintable(logText()), 5000);
    RTC::SdoServiceConsumerFactory::instance().addFactory(
        "IDL:RTStudioTests/Counting:1.0",
        coil::Creator<RTC::SdoServiceConsumerBase, LoggingSdoConsumer>,
        coil::Destructor<RTC::SdoServiceConsumerBase, LoggingSdoConsumer>);
    eventLog().clear();
    QVERIFY(m_writer->addSdoServiceConsumer(profile));
    QVERIFY(m_writer->addSdoServiceConsumer(profile));
    QVERIFY(m_writer->removeSdoServiceConsumer("counting"));
    QVERIFY(!m_writer->removeSdoServiceConsumer("counting"));
    QCOMPARE(eventLog().matching("consumer"),
             (QStringList {"consumer init counting", "consumer reinit counting",
                           "consumer finalize counting"}));
    RTC::SdoServiceConsumerFactory::instance().removeFactory("IDL:RTStudioTests/Counting:1.0");
}

void TestSdkPorts::portAdminByName()
{
    RTC::PortAdmin admin(m_manager->getORB(), m_manager->getPOA());
    RTC::OutPort<RTC::TimedLong> &out = m_writer->outPort();
    QVERIFY(admin.addPort(out));
    QVERIFY(!admin.addPort(out));
    QCOMPARE(admin.getPort(out.getName()), static_cast<RTC::PortBase *>(&out));
    QVERIFY(admin.getPortRef(out.getName())->_is_equivalent(out.getPortRef()));
    QVERIFY(!admin.getPort("nothing"));
    // A port known by reference only.
    RTC::PortService_var in = m_reader->inPort().reference();
    QVERIFY(admin.addPort(in.in()));
    QVERIFY(!admin.getPort(m_reader->inPort().getName()));
    RTC::PortServiceList_var refs = admin.getPortServiceList();
    QCOMPARE(refs->length(), CORBA::ULong(2));
    RTC::PortProfileList profiles = admin.getPortProfileList();
    QCOMPARE(profiles.length(), CORBA::ULong(2));
    QCOMPARE(std::string(profiles[0].name), std::string(out.getName()));

    QCOMPARE(connectWire(), RTC::RTC_OK);
    QVERIFY(admin.removePort(out));
    QVERIFY(!admin.getPort(out.getName()));
    QVERIFY(out.getConnectorIds().empty()); // removing disconnects
    admin.deletePortByName(m_reader->inPort().getName());
    refs = admin.getPortServiceList();
    QCOMPARE(refs->length(), CORBA::ULong(0));
}

void TestSdkPorts::portCallbacksOnConnectAndDisconnect()
{
    RecordConnection publish("publish"), subscribe("subscribe"), connected("connected"),
        unsubscribe("unsubscribe"), disconnected("disconnected");
    RTC::PortBase &port = m_reader->inPort();
    port.setOnPublishInterfaces(&publish);
    port.setOnSubscribeInterfaces(&subscribe);
    port.setOnConnected(&connected);
    port.setOnUnsubscribeInterfaces(&unsubscribe);
    port.setOnDisconnected(&disconnected);
    eventLog().clear();
    QCOMPARE(connectWire(), RTC::RTC_OK);
    QCOMPARE(eventLog().matching("callback"),
             (QStringList {"callback publish wire", "callback subscribe wire",
                           "callback connected wire"}));
    eventLog().clear();
    QCOMPARE(m_writer->outPort().disconnect(m_connectorId.c_str()), RTC::RTC_OK);
    QCOMPARE(eventLog().matching("callback"),
             (QStringList {"callback unsubscribe wire", "callback disconnected wire"}));
    // Taken away, they are not called any more.
    port.setOnConnected(nullptr);
    eventLog().clear();
    QCOMPARE(connectWire(), RTC::RTC_OK);
    QCOMPARE(eventLog().matching("callback"),
             (QStringList {"callback publish wire", "callback subscribe wire"}));
    port.setOnPublishInterfaces(nullptr);
    port.setOnSubscribeInterfaces(nullptr);
    port.setOnUnsubscribeInterfaces(nullptr);
    port.setOnDisconnected(nullptr);
}

void TestSdkPorts::unsupportedInterfaceTypeRefused_data()
{
    QTest::addColumn<QByteArray>("interfaceType");
    QTest::newRow("shared memory") << QByteArray("shared_memory");
    QTest::newRow("data service") << QByteArray("data_service");
}

void TestSdkPorts::unsupportedInterfaceTypeRefused()
{
    QFETCH(QByteArray, interfaceType);
    QCOMPARE(connectWire(interfaceType.constData()), RTC::BAD_PARAMETER);
    QVERIFY(m_writer->outPort().getConnectorIds().empty());
    QVERIFY(m_reader->inPort().getConnectorIds().empty());
    RTC::ConnectorProfileList_var left = m_writer->outPort().get_connector_profiles();
    QCOMPARE(left->length(), CORBA::ULong(0));
    const QString expected
        = QString("interface type '%1' is not available").arg(QString::fromUtf8(interfaceType));
    QTRY_VERIFY2_WITH_TIMEOUT(logText().contains(expected), qPrintable(logText()), 5000);
    QVERIFY(logText().contains(QString::fromUtf8(m_writer->outPort().getName())));
}

void TestSdkPorts::userSerializerRefusedByTypedPorts()
{
    // Typed C++ ports read and write plain CDR of their type: a connection naming a user serializer
    // (OpenRTM-aist-Python's, for Python InPorts) for either side is refused, naming it.
    for (const char *side : {"dataport.inport.marshaling_type", "dataport.outport.marshaling_type"}) {
        RTC::ConnectorProfile profile = dataConnector(m_writer->outPort(), m_reader->inPort(), "corba_cdr");
        profile.properties.length(profile.properties.length() + 1);
        profile.properties[profile.properties.length() - 1].name = CORBA::string_dup(side);
        profile.properties[profile.properties.length() - 1].value <<= "cdr:RTC/TimedShort:RTC/TimedLong";
        QCOMPARE(m_writer->outPort().connect(profile), RTC::BAD_PARAMETER);
        QVERIFY(m_writer->outPort().getConnectorIds().empty());
        QVERIFY(m_reader->inPort().getConnectorIds().empty());
    }
    QTRY_VERIFY2_WITH_TIMEOUT(logText().contains("no serializer 'cdr:RTC/TimedShort:RTC/TimedLong'"), qPrintable(logText()), 5000);
}

void TestSdkPorts::outPortStatusAndLatestValue()
{
    RTC::OutPort<RTC::TimedLong> &out = m_writer->outPort();
    QVERIFY(out.getStatusList().empty());
    QVERIFY(out.isEmpty());
    QCOMPARE(connectWire(), RTC::RTC_OK);
    QVERIFY(m_writer->write(12));
    // One status per connection, in the order of the connectors; an index beyond is an error.
    QCOMPARE(out.getStatusList(), RTC::DataPortStatusList(1, RTC::DataPortStatus::PORT_OK));
    QCOMPARE(status(out.getStatus(0)), status(RTC::DataPortStatus::PORT_OK));
    QCOMPARE(status(out.getStatus(3)), status(RTC::DataPortStatus::PORT_ERROR));
    // The latest value, for a reader in the process.
    QVERIFY(out.isNew());
    QVERIFY(!out.isEmpty());
    RTC::TimedLong latest = timedLong(0);
    out.read(latest);
    QCOMPARE(long(latest.data), 12L);
    QVERIFY(!out.isNew());
    QVERIFY(out.isEmpty());
    QVERIFY(out.getListeners() != nullptr);
}

void TestSdkPorts::componentPortRegistrationAndProfile()
{
    QCOMPARE(std::string(m_writer->getDescription()), std::string("writer"));
    QCOMPARE(std::string(m_writer->getVersion()), std::string("1.0.0"));
    QCOMPARE(std::string(m_writer->getVendor()), std::string("RTStudioTests"));
    coil::Properties names;
    names.setProperty("naming.names", "a.rtc, b/c.rtc");
    m_writer->setProperties(names);
    QCOMPARE(m_writer->getNamingNames(), (std::vector<std::string>{"a.rtc", "b/c.rtc"}));
    QCOMPARE(m_writer->getOutPorts().size(), size_t(1));
    QCOMPARE(m_reader->getInPorts().size(), size_t(1));
    QVERIFY(m_writer->getInPorts().empty());

    // onInitialize() run again by a peer's on_initialize(): its ports are listed once, as OpenRTM-aist's
    // port admin refuses a name it lists; adding a listed port again says so.
    RTC::PortServiceList_var before = m_writer->get_ports();
    RTC::RTObject_var writer = m_writer->getObjRef();
    QCOMPARE(writer->on_initialize(), RTC::RTC_OK);
    RTC::PortServiceList_var reinitialized = m_writer->get_ports();
    QCOMPARE(reinitialized->length(), before->length());
    QCOMPARE(m_writer->getOutPorts().size(), size_t(1));
    QVERIFY(!m_reader->addInPort("in", m_reader->inPort()));
    QCOMPARE(m_reader->getInPorts().size(), size_t(1));

    // Another object's port listed among the writer's and taken away again by its reference.
    RTC::PortService_var readerPort = RTC::PortService::_duplicate(m_reader->inPort().getPortRef());
    m_writer->registerPort(readerPort.in());
    RTC::PortServiceList_var with = m_writer->get_ports();
    QCOMPARE(with->length(), before->length() + 1);
    m_writer->deletePort(readerPort.in());
    RTC::PortServiceList_var without = m_writer->get_ports();
    QCOMPARE(without->length(), before->length());

    // A port of its own, removed by name: the REMOVE_PORT listener hears of it.
    eventLog().clear();
    m_writer->deletePortByName((std::string(m_writer->getInstanceName()) + ".out").c_str());
    RTC::PortServiceList_var after = m_writer->get_ports();
    QCOMPARE(after->length(), before->length() - 1);
    QVERIFY(m_writer->getOutPorts().empty());
    QCOMPARE(eventLog().matching("remove port").size(), 1);
}

void TestSdkPorts::corbaPortConnectionLimit()
{
    RTC::CorbaPort &port = m_writer->servicePort();
    coil::Properties limit;
    limit.setProperty("connection_limit", "0");
    port.init(limit);
    RTC::ConnectorProfile profile;
    profile.name = CORBA::string_dup("alone");
    profile.connector_id = CORBA::string_dup("");
    profile.ports.length(1);
    profile.ports[0] = RTC::PortService::_duplicate(port.getPortRef());
    QCOMPARE(port.connect(profile), RTC::PRECONDITION_NOT_MET);
    limit.setProperty("connection_limit", "-1");
    port.init(limit);
    QCOMPARE(port.connect(profile), RTC::RTC_OK);
    QCOMPARE(port.disconnect(profile.connector_id), RTC::RTC_OK);
}

void TestSdkPorts::listenerHoldersCallInOrder()
{
    RTC::ConnectorInfo info;
    info.properties.setProperty("serializer.cdr.endian", "little");
    RTC::ConnectorDataListenerHolderT<RTC::TimedLong> holder;
    auto *typed = new AddHundred;
    auto *raw = new RawSizes;
    holder.addListener(typed, true);
    holder.addListener(raw, true);
    QCOMPARE(holder.size(), size_t(2));
    RTC::ByteData bytes = marshalled(timedLong(5));
    const unsigned long length = bytes.getDataLength();
    QCOMPARE(int(holder.notify(info, bytes, "cdr")), int(RTC::ConnectorListenerStatus::DATA_CHANGED));
    QCOMPARE(typed->seen, std::vector<long>{5});
    QCOMPARE(raw->sizes, std::vector<unsigned long>{length});
    // What the typed listener changed travels on in the marshalled sample.
    cdrMemoryStream in(bytes.getBuffer(), bytes.getDataLength());
    in.setByteSwapFlag(true);
    RTC::TimedLong changed = timedLong(0);
    changed <<= in;
    QCOMPARE(long(changed.data), 105L);
    // A typed sample reaches the typed listener as it is, the others marshalled.
    RTC::TimedLong sample = timedLong(7);
    holder.notifyOut(info, sample);
    QCOMPARE(typed->seen, (std::vector<long>{5, 7}));
    QCOMPARE(raw->sizes.size(), size_t(2));
    holder.removeListener(raw);
    QCOMPARE(holder.size(), size_t(1));

    RTC::ConnectorListenersT<RTC::TimedLong> listeners;
    auto *connects = new CountConnects;
    QVERIFY(listeners.addListener(RTC::ConnectorListenerType::ON_CONNECT, connects));
    CountConnects outOfRange;
    QVERIFY(!listeners.addListener(RTC::ConnectorListenerType::CONNECTOR_LISTENER_NUM, &outOfRange, false));
    QCOMPARE(int(listeners.notify(RTC::ConnectorListenerType::ON_CONNECT, info)),
             int(RTC::ConnectorListenerStatus::INFO_CHANGED));
    QCOMPARE(connects->count, 1);
    QCOMPARE(int(listeners.notify(RTC::ConnectorListenerType::ON_DISCONNECT, info)),
             int(RTC::ConnectorListenerStatus::NO_CHANGE));

    RTC::FsmActionListeners fsm;
    RecordProfile profileListener;
    QVERIFY(fsm.addListener(RTC::FsmProfileListenerType::ADD_FSM_STATE, &profileListener, false));
    RTC::FsmProfile fsmProfile;
    QVERIFY(fsm.notify(RTC::FsmProfileListenerType::ADD_FSM_STATE, fsmProfile));
    QVERIFY(fsm.notify(RTC::FsmProfileListenerType::SET_FSM_PROFILE, fsmProfile));
    QVERIFY(!fsm.notify(RTC::FsmProfileListenerType::FSM_PROFILE_LISTENER_NUM, fsmProfile));
    QCOMPARE(profileListener.calls, 1);
    QVERIFY(fsm.removeListener(RTC::FsmProfileListenerType::ADD_FSM_STATE, &profileListener));
    QVERIFY(fsm.notify(RTC::FsmProfileListenerType::ADD_FSM_STATE, fsmProfile));
    QCOMPARE(profileListener.calls, 1);
    // The component keeps its own, for what serves its FSM.
    m_writer->addFsmProfileListener(RTC::FsmProfileListenerType::ADD_FSM_STATE, &profileListener, false);
    m_writer->removeFsmProfileListener(RTC::FsmProfileListenerType::ADD_FSM_STATE, &profileListener);
}

void TestSdkPorts::configAdminChangesAndUnbinding()
{
    RTC::ConfigAdmin &config = m_writer->getConfigService();
    long gain = 0;
    QVERIFY(config.bindParameter("gain", gain, "1"));
    QCOMPARE(gain, 1L);
    RecordSetName updated;
    config.setOnUpdate(&updated);

    coil::Properties set("default");
    set.setProperty("gain", "2");
    QVERIFY(config.setConfigurationSetValues(set));
    QVERIFY(config.activateConfigurationSet("default"));
    config.update();
    QCOMPARE(gain, 2L);
    QCOMPARE(config.changedParameters(), coil::vstring{"gain"});
    QCOMPARE(updated.names, std::vector<std::string>{"default"});
    bool listed = false;
    for (coil::Properties *node : config.getConfigurationSets())
        listed = listed || node->getName() == std::string("default");
    QVERIFY(listed);

    // Unbound: the variable keeps its value whatever the set says.
    QVERIFY(config.unbindParameter("gain"));
    QVERIFY(!config.unbindParameter("gain"));
    QVERIFY(!config.isExist("gain"));
    set.setProperty("gain", "3");
    QVERIFY(config.setConfigurationSetValues(set));
    QVERIFY(config.activateConfigurationSet("default"));
    config.update();
    QCOMPARE(gain, 2L);
    QVERIFY(config.changedParameters().empty());
    config.removeConfigurationSetNameListener(RTC::ConfigurationSetNameListenerType::ON_UPDATE_CONFIG_SET, &updated);

    // A parameter object of its own tells the admin set with setCallback of each change.
    long direct = 0;
    RTC::Config<long> parameter("direct", direct, "4");
    QVERIFY(parameter.update("6"));
    QCOMPARE(direct, 6L);
    QVERIFY(!parameter.update("not a number"));
    QCOMPARE(direct, 4L);
}

void TestSdkPorts::factoryNumbersInstances()
{
    coil::Properties profile(readerSpec);
    RTC::FactoryCXX factory(profile, RTC::Create<PortsReader>, RTC::Delete<PortsReader>);
    QCOMPARE(factory.number(), -1);
    RTC::RTObject_impl *first = factory.create(m_manager);
    RTC::RTObject_impl *second = factory.create(m_manager);
    QVERIFY(first && second);
    QCOMPARE(std::string(first->getInstanceName()), std::string("PortsReader0"));
    QCOMPARE(std::string(second->getInstanceName()), std::string("PortsReader1"));
    QCOMPARE(factory.number(), 1);
    QCOMPARE(factory.profile().getProperty("type_name"), std::string("PortsReader"));
    factory.destroy(first);
    factory.destroy(second);
    QCOMPARE(factory.number(), -1);
}

void TestSdkPorts::nullBufferKeepsTheLatest()
{
    RTC::NullBuffer<long> buffer;
    long value = 0;
    QVERIFY(buffer.empty());
    QCOMPARE(int(buffer.read(value)), int(RTC::BufferStatus::EMPTY));
    QCOMPARE(int(buffer.write(1)), int(RTC::BufferStatus::OK));
    QCOMPARE(int(buffer.write(2)), int(RTC::BufferStatus::OK));
    QVERIFY(!buffer.full());
    QCOMPARE(int(buffer.read(value)), int(RTC::BufferStatus::OK));
    QCOMPARE(value, 2L);
    QCOMPARE(int(buffer.read(value)), int(RTC::BufferStatus::OK)); // read again: still the latest
    QCOMPARE(buffer.length(), size_t(1));
    QCOMPARE(int(buffer.length(4)), int(RTC::BufferStatus::NOT_SUPPORTED));
    QCOMPARE(int(buffer.reset()), int(RTC::BufferStatus::OK));
    QVERIFY(buffer.empty());
}

void TestSdkPorts::loggerWriteAndCompParam()
{
    RTC::Logger rtclog("holders");
    rtclog.write(RTC::Logger::RTL_ERROR, std::string("one line from write"));
    coil::Properties prop;
    prop.setProperty("color", "blue");
    rtclog.write(RTC::Logger::RTL_ERROR, prop);
    QTRY_VERIFY_WITH_TIMEOUT(logText().contains("one line from write") && logText().contains("color: blue"), 5000);

    RTM::CompParam full("RTC:AIST:example:ConsoleIn:C++:1.0?instance_name=c1");
    QCOMPARE(full.vendor(), std::string("AIST"));
    QCOMPARE(full.category(), std::string("example"));
    QCOMPARE(full.impl_id(), std::string("ConsoleIn"));
    QCOMPARE(full.language(), std::string("C++"));
    QCOMPARE(full.version(), std::string("1.0"));
    RTM::CompParam plain("ConsoleOut?exec_cxt.periodic.rate=10");
    QCOMPARE(plain.impl_id(), std::string("ConsoleOut"));
    QCOMPARE(plain.language(), std::string("C++"));
    QVERIFY(plain.vendor().empty());
}

void TestSdkPorts::directConnectorsAndPortBase()
{
    QCOMPARE(connectWire(), RTC::RTC_OK);
    RTC::InPortConnector *incoming = m_reader->inPort().connectors().front();
    RTC::OutPortConnector *outgoing = m_writer->outPort().connectors().front();
    // The reader's connection takes the writer's latest value itself.
    RTC::TimedLong value = timedLong(0);
    QVERIFY(!incoming->getDirectData(value));
    QVERIFY(!incoming->setOutPort(nullptr));
    QVERIFY(incoming->setOutPort(&m_writer->outPort()));
    QVERIFY(m_writer->write(21));
    QVERIFY(incoming->getDirectData(value));
    QCOMPARE(long(value.data), 21L);
    RTC::TimedDouble other;
    QVERIFY(!incoming->getDirectData(other)); // not a sender of that type
    QVERIFY(!outgoing->pullDirectMode());
    outgoing->setPullDirectMode();
    QVERIFY(outgoing->pullDirectMode());
    QVERIFY(outgoing->setInPort(&m_reader->inPort()));
    QVERIFY(!outgoing->setInPort(nullptr));

    // PortBase: the typed OutPort is a direct sender, a service port is not.
    QVERIFY(m_writer->outPort().getDirectPort() != nullptr);
    QVERIFY(m_writer->servicePort().getDirectPort() == nullptr);
    RTC::PortBase &service = m_writer->servicePort();
    RTC::PortService_ptr own = service.getPortRef();
    service.setPortRef(RTC::PortService::_nil()); // refused: the port keeps its own
    QVERIFY(service.getPortRef() == own);
    service.setName("renamed.service");
    QCOMPARE(std::string(service.getName()), std::string("renamed.service"));

    // A listener holder of the caller's hears the port's connect steps.
    RTC::PortConnectListeners listeners;
    CountNotifyConnect counter;
    listeners.addListener(RTC::PortConnectListenerType::ON_NOTIFY_CONNECT, &counter, false);
    service.setPortConnectListenerHolder(&listeners);
    RTC::ConnectorProfile profile;
    profile.name = CORBA::string_dup("alone");
    profile.connector_id = CORBA::string_dup("");
    profile.ports.length(1);
    profile.ports[0] = RTC::PortService::_duplicate(service.getPortRef());
    QCOMPARE(service.connect(profile), RTC::RTC_OK);
    QCOMPARE(counter.count, 1);
    QCOMPARE(service.disconnect(profile.connector_id), RTC::RTC_OK);
    service.setPortConnectListenerHolder(nullptr);
}

QTEST_GUILESS_MAIN(TestSdkPorts)
#include "tst_sdkports.moc"
