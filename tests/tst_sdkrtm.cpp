// SPDX-License-Identifier: MIT
// The component SDK in one process: components written against OpenRTM-aist's C++ API are
// created by RTC::Manager, connected through their ports, configured through SDO and called
// through service ports, as OpenRTM-aist would do it.
#include "sdkinprocess.h"

#include <rtm/CorbaConsumer.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>
#include <rtm/LocalServiceAdmin.h>
#include <rtm/Manager.h>
#include <rtm/SdoConfiguration.h>
#include <rtm/SdoOrganization.h>
#include <rtm/SdoServiceAdmin.h>
#include <rtm/SdoServiceConsumerBase.h>
#include <rtm/SdoServiceProviderBase.h>

#include <SimpleService.hh>

#include <corbautil.h>
#include <managerconfig.h>

#include "loggersink.h"

#include <rtm/SystemLogger.h>

#include <QtTest>

#include <atomic>
#include <istream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

// What OpenRTP-style generated components bring for vector parameters: a stream extraction that
// coil::stringTo finds by argument-dependent lookup.
namespace std {
template <typename T>
std::istream &operator>>(std::istream &in, std::vector<T> &values)
{
    std::string all;
    std::getline(in, all);
    std::vector<T> read;
    std::istringstream items(all);
    for (std::string item; std::getline(items, item, ',');) {
        std::istringstream one(item);
        T value;
        if (!(one >> value)) {
            in.setstate(std::ios::failbit);
            return in;
        }
        read.push_back(value);
    }
    values = read;
    return in;
}
} // namespace std

namespace {

const char *const sourceSpec[] = {"implementation_id", "SdkSource", "type_name", "SdkSource",
                                  "description", "counter", "version", "1.0.0", "vendor", "RTStudioTests",
                                  "category", "test", "activity_type", "PERIODIC", "kind", "DataFlowComponent",
                                  "max_instance", "0", "language", "C++", "lang_type", "compile",
                                  "conf.default.step", "1", "conf.default.gains", "0.5,1.5",
                                  "exec_cxt.periodic.rate", "200", ""};

class SdkSource : public RTC::DataFlowComponentBase
{
public:
    explicit SdkSource(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_outOut("out", m_out)
    {
    }
    RTC::ReturnCode_t onInitialize() override
    {
        // IDL structs leave their numbers uninitialised, as in OpenRTM-aist: the count starts here.
        m_out.data = 0;
        addOutPort("out", m_outOut);
        if (!bindParameter("step", m_step, "1") || !bindParameter("gains", m_gains, "0.5,1.5"))
            return RTC::RTC_ERROR;
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        {
            std::lock_guard<std::mutex> lock(mutex);
            seenStep = m_step;
            seenGains = m_gains;
        }
        m_out.data += m_step;
        setTimestamp(m_out);
        m_outOut.write();
        return RTC::RTC_OK;
    }

    std::mutex mutex;
    int seenStep = 0;
    std::vector<double> seenGains;

private:
    int m_step = 0;
    std::vector<double> m_gains;
    RTC::TimedLong m_out;
    RTC::OutPort<RTC::TimedLong> m_outOut;
};

class CountingListener : public RTC::ConnectorDataListenerT<RTC::TimedLong>
{
    USE_CONNLISTENER_STATUS;

public:
    explicit CountingListener(std::atomic<int> *count, std::atomic<long> *last)
        : m_count(count)
        , m_last(last)
    {
    }
    ReturnCode operator()(RTC::ConnectorInfo &, RTC::TimedLong &data) override
    {
        ++*m_count;
        *m_last = data.data;
        return NO_CHANGE;
    }

private:
    std::atomic<int> *m_count;
    std::atomic<long> *m_last;
};

/// Takes samples in their CDR form, as OpenRTM-aist's untyped data listeners do.
class RawListener : public RTC::ConnectorDataListener
{
    USE_CONNLISTENER_STATUS;

public:
    explicit RawListener(std::atomic<long> *last) : m_last(last) {}
    ReturnCode operator()(RTC::ConnectorInfo &info, RTC::ByteData &data, const std::string &marshalingtype) override
    {
        if (marshalingtype != "cdr")
            return NO_CHANGE;
        cdrMemoryStream stream(data.getBuffer(), data.getDataLength());
        stream.setByteSwapFlag(info.properties.getProperty("serializer.cdr.endian") == "little");
        RTC::TimedLong sample;
        sample <<= stream;
        *m_last = sample.data;
        return NO_CHANGE;
    }

private:
    std::atomic<long> *m_last;
};

class ConnectListener : public RTC::ConnectorListener
{
    USE_CONNLISTENER_STATUS;

public:
    explicit ConnectListener(std::atomic<int> *count) : m_count(count) {}
    ReturnCode operator()(RTC::ConnectorInfo &info) override
    {
        if (!info.id.empty() && info.properties.getProperty("dataflow_type") == "push")
            ++*m_count;
        return NO_CHANGE;
    }

private:
    std::atomic<int> *m_count;
};

const char *const sinkSpec[] = {"implementation_id", "SdkSink", "type_name", "SdkSink", "version", "1.0.0",
                                "vendor", "RTStudioTests", "category", "test", "language", "C++",
                                "exec_cxt.periodic.rate", "200", ""};

class SdkSink : public RTC::DataFlowComponentBase
{
public:
    explicit SdkSink(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_inIn("in", m_in)
    {
    }
    RTC::ReturnCode_t onInitialize() override
    {
        addInPort("in", m_inIn);
        m_inIn.addConnectorDataListener(RTC::ConnectorDataListenerType::ON_BUFFER_WRITE,
                                        new CountingListener(&bufferWrites, &lastWritten));
        m_inIn.addConnectorListener(RTC::ON_CONNECT, new ConnectListener(&connects));
        m_inIn.addConnectorDataListener(RTC::ON_RECEIVED, new RawListener(&lastRaw));
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        while (m_inIn.isNew()) {
            m_inIn.read();
            ++received;
            lastRead = m_in.data;
        }
        return RTC::RTC_OK;
    }

    std::atomic<int> received{0};
    std::atomic<long> lastRead{0};
    std::atomic<int> bufferWrites{0};
    std::atomic<long> lastWritten{0};
    std::atomic<int> connects{0};
    std::atomic<long> lastRaw{0};

private:
    RTC::TimedLong m_in;
    RTC::InPort<RTC::TimedLong> m_inIn;
};

class EchoService : public virtual POA_SimpleService::MyService
{
public:
    char *echo(const char *msg) override { return CORBA::string_dup((std::string("echo:") + msg).c_str()); }
    SimpleService::EchoList *get_echo_history() override { return new SimpleService::EchoList; }
    void set_value(CORBA::Float value) override { m_value = value; }
    CORBA::Float get_value() override { return m_value; }
    SimpleService::ValueList *get_value_history() override { return new SimpleService::ValueList; }

private:
    CORBA::Float m_value = 0;
};

const char *const providerSpec[] = {"implementation_id", "SdkProvider", "type_name", "SdkProvider",
                                    "version", "1.0.0", "vendor", "RTStudioTests", "category", "test",
                                    "language", "C++", ""};

class SdkProvider : public RTC::DataFlowComponentBase
{
public:
    explicit SdkProvider(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_servicePort("MyService")
    {
    }
    RTC::ReturnCode_t onInitialize() override
    {
        m_servicePort.registerProvider("myservice", "SimpleService::MyService", m_service);
        addPort(m_servicePort);
        return RTC::RTC_OK;
    }

private:
    RTC::CorbaPort m_servicePort;
    EchoService m_service;
};

const char *const consumerSpec[] = {"implementation_id", "SdkConsumer", "type_name", "SdkConsumer",
                                    "version", "1.0.0", "vendor", "RTStudioTests", "category", "test",
                                    "language", "C++", ""};

class SdkConsumer : public RTC::DataFlowComponentBase
{
public:
    explicit SdkConsumer(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_servicePort("MyService")
    {
    }
    RTC::ReturnCode_t onInitialize() override
    {
        m_servicePort.registerConsumer("myservice", "SimpleService::MyService", m_service);
        addPort(m_servicePort);
        return RTC::RTC_OK;
    }
    RTC::CorbaConsumer<SimpleService::MyService> &service() { return m_service; }

private:
    RTC::CorbaPort m_servicePort;
    RTC::CorbaConsumer<SimpleService::MyService> m_service;
};

/// Writes down every manager action it hears of, in order.
class ActionRecorder : public RTM::RtcLifecycleActionListener,
                       public RTM::ModuleActionListener,
                       public RTM::NamingActionListener
{
public:
    void preCreate(std::string &args) override { record("preCreate " + args); }
    void postCreate(RTC::RTObject_impl *rtobj) override
    {
        record(std::string("postCreate ") + (rtobj ? rtobj->getInstanceName() : "null"));
    }
    void preConfigure(coil::Properties &prop) override
    {
        record("preConfigure " + prop.getProperty("type_name"));
        prop.setProperty("conf.default.step", "7"); // a listener may change the settings
    }
    void postConfigure(coil::Properties &prop) override { record("postConfigure " + prop.getProperty("instance_name")); }
    void preInitialize() override { record("preInitialize"); }
    void postInitialize() override { record("postInitialize"); }
    void preLoad(std::string &modname, std::string &) override { record("preLoad " + modname); }
    void postLoad(std::string &, std::string &funcname) override { record("postLoad " + funcname); }
    void preUnload(std::string &) override { record("preUnload"); }
    void postUnload(std::string &) override { record("postUnload"); }
    void preBind(RTC::RTObject_impl *rtobj, coil::vstring &name) override
    {
        record(std::string("preBind ") + rtobj->getInstanceName() + " " + (name.empty() ? "" : name.front()));
    }
    void postBind(RTC::RTObject_impl *, coil::vstring &) override { record("postBind"); }
    void preUnbind(RTC::RTObject_impl *, coil::vstring &) override { record("preUnbind"); }
    void postUnbind(RTC::RTObject_impl *, coil::vstring &) override { record("postUnbind"); }

    QStringList calls()
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_calls;
    }

private:
    void record(const std::string &text)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_calls << QString::fromStdString(text);
    }
    std::mutex m_mutex;
    QStringList m_calls;
};

RTC::PortService_ptr portNamed(RTC::RTObject_impl *component, const std::string &name)
{
    RTC::RTObject_var self = component->getObjRef();
    RTC::PortServiceList_var ports = self->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        if (std::string(profile->name) == std::string(component->getInstanceName()) + '.' + name)
            return RTC::PortService::_duplicate(ports[i]);
    }
    return RTC::PortService::_nil();
}

RTC::ReturnCode_t connectPorts(RTC::PortService_ptr a, RTC::PortService_ptr b, bool dataPort)
{
    RTC::ConnectorProfile profile;
    profile.name = CORBA::string_dup("test");
    profile.connector_id = CORBA::string_dup("");
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(a);
    profile.ports[1] = RTC::PortService::_duplicate(b);
    if (dataPort) {
        const char *const pairs[][2] = {{"dataport.interface_type", "corba_cdr"},
                                        {"dataport.dataflow_type", "push"},
                                        {"dataport.subscription_type", "flush"},
                                        {"dataport.data_type", "IDL:RTC/TimedLong:1.0"}};
        profile.properties.length(4);
        for (CORBA::ULong i = 0; i < 4; ++i) {
            profile.properties[i].name = CORBA::string_dup(pairs[i][0]);
            profile.properties[i].value <<= pairs[i][1];
        }
    }
    return a->connect(profile);
}

/// An SDO service provider that records its calls (SdoServiceAdmin::init() makes it from the factory).
class ProbeProvider : public RTC::SdoServiceProviderBase
{
public:
    ~ProbeProvider() override { ++deleted; }
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

    static inline std::atomic<int> finalized{0};
    static inline std::atomic<int> deleted{0};

private:
    SDOPackage::ServiceProfile m_profile;
};

/// An SDO service consumer that takes any profile.
class ProbeConsumer : public RTC::SdoServiceConsumerBase
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
    void finalize() override {}

private:
    SDOPackage::ServiceProfile m_profile;
};

/// A local service that records its calls (LocalServiceAdmin makes it from the factory).
class ProbeLocalService : public RTM::LocalServiceBase
{
public:
    ProbeLocalService() { m_profile.name = "ProbeLocalService"; }
    ~ProbeLocalService() override { ++deleted; }
    bool init(const coil::Properties &props) override
    {
        m_profile.properties = props;
        return props.getProperty("refuse") != "YES";
    }
    bool reinit(const coil::Properties &) override { return true; }
    const RTM::LocalServiceProfile &getProfile() const override { return m_profile; }
    void finalize() override { ++finalized; }

    static inline std::atomic<int> finalized{0};
    static inline std::atomic<int> deleted{0};

private:
    RTM::LocalServiceProfile m_profile;
};

void activate(RTC::RTObject_impl *component)
{
    QCOMPARE(component->activate(0), RTC::RTC_OK);
}

} // namespace

class TestSdkRtm : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void managerArguments_data();
    void managerArguments();
    void createsRegisteredTypes();
    void dataFlowsWithListeners();
    void configurationReachesBoundVariables();
    void serviceCallReturns();
    void managerActionListeners();
    void loggerWritesWhereConfigured();
    void loggerDateFormat_data();
    void loggerDateFormat();
    void loadableModulesOfAComponentProgram();
    void sdoServiceAdminOffersFactoryProviders();
    void sdoConfigurationServesTheComponentsSets();
    void sdoOrganizationListsMembers();
    void localServiceAdminRunsEnabledServices();

private:
    RTC::Manager *m_manager = nullptr;
};

void TestSdkRtm::initTestCase()
{
    // No name server and no master: the manager serves on a free loopback port only.
    m_manager = SdkTest::startInProcessManager(
        "tst_sdkrtm", {"manager.modules.load_path:" + QFileInfo(MANAGER_TEST_MODULE).path().toUtf8()});
    QVERIFY(m_manager != nullptr);
    QCOMPARE(&RTC::Manager::instance(), m_manager);
    coil::Properties source(sourceSpec), sink(sinkSpec), provider(providerSpec), consumer(consumerSpec);
    QVERIFY(m_manager->registerFactory(source, RTC::Create<SdkSource>, RTC::Delete<SdkSource>));
    QVERIFY(m_manager->registerFactory(sink, RTC::Create<SdkSink>, RTC::Delete<SdkSink>));
    QVERIFY(m_manager->registerFactory(provider, RTC::Create<SdkProvider>, RTC::Delete<SdkProvider>));
    QVERIFY(m_manager->registerFactory(consumer, RTC::Create<SdkConsumer>, RTC::Delete<SdkConsumer>));
}

void TestSdkRtm::cleanupTestCase()
{
    // The manager shuts down like a component program's: the ORB stops and runManager() returns.
    QVERIFY(SdkTest::stopInProcessManager(m_manager));
}

void TestSdkRtm::managerArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");
    QTest::addColumn<bool>("ok");
    QTest::newRow("-o colon") << QStringList{"-i", "-f", "/none", "-o", "exec_cxt.periodic.rate: 50"}
                              << "exec_cxt.periodic.rate" << "50" << true;
    QTest::newRow("-o equals, later wins")
        << QStringList{"-i", "-f", "/none", "-o", "a.b=1", "-o", "a.b=2"} << "a.b" << "2" << true;
    QTest::newRow("-o value with colon") << QStringList{"-i", "-f", "/none", "-o", "corba.endpoints:127.0.0.1:2811"}
                                         << "corba.endpoints" << "127.0.0.1:2811" << true;
    QTest::newRow("-p") << QStringList{"-i", "-f", "/none", "-p", "2812"} << "corba.endpoints" << ":2812" << true;
    QTest::newRow("-d") << QStringList{"-i", "-f", "/none", "-d"} << "manager.is_master" << "YES" << true;
    QTest::newRow("-a") << QStringList{"-i", "-f", "/none", "-a"} << "manager.corba_servant" << "NO" << true;
    QTest::newRow("default") << QStringList{"-i", "-f", "/none"} << "naming.formats" << "%h.host_cxt/%n.rtc" << true;
    QTest::newRow("missing -f file") << QStringList{"-f", "/nonexistent/rtc.conf"} << "" << "" << false;
    QTest::newRow("bad -o") << QStringList{"-o", "novalue"} << "" << "" << false;
    QTest::newRow("unknown") << QStringList{"--frobnicate"} << "" << "" << false;
}

void TestSdkRtm::managerArguments()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, key);
    QFETCH(QString, value);
    QFETCH(bool, ok);
    std::vector<QByteArray> storage{"prog"};
    for (const QString &argument : arguments)
        storage.push_back(argument.toUtf8());
    std::vector<char *> argv;
    for (QByteArray &argument : storage)
        argv.push_back(argument.data());
    Runtime::Properties config;
    std::string error;
    QCOMPARE(Runtime::parseManagerArguments(int(argv.size()), argv.data(), &config, &error), ok);
    if (ok)
        QCOMPARE(QString::fromStdString(config.value(key.toStdString())), value);
    else
        QVERIFY(!error.empty());
}

void TestSdkRtm::createsRegisteredTypes()
{
    RTC::RTObject_impl *component = m_manager->createComponent("SdkSource?instance_name=made");
    QVERIFY(component != nullptr);
    QCOMPARE(QString(component->getInstanceName()), QString("made"));
    QCOMPARE(QString(component->getTypeName()), QString("SdkSource"));
    QCOMPARE(QString::fromStdString(component->getProperties().getProperty("conf.default.step")), QString("1"));
    QCOMPARE(m_manager->getComponent("made"), component);
    RTC::PortService_var out = portNamed(component, "out");
    QVERIFY(!CORBA::is_nil(out));
    QVERIFY(m_manager->getModulesFactories().size() >= 4);
    QVERIFY(m_manager->createComponent("NoSuchType") == nullptr);
    m_manager->deleteComponent("made");
    QTRY_VERIFY_WITH_TIMEOUT(m_manager->getComponent("made") == nullptr, 5000);
}

void TestSdkRtm::dataFlowsWithListeners()
{
    auto *source = dynamic_cast<SdkSource *>(m_manager->createComponent("SdkSource"));
    auto *sink = dynamic_cast<SdkSink *>(m_manager->createComponent("SdkSink"));
    QVERIFY(source && sink);
    RTC::PortService_var out = portNamed(source, "out");
    RTC::PortService_var in = portNamed(sink, "in");
    QCOMPARE(connectPorts(out, in, true), RTC::RTC_OK);
    QCOMPARE(sink->connects.load(), 1);
    activate(source);
    activate(sink);
    QTRY_VERIFY_WITH_TIMEOUT(sink->received.load() > 5, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(sink->bufferWrites.load() > 5, 10000);
    QVERIFY(sink->lastRead.load() > 0);
    QVERIFY(sink->lastWritten.load() >= sink->lastRead.load());
    // Within one process samples skip CDR; listeners that want bytes still get them.
    QTRY_VERIFY_WITH_TIMEOUT(sink->lastRaw.load() > 0, 5000);
    QCOMPARE(source->deactivate(0), RTC::RTC_OK);
    QCOMPARE(sink->deactivate(0), RTC::RTC_OK);
    m_manager->deleteComponent(source);
    m_manager->deleteComponent(sink);
}

void TestSdkRtm::configurationReachesBoundVariables()
{
    auto *source = dynamic_cast<SdkSource *>(m_manager->createComponent("SdkSource"));
    QVERIFY(source);
    activate(source);
    QTRY_VERIFY_WITH_TIMEOUT(([source] {
                                 std::lock_guard<std::mutex> lock(source->mutex);
                                 return source->seenStep == 1 && source->seenGains == std::vector<double>{0.5, 1.5};
                             }()),
                             5000);
    RTC::RTObject_var self = source->getObjRef();
    SDOPackage::Configuration_var configuration = self->get_configuration();
    SDOPackage::ConfigurationSet set;
    set.id = CORBA::string_dup("default");
    set.description = CORBA::string_dup("");
    set.configuration_data.length(2);
    set.configuration_data[0].name = CORBA::string_dup("step");
    set.configuration_data[0].value <<= "5";
    set.configuration_data[1].name = CORBA::string_dup("gains");
    set.configuration_data[1].value <<= "2.5, 3.5, 4";
    QVERIFY(configuration->set_configuration_set_values(set));
    QVERIFY(configuration->activate_configuration_set("default"));
    QTRY_VERIFY_WITH_TIMEOUT(([source] {
                                 std::lock_guard<std::mutex> lock(source->mutex);
                                 return source->seenStep == 5
                                        && source->seenGains == std::vector<double>{2.5, 3.5, 4.0};
                             }()),
                             5000);
    QCOMPARE(source->deactivate(0), RTC::RTC_OK);
    m_manager->deleteComponent(source);
}

void TestSdkRtm::serviceCallReturns()
{
    RTC::RTObject_impl *provider = m_manager->createComponent("SdkProvider");
    auto *consumer = dynamic_cast<SdkConsumer *>(m_manager->createComponent("SdkConsumer"));
    QVERIFY(provider && consumer);
    QVERIFY(CORBA::is_nil(consumer->service()._ptr()));
    RTC::PortService_var provided = portNamed(provider, "MyService");
    RTC::PortService_var required = portNamed(consumer, "MyService");
    QCOMPARE(connectPorts(required, provided, false), RTC::RTC_OK);
    QVERIFY(!CORBA::is_nil(consumer->service()._ptr()));
    // As in OpenRTM-aist, the provided object answers only while its component is active.
    bool answeredInactive = true;
    try {
        CORBA::String_var early = consumer->service()->echo("early");
    } catch (const CORBA::OBJECT_NOT_EXIST &) {
        answeredInactive = false;
    }
    QVERIFY(!answeredInactive);
    QCOMPARE(provider->activate(0), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(!consumer->service()->_non_existent(), 5000);
    CORBA::String_var answer = consumer->service()->echo("hello");
    QCOMPARE(QString(answer.in()), QString("echo:hello"));
    consumer->service()->set_value(2.5f);
    QCOMPARE(consumer->service()->get_value(), 2.5f);
    QCOMPARE(required->disconnect_all(), RTC::RTC_OK);
    QVERIFY(CORBA::is_nil(consumer->service()._ptr()));
    QCOMPARE(provider->deactivate(0), RTC::RTC_OK);
    m_manager->deleteComponent(provider);
    m_manager->deleteComponent(consumer);
}

void TestSdkRtm::managerActionListeners()
{
    ActionRecorder recorder;
    m_manager->addRtcLifecycleActionListener(&recorder, false);
    m_manager->addModuleActionListener(&recorder, false);
    m_manager->addNamingActionListener(&recorder, false);
    auto *source = dynamic_cast<SdkSource *>(m_manager->createComponent("SdkSource?instance_name=watched"));
    QVERIFY(source);
    QCOMPARE(QString::fromStdString(source->getProperties().getProperty("conf.default.step")), QString("7"));
    QCOMPARE(m_manager->load(MANAGER_TEST_MODULE.toStdString(), ""), RTC::RTC_OK);
    QCOMPARE(m_manager->getLoadedModules().size(), size_t(1));
    m_manager->unload(qPrintable(MANAGER_TEST_MODULE));
    QVERIFY(m_manager->getLoadedModules().empty());
    m_manager->deleteComponent(source);
    QTRY_VERIFY_WITH_TIMEOUT(recorder.calls().contains("postUnbind"), 5000);
    m_manager->removeRtcLifecycleActionListener(&recorder);
    m_manager->removeModuleActionListener(&recorder);
    m_manager->removeNamingActionListener(&recorder);
    const QStringList expected{"preCreate SdkSource?instance_name=watched",
                               "preConfigure SdkSource",
                               "postConfigure watched",
                               "preInitialize",
                               "postInitialize",
                               "preBind watched %h.host_cxt/watched.rtc",
                               "postBind",
                               "postCreate watched",
                               QStringLiteral("preLoad ") + MANAGER_TEST_MODULE,
                               "postLoad ",
                               "preUnload",
                               "postUnload",
                               "preUnbind",
                               "postUnbind"};
    QStringList calls = recorder.calls();
    calls.replaceInStrings(QRegularExpression("^preBind watched [^/]*"), "preBind watched %h.host_cxt");
    QCOMPARE(calls, expected);
    // Unloading withdrew the module's type.
    const std::vector<std::string> factories = m_manager->getModulesFactories();
    QVERIFY(std::find(factories.begin(), factories.end(), "ModuleCounter") == factories.end());
    QVERIFY(m_manager->createComponent("ModuleCounter") == nullptr);
}

void TestSdkRtm::loggerWritesWhereConfigured()
{
    // OpenRTM's logger.file_name: several destinations, format codes and environment variables.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    qputenv("RTSTUDIO_LOG_TEST_DIR", dir.path().toUtf8());
    Runtime::Properties config;
    config.set("logger.log_level", "DEBUG");
    config.set("logger.file_name", "${RTSTUDIO_LOG_TEST_DIR}/rtc%p.log, " + dir.path().toStdString() + "/%M.log");
    config.set("manager.name", "logmanager");
    RTC::Sdk::LoggerSink::instance().configure(config);
    RTC::Logger rtclog("LogTest");
    RTC_DEBUG(("debug %d", 1));
    RTC_TRACE(("trace %d", 2));
    RTC_INFO_STR("info line");
    for (const QString &name : {QString("rtc%1.log").arg(QCoreApplication::applicationPid()), QString("logmanager.log")}) {
        QFile file(dir.filePath(name));
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(name));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY2(text.contains("DEBUG: LogTest: debug 1"), qPrintable(text));
        QVERIFY2(text.contains("INFO: LogTest: info line"), qPrintable(text));
        QVERIFY2(!text.contains("trace"), qPrintable(text));
    }
    // Back to what initTestCase chose, so that nothing else writes into the folder.
    config = Runtime::Properties();
    config.set("logger.log_level", "ERROR");
    RTC::Sdk::LoggerSink::instance().configure(config);
}

void TestSdkRtm::loggerDateFormat_data()
{
    QTest::addColumn<QString>("format");
    QTest::addColumn<QString>("expected");
    // 2026-11-29 20:49:07.123456 local time.
    QTest::newRow("OpenRTM's default") << "%b %d %H:%M:%S.%Q" << "Nov 29 20:49:07.123";
    QTest::newRow("microseconds") << "%Y-%m-%dT%H:%M:%S.%q" << "2026-11-29T20:49:07.123456";
    QTest::newRow("no fraction") << "%H:%M:%S" << "20:49:07";
    QTest::newRow("a percent sign before Q") << "%%Q %S" << "%Q 07";
}

void TestSdkRtm::loggerDateFormat()
{
    QFETCH(QString, format);
    QFETCH(QString, expected);
    std::tm local{};
    local.tm_year = 2026 - 1900;
    local.tm_mon = 10;
    local.tm_mday = 29;
    local.tm_hour = 20;
    local.tm_min = 49;
    local.tm_sec = 7;
    local.tm_isdst = -1;
    const auto time = std::chrono::system_clock::from_time_t(std::mktime(&local)) + std::chrono::microseconds(123456);
    QCOMPARE(QString::fromStdString(RTC::Sdk::LoggerSink::formatDate(format.toStdString(), time)), expected);
}

// A component program is no rtmanager: it cannot load a module in a process of its own to see
// which types it registers, and names the module files instead.
void TestSdkRtm::loadableModulesOfAComponentProgram()
{
    QStringList files;
    for (coil::Properties &module : m_manager->getLoadableModules()) {
        QVERIFY(module["implementation_id"].empty());
        files << QString::fromStdString(module["module_file_name"]);
    }
    QVERIFY2(files.contains("ManagerTestModule.so"), qPrintable(files.join(' ')));
}

void TestSdkRtm::sdoServiceAdminOffersFactoryProviders()
{
    RTC::RTObject_impl *component = m_manager->createComponent("SdkSource?instance_name=sdoadmin");
    QVERIFY(component != nullptr);
    const char type[] = "IDL:rtstudio/tests/Probe:1.0";
    RTC::SdoServiceProviderFactory::instance().addFactory(
        type, coil::Creator<RTC::SdoServiceProviderBase, ProbeProvider>,
        coil::Destructor<RTC::SdoServiceProviderBase, ProbeProvider>);
    coil::Properties props;
    props.setProperty("sdo.service.provider.enabled_services", "ALL");
    props.setProperty("sdo.service.consumer.enabled_services", "OnlyThisType");
    RTC::SdoServiceAdmin admin(*component);
    admin.init(props);
    RTC::SdoServiceProviderFactory::instance().removeFactory(type);

    // The provider is the component's: its SDO interface lists it.
    SDOPackage::ServiceProfileList_var offered = admin.getServiceProviderProfiles();
    QCOMPARE(offered->length(), CORBA::ULong(1));
    QCOMPARE(QString(offered[0].interface_type.in()), QString(type));
    const std::string id(offered[0].id.in());
    SDOPackage::ServiceProfileList_var listed = component->get_service_profiles();
    QCOMPARE(listed->length(), CORBA::ULong(1));
    QCOMPARE(QString(listed[0].id.in()), QString::fromStdString(id));
    SDOPackage::SDOService_var service = admin.getServiceProvider(id.c_str());
    QVERIFY(!CORBA::is_nil(service));
    QVERIFY_THROWS_EXCEPTION(SDOPackage::InvalidParameter, admin.getServiceProviderProfile("no-such-id"));

    // A consumer type the properties do not enable is refused, although a consumer is registered.
    RTC::SdoServiceConsumerFactory::instance().addFactory(
        type, coil::Creator<RTC::SdoServiceConsumerBase, ProbeConsumer>,
        coil::Destructor<RTC::SdoServiceConsumerBase, ProbeConsumer>);
    SDOPackage::ServiceProfile consumer;
    consumer.id = CORBA::string_dup("c1");
    consumer.interface_type = CORBA::string_dup(type);
    QVERIFY(!admin.addSdoServiceConsumer(consumer));
    RTC::SdoServiceAdmin acceptingAll(*component);
    acceptingAll.init(coil::Properties());
    QVERIFY(acceptingAll.addSdoServiceConsumer(consumer));
    QVERIFY(acceptingAll.removeSdoServiceConsumer("c1"));
    RTC::SdoServiceConsumerFactory::instance().removeFactory(type);

    const int finalized = ProbeProvider::finalized;
    QVERIFY(admin.removeSdoServiceProvider(id.c_str()));
    QCOMPARE(ProbeProvider::finalized.load(), finalized + 1);
    QVERIFY(!admin.removeSdoServiceProvider(id.c_str()));
    offered = admin.getServiceProviderProfiles();
    QCOMPARE(offered->length(), CORBA::ULong(0));
    m_manager->deleteComponent("sdoadmin");
    QTRY_VERIFY_WITH_TIMEOUT(m_manager->getComponent("sdoadmin") == nullptr, 5000);
}

void TestSdkRtm::sdoConfigurationServesTheComponentsSets()
{
    RTC::RTObject_impl *component = m_manager->createComponent("SdkSource?instance_name=sdoconf");
    QVERIFY(component != nullptr);
    RTC::SdoServiceAdmin admin(*component);
    auto *configuration = new SDOPackage::Configuration_impl(component->getConfigService(), admin);
    {
        SDOPackage::Configuration_var ref = configuration->getObjRef();
        QVERIFY(!CORBA::is_nil(ref));
        SDOPackage::ConfigurationSet_var active = ref->get_active_configuration_set();
        QCOMPARE(QString(active->id.in()), QString("default"));

        // A set added through SDO is the component's.
        SDOPackage::ConfigurationSet extra;
        extra.id = CORBA::string_dup("extra");
        extra.description = CORBA::string_dup("");
        extra.configuration_data.length(1);
        extra.configuration_data[0].name = CORBA::string_dup("step");
        extra.configuration_data[0].value <<= "7";
        QVERIFY(ref->add_configuration_set(extra));
        QVERIFY(component->getConfigService().haveConfig("extra"));
        QCOMPARE(QString::fromStdString(component->getConfigService().getConfigurationSet("extra").getProperty("step")),
                 QString("7"));

        // A service profile attaches a consumer: none is registered for this type.
        SDOPackage::ServiceProfile profile;
        profile.id = CORBA::string_dup("p1");
        profile.interface_type = CORBA::string_dup("IDL:rtstudio/tests/Unknown:1.0");
        QVERIFY(!ref->add_service_profile(profile));
        QVERIFY(!ref->remove_service_profile("p1"));

        SDOPackage::DeviceProfile device;
        device.device_type = CORBA::string_dup("probe");
        QVERIFY(ref->set_device_profile(device));
        QCOMPARE(QString(configuration->getDeviceProfile().device_type.in()), QString("probe"));
    }
    PortableServer::POA_var poa = configuration->_default_POA();
    Runtime::releaseServant(poa, configuration);
    m_manager->deleteComponent("sdoconf");
    QTRY_VERIFY_WITH_TIMEOUT(m_manager->getComponent("sdoconf") == nullptr, 5000);
}

void TestSdkRtm::sdoOrganizationListsMembers()
{
    RTC::RTObject_impl *owner = m_manager->createComponent("SdkSource?instance_name=orgowner");
    RTC::RTObject_impl *member = m_manager->createComponent("SdkSource?instance_name=orgmember");
    QVERIFY(owner != nullptr && member != nullptr);
    RTC::RTObject_var ownerRef = owner->getObjRef();
    auto *organization = new SDOPackage::Organization_impl(ownerRef.in());
    {
        SDOPackage::Organization_var ref = organization->getObjRef();
        QVERIFY(!CORBA::is_nil(ref));
        CORBA::String_var id = ref->get_organization_id();
        QVERIFY(std::string(id.in()).size() > 0);
        SDOPackage::SDOSystemElement_var got = ref->get_owner();
        QVERIFY(got->_is_equivalent(ownerRef));

        SDOPackage::SDOList members;
        members.length(1);
        members[0] = member->getObjRef();
        QVERIFY(ref->add_members(members));
        SDOPackage::SDOList_var listed = ref->get_members();
        QCOMPARE(listed->length(), CORBA::ULong(1));
        CORBA::String_var memberId = member->get_sdo_id();
        QVERIFY(ref->remove_member(memberId));
        listed = ref->get_members();
        QCOMPARE(listed->length(), CORBA::ULong(0));
    }
    Runtime::releaseServant(RTC::Manager::instance().getPOA(), organization);
    m_manager->deleteComponent("orgowner");
    m_manager->deleteComponent("orgmember");
    QTRY_VERIFY_WITH_TIMEOUT(m_manager->getComponent("orgmember") == nullptr, 5000);
}

void TestSdkRtm::localServiceAdminRunsEnabledServices()
{
    RTM::LocalServiceFactory::instance().addFactory("ProbeLocalService",
                                                    coil::Creator<RTM::LocalServiceBase, ProbeLocalService>,
                                                    coil::Destructor<RTM::LocalServiceBase, ProbeLocalService>);
    RTM::LocalServiceAdmin &admin = RTM::LocalServiceAdmin::instance();

    // Not enabled: nothing made.
    coil::Properties none;
    none.setProperty("enabled_services", "SomethingElse");
    admin.init(none);
    QVERIFY(admin.getService("ProbeLocalService") == nullptr);

    // A service that refuses its properties is deleted at once.
    const int deleted = ProbeLocalService::deleted;
    coil::Properties refusing;
    refusing.setProperty("enabled_services", "ALL");
    refusing.setProperty("refuse", "YES");
    admin.init(refusing);
    QVERIFY(admin.getService("ProbeLocalService") == nullptr);
    QCOMPARE(ProbeLocalService::deleted.load(), deleted + 1);

    coil::Properties enabled;
    enabled.setProperty("enabled_services", "ProbeLocalService");
    enabled.setProperty("greeting", "hello");
    admin.init(enabled);
    QVERIFY(admin.getService("ProbeLocalService") != nullptr);
    RTM::LocalServiceProfile profile;
    QVERIFY(admin.getServiceProfile("ProbeLocalService", profile));
    QCOMPARE(QString::fromStdString(profile.properties.getProperty("greeting")), QString("hello"));
    QCOMPARE(admin.getServiceProfiles().size(), size_t(1));
    {
        std::unique_ptr<ProbeLocalService> second(new ProbeLocalService);
        QVERIFY(!admin.addLocalService(second.get())); // the name is taken; the caller keeps it
    }
    QCOMPARE(ProbeLocalService::deleted.load(), deleted + 2);

    const int finalized = ProbeLocalService::finalized;
    QVERIFY(admin.removeLocalService("ProbeLocalService"));
    QCOMPARE(ProbeLocalService::finalized.load(), finalized + 1);
    QCOMPARE(ProbeLocalService::deleted.load(), deleted + 3);
    QVERIFY(!admin.removeLocalService("ProbeLocalService"));
    QVERIFY(admin.getServiceProfiles().empty());
    RTM::LocalServiceFactory::instance().removeFactory("ProbeLocalService");
}

QTEST_GUILESS_MAIN(TestSdkRtm)
#include "tst_sdkrtm.moc"
