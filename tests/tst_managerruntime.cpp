// SPDX-License-Identifier: MIT
// The component runtime in one process: properties and create strings, buffers, the execution
// context's state machine, configuration sets, data ports (push flush/new/periodic, pull, both
// byte orders) and service ports, driven through their CORBA interfaces as tools would.
#include "builtins.h"
#include "corbautil.h"
#include "createrequest.h"
#include "inportconnector.h"
#include "namingregistrar.h"
#include "portbase.h"
#include "rtobject.h"
#include "ringbuffer.h"

#include "common/nvlist.h"

#include <QtTest>

#include <omniORB4/omniORB.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <thread>

using namespace Runtime;

namespace {

/// A component whose callbacks fail on demand, to drive the EC into ERROR and back.
class Faulty : public RtObject
{
public:
    using RtObject::RtObject;
    using RtObject::addInPort;
    using RtObject::addOutPort;
    using RtObject::findPort;
    std::atomic<bool> failExecute{false};
    std::atomic<bool> failReset{false};
    std::atomic<int> activations{0};
    std::atomic<int> executions{0};

protected:
    RTC::ReturnCode_t onActivated(RTC::ExecutionContextHandle_t) override
    {
        ++activations;
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        ++executions;
        return failExecute ? RTC::RTC_ERROR : RTC::RTC_OK;
    }
    RTC::ReturnCode_t onReset(RTC::ExecutionContextHandle_t) override
    {
        return failReset ? RTC::RTC_ERROR : RTC::RTC_OK;
    }
};

/// A port at the far end of a connector that keeps the connector however its notify_connect
/// ends, as an OpenRTM-aist port keeps one whose subscription failed, and notes what it is told.
class KeepingPort : public POA_RTC::PortService
{
public:
    enum Ending { Refuse, TimeOut };
    explicit KeepingPort(Ending ending)
        : m_ending(ending)
    {
    }
    QStringList held;
    QStringList toldToDrop;

    RTC::PortProfile *get_port_profile() override
    {
        auto *profile = new RTC::PortProfile;
        profile->name = "Keeper.in";
        return profile;
    }
    RTC::ConnectorProfileList *get_connector_profiles() override { return new RTC::ConnectorProfileList; }
    RTC::ConnectorProfile *get_connector_profile(const char *) override { return new RTC::ConnectorProfile; }
    RTC::ReturnCode_t connect(RTC::ConnectorProfile &) override { return RTC::UNSUPPORTED; }
    RTC::ReturnCode_t disconnect(const char *) override { return RTC::UNSUPPORTED; }
    RTC::ReturnCode_t disconnect_all() override { return RTC::UNSUPPORTED; }
    RTC::ReturnCode_t notify_connect(RTC::ConnectorProfile &profile) override
    {
        held << QString::fromUtf8(profile.connector_id.in());
        if (m_ending == TimeOut)
            throw CORBA::TIMEOUT(0, CORBA::COMPLETED_MAYBE);
        return RTC::RTC_ERROR;
    }
    RTC::ReturnCode_t notify_disconnect(const char *id) override
    {
        toldToDrop << QString::fromUtf8(id);
        return held.removeAll(QString::fromUtf8(id)) ? RTC::RTC_OK : RTC::BAD_PARAMETER;
    }

private:
    Ending m_ending;
};

QString statusOf(RTC::RTObject_ptr rtc, const char *name)
{
    SDOPackage::NVList_var list = rtc->get_status_list();
    for (CORBA::ULong i = 0; i < list->length(); ++i) {
        const char *text = nullptr;
        if (QByteArray(list[i].name) == name && (list[i].value >>= text))
            return QString::fromUtf8(text);
    }
    return {};
}

long statusNumber(RTC::RTObject_ptr rtc, const char *name)
{
    return statusOf(rtc, name).toLong();
}

/// The reference of type T that entry @p name of @p list holds; nil when it holds none.
template<typename T>
typename T::_var_type nvReference(const SDOPackage::NVList &list, const char *name)
{
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        typename T::_ptr_type reference = T::_nil();
        if (QByteArray(list[i].name) == name && (list[i].value >>= reference))
            return T::_duplicate(reference);
    }
    return T::_nil();
}

void setNv(SDOPackage::NVList &list, const char *name, const char *value)
{
    const CORBA::ULong n = list.length();
    list.length(n + 1);
    list[n].name = name;
    list[n].value <<= value;
}

} // namespace

class TestManagerRuntime : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanup();
    void cleanupTestCase();

    void confParsing();
    void objectUrls_data();
    void objectUrls();
    void argumentsSplitAsOpenRtm_data();
    void argumentsSplitAsOpenRtm();
    void formatCodes_data();
    void formatCodes();
    void createRequest_data();
    void createRequest();
    void createRequestErrors_data();
    void createRequestErrors();
    void ringBufferPolicies();
    void cdrLayout();
    void putFromThisProcessKeepsCallersBytes();

    void stateMachine();
    void errorAndReset();
    void contextThreadStartsWithWork();
    void rateAndProfile();
    void configurationSets();
    void componentProfile();
    void dataFlow_data();
    void dataFlow();
    void disconnectStopsFlow();
    void onInitializeAgainKeepsPorts();
    void connectorBufferPolicy();
    void connectRejectsMismatch_data();
    void connectRejectsMismatch();
    void marshalingTypeNeedsASerializer();
    void connectRefusesNilPeer_data();
    void connectRefusesNilPeer();
    void duplicateConnectionRefused();
    void failedConnectLeavesNothingBehind_data();
    void failedConnectLeavesNothingBehind();
    void inPortTakesAnySubscription();
    void seqInReadsEveryFlow_data();
    void seqInReadsEveryFlow();
    void connectionLimits_data();
    void connectionLimits();
    void sameDataType_data();
    void sameDataType();
    void connectDataTypeSpellings_data();
    void connectDataTypeSpellings();
    void controlLoop();
    void servicePort();

private:
    RtObject *create(const QString &type, const QString &instance, const Properties &extra = {});
    RTC::ExecutionContext_ptr ownedContext(RTC::RTObject_ptr rtc);
    RTC::ReturnCode_t connect(RTC::PortService_ptr a, RTC::PortService_ptr b, const Properties &p,
                              RTC::ConnectorProfile *result = nullptr);
    RTC::PortService_ptr port(RTC::RTObject_ptr rtc, const char *shortName);
    /// A ConsoleIn and a ConsoleOut as most connection tests use them: the components (`in` is the
    /// ConsoleIn, `out` the ConsoleOut) and the ports between them.
    struct ConsolePair
    {
        RTC::RTObject_var in;
        RTC::RTObject_var out;
        RTC::PortService_var outPort;
        RTC::PortService_var inPort;
    };
    ConsolePair consolePair(const char *source, const char *sink);

    CORBA::ORB_var m_orb;
    PortableServer::POA_var m_poa;
    std::vector<RtObject *> m_components;
};

void TestManagerRuntime::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    CORBA::Object_var object = m_orb->resolve_initial_references("RootPOA");
    m_poa = PortableServer::POA::_narrow(object);
    PortableServer::POAManager_var manager = m_poa->the_POAManager();
    manager->activate();
}

void TestManagerRuntime::cleanup()
{
    for (RtObject *component : m_components) {
        component->shutdownComponent();
        PortableServer::ObjectId_var id = m_poa->servant_to_id(component);
        m_poa->deactivate_object(id);
        component->_remove_ref();
    }
    m_components.clear();
}

void TestManagerRuntime::cleanupTestCase()
{
    m_orb->destroy();
}

RtObject *TestManagerRuntime::create(const QString &type, const QString &instance, const Properties &extra)
{
    RtObject *servant = nullptr;
    Properties properties;
    if (type == QLatin1String("Faulty")) {
        servant = new Faulty(m_poa);
    } else {
        for (const ComponentFactory &factory : builtinFactories()) {
            if (factory.implementationId() == type.toStdString()) {
                servant = factory.create(m_poa);
                properties = factory.profile;
            }
        }
    }
    if (!servant)
        return nullptr;
    properties.set("instance_name", instance.toStdString());
    properties.set("exec_cxt.periodic.rate", "500");
    properties.merge(extra);
    servant->setProperties(properties);
    RTC::RTObject_var ref = servant->reference();
    if (servant->initialize() != RTC::RTC_OK)
        return nullptr;
    m_components.push_back(servant);
    return servant;
}

RTC::ExecutionContext_ptr TestManagerRuntime::ownedContext(RTC::RTObject_ptr rtc)
{
    RTC::ExecutionContextList_var list = rtc->get_owned_contexts();
    return list->length() ? RTC::ExecutionContext::_duplicate(list[0]) : RTC::ExecutionContext::_nil();
}

RTC::PortService_ptr TestManagerRuntime::port(RTC::RTObject_ptr rtc, const char *shortName)
{
    RTC::PortServiceList_var ports = rtc->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        const QByteArray name(profile->name);
        if (name.endsWith(QByteArray(".") + shortName))
            return RTC::PortService::_duplicate(ports[i]);
    }
    return RTC::PortService::_nil();
}

TestManagerRuntime::ConsolePair TestManagerRuntime::consolePair(const char *source,
                                                                const char *sink)
{
    ConsolePair pair;
    pair.in = create("ConsoleIn", source)->reference();
    pair.out = create("ConsoleOut", sink)->reference();
    pair.outPort = port(pair.in, "out");
    pair.inPort = port(pair.out, "in");
    return pair;
}

RTC::ReturnCode_t TestManagerRuntime::connect(RTC::PortService_ptr a, RTC::PortService_ptr b, const Properties &p,
                                              RTC::ConnectorProfile *result)
{
    RTC::ConnectorProfile profile;
    profile.name = "test";
    profile.connector_id = "";
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(a);
    profile.ports[1] = RTC::PortService::_duplicate(b);
    for (const auto &[key, value] : p.entries())
        setNv(profile.properties, key.c_str(), value.c_str());
    const RTC::ReturnCode_t code = a->connect(profile);
    if (result)
        *result = profile;
    return code;
}

void TestManagerRuntime::confParsing()
{
    std::vector<std::string> errors;
    const Properties p = Properties::parseConf("# comment\ncorba.nameservers: localhost:2809\n"
                                               "naming.formats = %h.host_cxt/%n.rtc\n"
                                               "manager.modules.load_path: a,\\\n b\n"
                                               "no separator here\n",
                                               &errors);
    QCOMPARE(p.value("corba.nameservers"), std::string("localhost:2809"));
    QCOMPARE(p.value("naming.formats"), std::string("%h.host_cxt/%n.rtc"));
    QCOMPARE(p.value("manager.modules.load_path"), std::string("a, b"));
    QCOMPARE(errors.size(), size_t(1));
    QVERIFY(QString::fromStdString(errors[0]).startsWith("6:"));
    QCOMPARE(p.subtree("naming").value("formats"), std::string("%h.host_cxt/%n.rtc"));

    // Numbers: a malformed one gives the fallback and says why (rtmanager reports it and starts).
    const Properties numbers = Properties::parseConf("a: 250\nb: 0.5\nc: abc\nd: 12ms\ne:\n");
    std::string problem;
    QCOMPARE(numbers.number("a", 1, &problem), 250.0);
    QCOMPARE(numbers.number("b", 1, &problem), 0.5);
    QCOMPARE(numbers.number("e", 7, &problem), 7.0);
    QCOMPARE(numbers.number("missing", 7, &problem), 7.0);
    QVERIFY(problem.empty());
    QCOMPARE(numbers.number("c", 5000, &problem), 5000.0);
    QCOMPARE(problem, std::string("c: 'abc' is not a number; 5000 is used"));
    QCOMPARE(numbers.number("d", 3, &problem), 3.0);
}

void TestManagerRuntime::objectUrls_data()
{
    // The address forms of OpenRTM-aist's corba.nameservers and corba.master_manager.
    QTest::addColumn<QString>("address");
    QTest::addColumn<bool>("tls");
    QTest::addColumn<QString>("url");
    QTest::newRow("host:port") << "robot1:2809" << false << "corbaloc:iiop:1.2@robot1:2809/NameService";
    QTest::newRow("host:port, TLS") << "robot1:2809" << true << "corbaloc:ssliop:robot1:2809/NameService";
    QTest::newRow("giop:tcp:") << "giop:tcp:robot1:2809" << true << "corbaloc:iiop:1.2@robot1:2809/NameService";
    QTest::newRow("giop::") << "giop::robot1:2809" << false << "corbaloc:iiop:1.2@robot1:2809/NameService";
    QTest::newRow("giop:ssl:") << "giop:ssl:robot1:2809" << false << "corbaloc:ssliop:robot1:2809/NameService";
    QTest::newRow("iiop://") << "iiop://robot1:2809" << false << "corbaloc:iiop:1.2@robot1:2809/NameService";
    QTest::newRow("ssliop://") << "ssliop://robot1:2809" << false << "corbaloc:ssliop:robot1:2809/NameService";
    QTest::newRow("ssliop:") << "ssliop:robot1:2809" << false << "corbaloc:ssliop:robot1:2809/NameService";
    QTest::newRow("inet:") << "inet:robot1:2809" << false << "corbaloc:iiop:1.2@robot1:2809/NameService";
    QTest::newRow("corbaloc") << "corbaloc:ssliop:robot1:2809" << false << "corbaloc:ssliop:robot1:2809/NameService";
    QTest::newRow("corbaname") << "corbaname::robot1:2809" << false << "corbaname::robot1:2809#NameService";
}

void TestManagerRuntime::objectUrls()
{
    QFETCH(QString, address);
    QFETCH(bool, tls);
    QFETCH(QString, url);
    QCOMPARE(QString::fromStdString(Runtime::objectUrl(address.toStdString(), "NameService", tls)), url);
}

void TestManagerRuntime::argumentsSplitAsOpenRtm_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("blanks") << " -ORBa  1\t-b " << QStringList {"-ORBa", "1", "-b"};
    QTest::newRow("double quotes") << "-ORBserverTransportRule \"* ssl\" -ORBendPoint giop:ssl::"
                                   << QStringList {"-ORBserverTransportRule", "* ssl", "-ORBendPoint", "giop:ssl::"};
    QTest::newRow("single quotes") << "a 'b c'd" << QStringList {"a", "b cd"};
    QTest::newRow("escaped blank") << "a\\ b" << QStringList {"a b"};
    QTest::newRow("empty") << "" << QStringList {""};
}

void TestManagerRuntime::argumentsSplitAsOpenRtm()
{
    QFETCH(QString, text);
    QFETCH(QStringList, arguments);
    QStringList split;
    for (const std::string &argument : Runtime::splitArguments(text.toStdString()))
        split << QString::fromStdString(argument);
    QCOMPARE(split, arguments);
}

void TestManagerRuntime::formatCodes_data()
{
    QTest::addColumn<QString>("formats");
    QTest::addColumn<QStringList>("expanded");
    const QString pid = QString::number(QCoreApplication::applicationPid());
    QTest::newRow("naming") << "%h.host_cxt/%n.rtc" << QStringList{"box.host_cxt/Motor3.rtc"};
    QTest::newRow("profile codes") << "%t %m %i %N %c %v %V" << QStringList{"MotorType MotorType Motor 3 cat 2.1 AIST"};
    QTest::newRow("several, trimmed") << "a/%n.rtc , %M/%n" << QStringList{"a/Motor3.rtc", "mgr/Motor3"};
    QTest::newRow("pid and percent") << "rtc%p.log 100%%" << QStringList{"rtc" + pid + ".log 100%"};
    QTest::newRow("environment") << "${RTSTUDIO_FORMAT_TEST}/x" << QStringList{"/var/envtest/x"};
    QTest::newRow("unset variable, unknown code") << "${RTSTUDIO_NOT_SET_AT_ALL}%q" << QStringList{"%q"};
}

void TestManagerRuntime::formatCodes()
{
    QFETCH(QString, formats);
    QFETCH(QStringList, expanded);
    qputenv("RTSTUDIO_FORMAT_TEST", "/var/envtest");
    Properties values;
    values.set("host", "box");
    values.set("instance_name", "Motor3");
    values.set("implementation_id", "Motor");
    values.set("type_name", "MotorType");
    values.set("category", "cat");
    values.set("version", "2.1");
    values.set("vendor", "AIST");
    values.set("manager_name", "mgr");
    QStringList result;
    for (const std::string &path : NamingRegistrar::expand(formats.toStdString(), values))
        result << QString::fromStdString(path);
    QCOMPARE(result, expanded);
}

void TestManagerRuntime::createRequest_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("type");
    QTest::addColumn<QString>("address");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("instance");
    QTest::addColumn<QString>("forwarded");

    QTest::newRow("plain") << "ConsoleIn" << "ConsoleIn" << "" << "" << "" << "ConsoleIn";
    QTest::newRow("name last") << "ConsoleIn?instance_name=a&manager_name=s1" << "ConsoleIn" << "" << "s1" << "a"
                               << "ConsoleIn?instance_name=a";
    QTest::newRow("name first") << "ConsoleIn?manager_name=s1&instance_name=a" << "ConsoleIn" << "" << "s1"
                                << "a" << "ConsoleIn?instance_name=a";
    QTest::newRow("address middle") << "ConsoleOut?exec_cxt.periodic.rate=10&manager_address=127.0.0.1:5000&"
                                       "instance_name=b"
                                    << "ConsoleOut" << "127.0.0.1:5000" << "" << "b"
                                    << "ConsoleOut?exec_cxt.periodic.rate=10&instance_name=b";
    QTest::newRow("full id") << "RTC:AIST:example:ConsoleIn:C++:2.0.0?instance_name=c" << "ConsoleIn" << "" << ""
                             << "c" << "RTC:AIST:example:ConsoleIn:C++:2.0.0?instance_name=c";
}

void TestManagerRuntime::createRequest()
{
    QFETCH(QString, text);
    std::string error;
    const auto request = CreateRequest::parse(text.toStdString(), &error);
    QVERIFY2(request, error.c_str());
    QTEST(QString::fromStdString(request->implementationId), "type");
    QTEST(QString::fromStdString(request->managerAddress.value_or("")), "address");
    QTEST(QString::fromStdString(request->managerName.value_or("")), "name");
    QTEST(QString::fromStdString(request->properties.value("instance_name")), "instance");
    QTEST(QString::fromStdString(request->toStringWithoutManager()), "forwarded");
}

void TestManagerRuntime::createRequestErrors_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("two ?") << "ConsoleIn?a=1?b=2" << "more than one '?'";
    QTest::newRow("empty") << "?a=1" << "no component type";
    QTest::newRow("pair") << "ConsoleIn?novalue" << "malformed parameter 'novalue'";
    QTest::newRow("bad id") << "RTC:AIST:ConsoleIn" << "malformed component id";
    QTest::newRow("both") << "ConsoleIn?manager_name=a&manager_address=h:1" << "both manager_address";
}

void TestManagerRuntime::createRequestErrors()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    std::string error;
    QVERIFY(!CreateRequest::parse(text.toStdString(), &error));
    QVERIFY2(QString::fromStdString(error).contains(message), error.c_str());

    std::string host;
    int port = 0;
    QVERIFY(!parseHostPort("nohostport", &host, &port, &error));
    QVERIFY(!parseHostPort("h:99999", &host, &port, &error));
    QVERIFY(!parseHostPort("h:12x", &host, &port, &error));
    QVERIFY(parseHostPort("h:2810", &host, &port, &error));
    QCOMPARE(port, 2810);
}

void TestManagerRuntime::ringBufferPolicies()
{
    Properties p;
    p.set("length", "2");
    p.set("write.full_policy", "do_nothing");
    p.set("read.empty_policy", "do_nothing");
    RingBuffer strict(p);
    QCOMPARE(strict.write({1}), RingBuffer::Status::Ok);
    QCOMPARE(strict.write({2}), RingBuffer::Status::Ok);
    QCOMPARE(strict.write({3}), RingBuffer::Status::Full);
    CdrBytes out;
    QCOMPARE(strict.read(&out), RingBuffer::Status::Ok);
    QCOMPARE(out, CdrBytes{1});
    QCOMPARE(strict.read(&out), RingBuffer::Status::Ok);
    QCOMPARE(strict.read(&out), RingBuffer::Status::Empty);

    RingBuffer overwrite(Properties::parseConf("length: 2\n"));
    overwrite.write({1});
    overwrite.write({2});
    overwrite.write({3});
    QCOMPARE(overwrite.read(&out), RingBuffer::Status::Ok);
    QCOMPARE(out, CdrBytes{2});
    overwrite.read(&out);
    // readback repeats the last sample when empty
    QCOMPARE(overwrite.read(&out), RingBuffer::Status::Ok);
    QCOMPARE(out, CdrBytes{3});

    RingBuffer blocking(Properties::parseConf("length: 1\nwrite.full_policy: block\nwrite.timeout: 0.05\n"
                                              "read.empty_policy: block\nread.timeout: 0.05\n"));
    QCOMPARE(blocking.read(&out), RingBuffer::Status::Timeout);
    QCOMPARE(blocking.write({7}), RingBuffer::Status::Ok);
    QCOMPARE(blocking.write({8}), RingBuffer::Status::Timeout);

    // Timeouts out of range: a negative one does not wait, one of 10^122 s waits until the buffer
    // is closed (not a duration that overflows), "nan" keeps the default.
    RingBuffer extremes(Properties::parseConf("length: 1\nwrite.full_policy: block\nwrite.timeout: 5e122\n"
                                              "read.empty_policy: block\nread.timeout: -3\n"));
    QElapsedTimer clock;
    clock.start();
    QCOMPARE(extremes.read(&out), RingBuffer::Status::Timeout);
    QVERIFY2(clock.elapsed() < 500, qPrintable(QString::number(clock.elapsed())));
    QCOMPARE(extremes.write({1}), RingBuffer::Status::Ok);
    std::thread closer([&extremes] { extremes.close(); });
    QCOMPARE(extremes.write({2}), RingBuffer::Status::Timeout);
    closer.join();
    RingBuffer notANumber(Properties::parseConf("read.empty_policy: block\nread.timeout: nan\n"));
    clock.restart();
    QCOMPARE(notANumber.read(&out), RingBuffer::Status::Timeout);
    QVERIFY2(clock.elapsed() >= 900, qPrintable(QString::number(clock.elapsed())));
}

void TestManagerRuntime::cdrLayout()
{
    // OpenRTM marshals RTC::TimedLong as tm.sec, tm.nsec, data: 3 x 4 bytes in the chosen order.
    RTC::TimedLong sample;
    sample.tm.sec = 1;
    sample.tm.nsec = 2;
    sample.data = 0x01020304;
    const CdrBytes little = marshal(sample, true);
    QCOMPARE(little, CdrBytes({1, 0, 0, 0, 2, 0, 0, 0, 4, 3, 2, 1}));
    const CdrBytes big = marshal(sample, false);
    QCOMPARE(big, CdrBytes({0, 0, 0, 1, 0, 0, 0, 2, 1, 2, 3, 4}));
    RTC::TimedLong back;
    QVERIFY(unmarshal(big, false, &back));
    QCOMPARE(back.data, CORBA::Long(0x01020304));
    QVERIFY(!unmarshal(CdrBytes{1, 2}, true, &back));
    QCOMPARE(QString::fromStdString(repositoryId<RTC::TimedLong>()), QString("IDL:RTC/TimedLong:1.0"));
}

void TestManagerRuntime::putFromThisProcessKeepsCallersBytes()
{
    // A remote put's bytes are taken over from the skeleton; a put within the process passes the
    // caller's own sequence, which must come back untouched while the port keeps a copy.
    CdrView heard;
    InPortPushConnector connector("c0", Properties(), m_poa,
                                  [&heard](const CdrView &data, bool) { heard = data; });
    OpenRTM::InPortCdr_var port = connector.reference();
    OpenRTM::CdrData data(4);
    data.length(4);
    for (CORBA::ULong i = 0; i < 4; ++i)
        data[i] = CORBA::Octet(i + 1);
    QVERIFY(data.release());
    QCOMPARE(port->put(data), OpenRTM::PORT_OK);
    QCOMPARE(data.length(), CORBA::ULong(4));
    QCOMPARE(int(data[3]), 4);
    QCOMPARE(heard.size, size_t(4));
    QVERIFY(heard.data != data.get_buffer());
    SharedCdr sample;
    QVERIFY(connector.read(&sample));
    QCOMPARE(sample->view().bytes(), CdrBytes({1, 2, 3, 4}));
}

void TestManagerRuntime::stateMachine()
{
    auto *faulty = static_cast<Faulty *>(create("Faulty", "F0"));
    QVERIFY(faulty);
    RTC::RTObject_var rtc = faulty->reference();
    RTC::ExecutionContext_var ec = ownedContext(rtc);
    QVERIFY(!CORBA::is_nil(ec));
    QVERIFY(ec->is_running());
    QVERIFY(rtc->is_alive(ec));
    QCOMPARE(rtc->get_context_handle(ec), 0);
    QCOMPARE(ec->get_component_state(rtc), RTC::INACTIVE_STATE);
    QCOMPARE(ec->deactivate_component(rtc), RTC::PRECONDITION_NOT_MET);
    QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(rtc), RTC::ACTIVE_STATE);
    QCOMPARE(faulty->activations.load(), 1);
    QTRY_VERIFY(faulty->executions.load() > 5);
    QCOMPARE(ec->activate_component(rtc), RTC::PRECONDITION_NOT_MET);
    QCOMPARE(ec->deactivate_component(rtc), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(rtc), RTC::INACTIVE_STATE);
    // Stopped contexts change states at once in the caller's thread.
    QCOMPARE(ec->stop(), RTC::RTC_OK);
    QVERIFY(!ec->is_running());
    QCOMPARE(ec->stop(), RTC::PRECONDITION_NOT_MET);
    QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(rtc), RTC::ACTIVE_STATE);
    QCOMPARE(ec->start(), RTC::RTC_OK);
    QCOMPARE(ec->get_kind(), RTC::PERIODIC);

    RTC::ExecutionContextList_var participating = rtc->get_participating_contexts();
    QCOMPARE(participating->length(), CORBA::ULong(0));
    QCOMPARE(rtc->initialize(), RTC::PRECONDITION_NOT_MET);
}

void TestManagerRuntime::errorAndReset()
{
    auto *faulty = static_cast<Faulty *>(create("Faulty", "F1"));
    QVERIFY(faulty);
    RTC::RTObject_var rtc = faulty->reference();
    RTC::ExecutionContext_var ec = ownedContext(rtc);
    QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    faulty->failExecute = true;
    QTRY_COMPARE(ec->get_component_state(rtc), RTC::ERROR_STATE);
    faulty->failReset = true;
    QCOMPARE(ec->reset_component(rtc), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(rtc), RTC::ERROR_STATE);
    faulty->failReset = false;
    faulty->failExecute = false;
    QCOMPARE(ec->reset_component(rtc), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(rtc), RTC::INACTIVE_STATE);
    QCOMPARE(ec->reset_component(rtc), RTC::PRECONDITION_NOT_MET);
}

/// Threads of this process now.
int threadCount()
{
    return int(QDir(QStringLiteral("/proc/self/task")).entryList(QDir::Dirs | QDir::NoDotAndDotDot).size());
}

void TestManagerRuntime::contextThreadStartsWithWork()
{
    // Components that were only created run their contexts without a thread each: a manager
    // hosting many inactive components holds no thread per component.
    const int before = threadCount();
    std::vector<RTC::RTObject_var> components;
    for (int i = 0; i < 5; ++i) {
        RtObject *component = create("ConsoleOut", QStringLiteral("Idle%1").arg(i));
        QVERIFY(component);
        components.push_back(component->reference());
    }
    QCOMPARE(threadCount(), before);
    RTC::ExecutionContext_var ec = ownedContext(components.front());
    QVERIFY(ec->is_running());
    QCOMPARE(ec->get_component_state(components.front()), RTC::INACTIVE_STATE);
    // The first request starts the thread, which serves it before activate returns.
    QCOMPARE(ec->activate_component(components.front()), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(components.front()), RTC::ACTIVE_STATE);
    QCOMPARE(threadCount(), before + 1);
    QCOMPARE(ec->deactivate_component(components.front()), RTC::RTC_OK);
    QCOMPARE(ec->activate_component(components.front()), RTC::RTC_OK);
    QCOMPARE(threadCount(), before + 1);
    // A context stopped with an active participant starts its thread again at once.
    QCOMPARE(ec->stop(), RTC::RTC_OK);
    QCOMPARE(threadCount(), before);
    QCOMPARE(ec->start(), RTC::RTC_OK);
    QCOMPARE(threadCount(), before + 1);
    QCOMPARE(ec->deactivate_component(components.front()), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(components.front()), RTC::INACTIVE_STATE);
}

void TestManagerRuntime::rateAndProfile()
{
    RtObject *component = create("ConsoleIn", "CI9");
    QVERIFY(component);
    RTC::RTObject_var rtc = component->reference();
    RTC::ExecutionContext_var ec = ownedContext(rtc);
    QCOMPARE(ec->get_rate(), 500.0);
    QCOMPARE(ec->set_rate(0.0), RTC::BAD_PARAMETER);
    QCOMPARE(ec->set_rate(std::numeric_limits<double>::infinity()), RTC::BAD_PARAMETER);
    QCOMPARE(ec->set_rate(std::nan("")), RTC::BAD_PARAMETER);
    // A period longer than the clock can add (10^300 s) is served as a very long one: transitions
    // are still served at once.
    QCOMPARE(ec->set_rate(1e-300), RTC::RTC_OK);
    QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(rtc), RTC::ACTIVE_STATE);
    QCOMPARE(ec->deactivate_component(rtc), RTC::RTC_OK);
    QCOMPARE(ec->get_component_state(rtc), RTC::INACTIVE_STATE);
    QCOMPARE(ec->set_rate(20.0), RTC::RTC_OK);
    RTC::ExecutionContextService_var service = RTC::ExecutionContextService::_narrow(ec);
    RTC::ExecutionContextProfile_var profile = service->get_profile();
    QCOMPARE(profile->rate, 20.0);
    QCOMPARE(profile->kind, RTC::PERIODIC);
    QVERIFY(profile->owner->_is_equivalent(rtc));
    QCOMPARE(profile->participants.length(), CORBA::ULong(1));

    // A second component joins the first one's context as participant.
    RtObject *other = create("ConsoleOut", "CO9");
    RTC::RTObject_var otherRef = other->reference();
    QCOMPARE(ec->add_component(otherRef), RTC::RTC_OK);
    QCOMPARE(ec->add_component(otherRef), RTC::PRECONDITION_NOT_MET);
    RTC::ExecutionContextList_var joined = otherRef->get_participating_contexts();
    QCOMPARE(joined->length(), CORBA::ULong(1));
    QVERIFY(otherRef->get_context_handle(ec) >= 1000);
    QCOMPARE(otherRef->finalize(), RTC::PRECONDITION_NOT_MET);
    QCOMPARE(ec->remove_component(otherRef), RTC::RTC_OK);
    joined = otherRef->get_participating_contexts();
    QCOMPARE(joined->length(), CORBA::ULong(0));
}

void TestManagerRuntime::configurationSets()
{
    RtObject *component = create("ConfigSample", "CS0", Properties::parseConf("conf.default.int_param1: 77\n"));
    QVERIFY(component);
    RTC::RTObject_var rtc = component->reference();
    SDOPackage::Configuration_var config = rtc->get_configuration();
    SDOPackage::ConfigurationSetList_var sets = config->get_configuration_sets();
    QStringList ids;
    for (CORBA::ULong i = 0; i < sets->length(); ++i)
        ids << QString::fromUtf8(sets[i].id.in());
    QCOMPARE(ids, QStringList({"__constraints__", "__widget__", "default", "mode0", "mode1"}));
    SDOPackage::ConfigurationSet_var active = config->get_active_configuration_set();
    QCOMPARE(QByteArray(active->id), QByteArray("default"));
    QCOMPARE(nv(active->configuration_data, "int_param1"), QString("77"));
    QCOMPARE(statusOf(rtc, "int_param1"), QString("77"));
    SDOPackage::ConfigurationSet_var widget = config->get_configuration_set("__widget__");
    QCOMPARE(nv(widget->configuration_data, "int_param0"), QString("slider.10"));

    // Activation reaches the variables in the EC thread once the component runs.
    RTC::ExecutionContext_var ec = ownedContext(rtc);
    QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    QVERIFY(config->activate_configuration_set("mode0"));
    QTRY_COMPARE(statusOf(rtc, "int_param0"), QString("12345"));
    QCOMPARE(statusOf(rtc, "str_param0"), QString("mode0"));

    SDOPackage::ConfigurationSet edit;
    edit.id = "mode0";
    edit.description = "";
    setNv(edit.configuration_data, "int_param0", "42");
    QVERIFY(config->set_configuration_set_values(edit));
    // As in OpenRTM-aist: after a write no set is active, and nothing reaches the variables, until
    // a set is activated.
    QVERIFY_THROWS_EXCEPTION(SDOPackage::NotAvailable, config->get_active_configuration_set());
    SDOPackage::ConfigurationSet_var written = config->get_configuration_set("mode0");
    QCOMPARE(nv(written->configuration_data, "int_param0"), QString("42"));
    {
        // The same rule, held still: an update between the write and the activation applies nothing.
        ConfigAdmin admin;
        std::string bound;
        admin.bindParameter("p", "1", [&bound](const std::string &value) {
            bound = value;
            return true;
        });
        admin.update();
        QCOMPARE(bound, std::string("1"));
        QVERIFY(admin.setValues("default", Properties::parseConf("p: 2\n")));
        QVERIFY(!admin.isActive());
        admin.update();
        QCOMPARE(bound, std::string("1"));
        QVERIFY(admin.activate("default"));
        QVERIFY(admin.isActive());
        admin.update();
        QCOMPARE(bound, std::string("2"));
    }
    QVERIFY(config->activate_configuration_set("mode0"));
    QCOMPARE(QByteArray(SDOPackage::ConfigurationSet_var(config->get_active_configuration_set())->id),
             QByteArray("mode0"));
    QTRY_COMPARE(statusOf(rtc, "int_param0"), QString("42"));

    QVERIFY_THROWS_EXCEPTION(SDOPackage::InvalidParameter, config->activate_configuration_set("__widget__"));
    QVERIFY_THROWS_EXCEPTION(SDOPackage::InvalidParameter, config->activate_configuration_set("nope"));
    QVERIFY_THROWS_EXCEPTION(SDOPackage::InvalidParameter, config->remove_configuration_set("mode0"));
    SDOPackage::ConfigurationSet added;
    added.id = "mine";
    added.description = "";
    setNv(added.configuration_data, "int_param0", "5");
    QVERIFY(config->add_configuration_set(added));
    QVERIFY_THROWS_EXCEPTION(SDOPackage::NotAvailable, config->get_active_configuration_set());
    QVERIFY_THROWS_EXCEPTION(SDOPackage::InvalidParameter, config->add_configuration_set(added));
    QVERIFY(config->activate_configuration_set("mode0"));
    QVERIFY(config->remove_configuration_set("mine"));
    QVERIFY_THROWS_EXCEPTION(SDOPackage::NotAvailable, config->get_active_configuration_set());
    QVERIFY(config->activate_configuration_set("mode0"));
}

void TestManagerRuntime::componentProfile()
{
    RtObject *component = create("SeqIn", "SI0");
    QVERIFY(component);
    RTC::RTObject_var rtc = component->reference();
    RTC::ComponentProfile_var profile = rtc->get_component_profile();
    QCOMPARE(QByteArray(profile->instance_name), QByteArray("SI0"));
    QCOMPARE(QByteArray(profile->type_name), QByteArray("SeqIn"));
    QCOMPARE(QByteArray(profile->vendor), QByteArray("AIST"));
    QCOMPARE(QByteArray(profile->category), QByteArray("example"));
    QCOMPARE(profile->port_profiles.length(), CORBA::ULong(10));
    QCOMPARE(QByteArray(profile->port_profiles[2].name), QByteArray("SI0.Long"));
    QCOMPARE(nv(profile->port_profiles[2].properties, "dataport.data_type"), QString("IDL:RTC/TimedLong:1.0"));
    QCOMPARE(nv(profile->port_profiles[2].properties, "port.port_type"), QString("DataInPort"));
    QVERIFY(profile->port_profiles[2].owner->_is_equivalent(rtc));
    CORBA::String_var id = rtc->get_sdo_id();
    QCOMPARE(QByteArray(id.in()), QByteArray("SI0"));
    QVERIFY(rtc->_is_a("IDL:openrtm.aist.go.jp/OpenRTM/DataFlowComponent:1.0"));
    QVERIFY_THROWS_EXCEPTION(SDOPackage::InterfaceNotImplemented, rtc->get_monitoring());
    QVERIFY_THROWS_EXCEPTION(SDOPackage::InvalidParameter, rtc->get_status("nothing"));
}

void TestManagerRuntime::dataFlow_data()
{
    QTest::addColumn<QString>("flow");
    QTest::addColumn<QString>("subscription");
    QTest::addColumn<QString>("endian");
    QTest::addColumn<bool>("inFirst");
    QTest::newRow("push flush") << "push" << "flush" << "little" << false;
    QTest::newRow("push new") << "push" << "new" << "little" << false;
    QTest::newRow("push periodic") << "push" << "periodic" << "little" << false;
    QTest::newRow("push flush big endian") << "push" << "flush" << "big" << false;
    QTest::newRow("push flush, inport first") << "push" << "flush" << "little" << true;
    // OpenRTM-aist 2.x's other names for flush and new.
    QTest::newRow("push block") << "push"
                                << "block"
                                << "little" << false;
    QTest::newRow("push nonblock") << "push"
                                   << "nonblock"
                                   << "little" << false;
    QTest::newRow("pull") << "pull" << "" << "little" << false;
    QTest::newRow("pull, inport first") << "pull" << "" << "big" << true;
}

void TestManagerRuntime::dataFlow()
{
    QFETCH(QString, flow);
    QFETCH(QString, subscription);
    QFETCH(QString, endian);
    QFETCH(bool, inFirst);
    auto [in, out, outPort, inPort] = consolePair("CI0", "CO0");
    Properties p;
    p.set("dataport.interface_type", "corba_cdr");
    p.set("dataport.dataflow_type", flow.toStdString());
    if (!subscription.isEmpty())
        p.set("dataport.subscription_type", subscription.toStdString());
    p.set("dataport.data_type", "IDL:RTC/TimedLong:1.0");
    p.set("dataport.serializer.cdr.endian", endian.toStdString());
    p.set("dataport.publisher.push_rate", "200");
    RTC::ConnectorProfile profile;
    QCOMPARE(inFirst ? connect(inPort, outPort, p, &profile) : connect(outPort, inPort, p, &profile), RTC::RTC_OK);
    QVERIFY(!QByteArray(profile.connector_id).isEmpty());
    const char *iorKey = flow == "push" ? "dataport.corba_cdr.inport_ior" : "dataport.corba_cdr.outport_ior";
    QVERIFY(nv(profile.properties, iorKey).startsWith("IOR:"));
    // As OpenRTM's ports, the offering port also passes its interface as a reference (`…_ref`).
    CORBA::Object_var offered = m_orb->string_to_object(nv(profile.properties, iorKey).toUtf8());
    CORBA::Object_var passed = flow == "push"
        ? CORBA::Object_var(
            nvReference<OpenRTM::InPortCdr>(profile.properties, "dataport.corba_cdr.inport_ref")
                ._retn())
        : CORBA::Object_var(
            nvReference<OpenRTM::OutPortCdr>(profile.properties, "dataport.corba_cdr.outport_ref")
                ._retn());
    QVERIFY(!CORBA::is_nil(passed));
    QVERIFY(passed->_is_equivalent(offered));
    RTC::ConnectorProfileList_var onOut = outPort->get_connector_profiles();
    RTC::ConnectorProfileList_var onIn = inPort->get_connector_profiles();
    QCOMPARE(onOut->length(), CORBA::ULong(1));
    QCOMPARE(onIn->length(), CORBA::ULong(1));
    QCOMPARE(QByteArray(onOut[0].connector_id), QByteArray(profile.connector_id));

    RTC::ExecutionContext_var sourceEc = ownedContext(in);
    RTC::ExecutionContext_var sinkEc = ownedContext(out);
    QCOMPARE(sinkEc->activate_component(out), RTC::RTC_OK);
    QCOMPARE(sourceEc->activate_component(in), RTC::RTC_OK);
    QTRY_VERIFY(statusNumber(out, "received_count") > 20);
    // What arrives is the counter itself, in increasing order, whatever the byte order.
    const QStringList values = statusOf(out, "received_values").split(',');
    QVERIFY(values.size() >= 2);
    QVERIFY(values.last().toLong() > 0);
    QVERIFY(values.last().toLong() <= statusNumber(in, "sent_count"));
    QVERIFY(values.first().toLong() <= values.last().toLong());
}

void TestManagerRuntime::disconnectStopsFlow()
{
    auto [in, out, outPort, inPort] = consolePair("CI1", "CO1");
    RTC::ConnectorProfile profile;
    QCOMPARE(connect(outPort, inPort, Properties::parseConf("dataport.dataflow_type: push\n"), &profile),
             RTC::RTC_OK);
    // The same id twice is refused, with OpenRTM-aist's code.
    RTC::ConnectorProfile again = profile;
    QCOMPARE(outPort->connect(again), RTC::PRECONDITION_NOT_MET);
    RTC::ExecutionContext_var sourceEc = ownedContext(in);
    RTC::ExecutionContext_var sinkEc = ownedContext(out);
    sinkEc->activate_component(out);
    sourceEc->activate_component(in);
    QTRY_VERIFY(statusNumber(out, "received_count") > 5);
    QCOMPARE(inPort->disconnect(profile.connector_id), RTC::RTC_OK);
    RTC::ConnectorProfileList_var onOut = outPort->get_connector_profiles();
    RTC::ConnectorProfileList_var onIn = inPort->get_connector_profiles();
    QCOMPARE(onOut->length(), CORBA::ULong(0));
    QCOMPARE(onIn->length(), CORBA::ULong(0));
    QCOMPARE(inPort->disconnect(profile.connector_id), RTC::BAD_PARAMETER);
    const long sent = statusNumber(in, "sent_count");
    QTRY_VERIFY(statusNumber(in, "sent_count") > sent + 20);
    const long received = statusNumber(out, "received_count");
    QTRY_VERIFY(statusNumber(in, "sent_count") > sent + 40);
    QCOMPARE(statusNumber(out, "received_count"), received);
}

// on_initialize() is an operation any peer may call: the component's onInitialize() runs again, and
// its ports must neither pile up (a name is listed once, as in OpenRTM-aist) nor stop working.
void TestManagerRuntime::onInitializeAgainKeepsPorts()
{
    auto [in, out, outPort, inPort] = consolePair("CI2", "CO2");
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(in->on_initialize(), RTC::RTC_OK);
        QCOMPARE(out->on_initialize(), RTC::RTC_OK);
    }
    for (RTC::RTObject_ptr rtc : {in.in(), out.in()}) {
        RTC::PortServiceList_var ports = rtc->get_ports();
        QCOMPARE(ports->length(), CORBA::ULong(1));
        RTC::ComponentProfile_var profile = rtc->get_component_profile();
        QCOMPARE(profile->port_profiles.length(), CORBA::ULong(1));
    }
    // The ports the components write and read are still the listed ones.
    QCOMPARE(connect(outPort, inPort, Properties::parseConf("dataport.dataflow_type: push\n")), RTC::RTC_OK);
    RTC::ExecutionContext_var sourceEc = ownedContext(in);
    RTC::ExecutionContext_var sinkEc = ownedContext(out);
    sinkEc->activate_component(out);
    sourceEc->activate_component(in);
    QTRY_VERIFY(statusNumber(out, "received_count") > 5);

    // A port of a listed name is refused; one of another type under that name is not handed out.
    auto *component = dynamic_cast<Faulty *>(create("Faulty", "F2"));
    QVERIFY(component);
    InPort<RTC::TimedLong> *first = component->addInPort<RTC::TimedLong>("extra");
    QVERIFY(first);
    QCOMPARE(component->addInPort<RTC::TimedLong>("extra"), first);
    QCOMPARE(component->addOutPort<RTC::TimedLong>("extra"), static_cast<OutPort<RTC::TimedLong> *>(nullptr));
    QCOMPARE(component->findPort("extra"), static_cast<PortBase *>(first));
    RTC::RTObject_var reference = component->reference();
    RTC::PortServiceList_var ports = reference->get_ports();
    QCOMPARE(ports->length(), CORBA::ULong(1));
}

void TestManagerRuntime::connectorBufferPolicy()
{
    auto [in, out, outPort, inPort] = consolePair("CI3", "CO3");
    RTC::ConnectorProfile profile;
    QCOMPARE(connect(outPort, inPort,
                     Properties::parseConf("dataport.dataflow_type: push\n"
                                           "dataport.inport.buffer.length: 2\n"
                                           "dataport.buffer.write.full_policy: do_nothing\n"),
                     &profile),
             RTC::RTC_OK);
    // Nobody reads (the sink is inactive): the third sample finds the buffer full.
    CORBA::Object_var object = m_orb->string_to_object(nv(profile.properties, "dataport.corba_cdr.inport_ior").toUtf8());
    OpenRTM::InPortCdr_var inCdr = OpenRTM::InPortCdr::_narrow(object);
    QVERIFY(!CORBA::is_nil(inCdr));
    RTC::TimedLong sample{};
    const CdrBytes bytes = marshal(sample, true);
    OpenRTM::CdrData data(CORBA::ULong(bytes.size()), CORBA::ULong(bytes.size()),
                          const_cast<CORBA::Octet *>(bytes.data()), false);
    QCOMPARE(inCdr->put(data), OpenRTM::PORT_OK);
    QCOMPARE(inCdr->put(data), OpenRTM::PORT_OK);
    QCOMPARE(inCdr->put(data), OpenRTM::BUFFER_FULL);
}

void TestManagerRuntime::connectRejectsMismatch_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");
    QTest::newRow("data type") << "dataport.data_type" << "IDL:RTC/TimedDouble:1.0";
    QTest::newRow("interface") << "dataport.interface_type" << "shared_memory";
    QTest::newRow("flow") << "dataport.dataflow_type" << "sideways";
    QTest::newRow("subscription") << "dataport.subscription_type" << "sometimes";
}

void TestManagerRuntime::connectRejectsMismatch()
{
    QFETCH(QString, key);
    QFETCH(QString, value);
    auto [in, out, outPort, inPort] = consolePair("CI2", "CO2");
    Properties p;
    p.set(key.toStdString(), value.toStdString());
    QCOMPARE(connect(outPort, inPort, p), RTC::BAD_PARAMETER);
    RTC::ConnectorProfileList_var onOut = outPort->get_connector_profiles();
    RTC::ConnectorProfileList_var onIn = inPort->get_connector_profiles();
    QCOMPARE(onOut->length(), CORBA::ULong(0));
    QCOMPARE(onIn->length(), CORBA::ULong(0));
    // A bare OpenRTM 1.x type name still matches.
    p = Properties();
    p.set("dataport.data_type", "TimedLong");
    QCOMPARE(connect(outPort, inPort, p), RTC::RTC_OK);
}

void TestManagerRuntime::marshalingTypeNeedsASerializer()
{
    // OpenRTM's user serializers (`inport.marshaling_type=cdr:RTC/TimedLong:RTC/TimedDouble`) let a
    // port read or write another data type. The built-in ports have none: they read and write plain
    // CDR of their own type and refuse any other marshaling type on their side.
    auto [in, out, outPort, inPort] = consolePair("CI4", "CO4");
    Properties p;
    p.set("dataport.data_type", "IDL:RTC/TimedDouble:1.0");
    p.set("dataport.inport.marshaling_type", "cdr");
    QCOMPARE(connect(outPort, inPort, p), RTC::BAD_PARAMETER);
    // A built-in port says on standard error which port refused which connector, and why.
    std::ostringstream said;
    std::streambuf *const standardError = std::cerr.rdbuf(said.rdbuf());
    p.set("dataport.outport.marshaling_type", "cdr:RTC/TimedDouble:RTC/TimedLong");
    const RTC::ReturnCode_t refused = connect(outPort, inPort, p);
    std::cerr.rdbuf(standardError);
    QCOMPARE(refused, RTC::BAD_PARAMETER);
    const QString line = QString::fromStdString(said.str());
    QVERIFY2(line.contains(QLatin1String(": port CI4.out: connector '"))
                 && line.contains(QLatin1String("' refused: no serializer 'cdr:RTC/TimedDouble:RTC/TimedLong' for "
                                                "this OutPort (it writes plain cdr)")),
             qPrintable(line));
    p.remove("dataport.outport.marshaling_type");
    p.set("dataport.outport.marshaling_type", "cdr:RTC/TimedDouble:RTC/TimedLong");
    p.set("dataport.inport.marshaling_type", "cdr:RTC/TimedLong:RTC/TimedDouble");
    QCOMPARE(connect(outPort, inPort, p), RTC::BAD_PARAMETER);
    p.set("dataport.outport.marshaling_type", "cdr");
    QCOMPARE(connect(outPort, inPort, p), RTC::BAD_PARAMETER);
    RTC::ConnectorProfileList_var left = outPort->get_connector_profiles();
    QCOMPARE(left->length(), CORBA::ULong(0));
    p.set("dataport.data_type", "IDL:RTC/TimedLong:1.0");
    p.set("dataport.inport.marshaling_type", " cdr ");
    QCOMPARE(connect(outPort, inPort, p), RTC::RTC_OK);
}

void TestManagerRuntime::connectRefusesNilPeer_data()
{
    QTest::addColumn<QString>("flow");
    QTest::addColumn<QString>("portName");
    QTest::addColumn<QString>("peerKey");
    // The subscribing end of each flow: an InPort pulls from the OutPort's interface, an OutPort
    // pushes into the InPort's.
    QTest::newRow("pull into an InPort") << "pull"
                                         << "in"
                                         << "dataport.corba_cdr.outport_ior";
    QTest::newRow("push from an OutPort") << "push"
                                          << "out"
                                          << "dataport.corba_cdr.inport_ior";
}

void TestManagerRuntime::connectRefusesNilPeer()
{
    QFETCH(QString, flow);
    QFETCH(QString, portName);
    QFETCH(QString, peerKey);
    RtObject *component = create(portName == "in" ? "ConsoleOut" : "ConsoleIn", "NP0");
    RTC::RTObject_var rtc = component->reference();
    RTC::PortService_var subscriber = port(rtc, portName.toUtf8().constData());
    // A peer interface that names no object: the connection is refused, not made to send
    // nowhere.
    CORBA::String_var nil = m_orb->object_to_string(CORBA::Object::_nil());
    RTC::ConnectorProfile profile;
    profile.name = "nil peer";
    profile.connector_id = "";
    profile.ports.length(1);
    profile.ports[0] = RTC::PortService::_duplicate(subscriber);
    setNv(profile.properties, "dataport.dataflow_type", flow.toUtf8().constData());
    setNv(profile.properties, peerKey.toUtf8().constData(), nil.in());
    QCOMPARE(subscriber->connect(profile), RTC::BAD_PARAMETER);
    RTC::ConnectorProfileList_var kept = subscriber->get_connector_profiles();
    QCOMPARE(kept->length(), CORBA::ULong(0));
}

void TestManagerRuntime::failedConnectLeavesNothingBehind_data()
{
    QTest::addColumn<int>("ending");
    QTest::newRow("refused after keeping it") << int(KeepingPort::Refuse);
    QTest::newRow("answer timed out") << int(KeepingPort::TimeOut);
}

void TestManagerRuntime::failedConnectLeavesNothingBehind()
{
    QFETCH(int, ending);
    RtObject *source = create("ConsoleIn", "HALF0");
    RTC::RTObject_var rtc = source->reference();
    RTC::PortService_var outPort = port(rtc, "out");
    auto *keeper = new KeepingPort(KeepingPort::Ending(ending));
    PortableServer::ObjectId_var id = m_poa->activate_object(keeper);
    RTC::PortService_var far = keeper->_this();
    RTC::ConnectorProfile made;
    QCOMPARE(connect(outPort, far, Properties(), &made), RTC::RTC_ERROR);
    // The far port was told to drop what it kept, and the near one holds nothing.
    QCOMPARE(keeper->toldToDrop, QStringList(QString::fromUtf8(made.connector_id.in())));
    QVERIFY(keeper->held.isEmpty());
    RTC::ConnectorProfileList_var onOut = outPort->get_connector_profiles();
    QCOMPARE(onOut->length(), CORBA::ULong(0));
    m_poa->deactivate_object(id);
    keeper->_remove_ref();
}

void TestManagerRuntime::duplicateConnectionRefused()
{
    auto [in, out, outPort, inPort] = consolePair("DUP0", "DUP1");
    QCOMPARE(connect(outPort, inPort, Properties()), RTC::RTC_OK);
    // As OpenRTM-aist's ports: a second connection between the same ports is refused, from
    // either end, and leaves nothing behind.
    QCOMPARE(connect(outPort, inPort, Properties()), RTC::PRECONDITION_NOT_MET);
    QCOMPARE(connect(inPort, outPort, Properties()), RTC::PRECONDITION_NOT_MET);
    RTC::ConnectorProfileList_var onOut = outPort->get_connector_profiles();
    RTC::ConnectorProfileList_var onIn = inPort->get_connector_profiles();
    QCOMPARE(onOut->length(), CORBA::ULong(1));
    QCOMPARE(onIn->length(), CORBA::ULong(1));
    // ... unless the connector allows it.
    QCOMPARE(
        connect(outPort, inPort, Properties::parseConf("dataport.allow_dup_connection: YES\n")),
        RTC::RTC_OK);
    onOut = outPort->get_connector_profiles();
    onIn = inPort->get_connector_profiles();
    QCOMPARE(onOut->length(), CORBA::ULong(2));
    QCOMPARE(onIn->length(), CORBA::ULong(2));
}

void TestManagerRuntime::inPortTakesAnySubscription()
{
    RtObject *sink = create("ConsoleOut", "ANY0");
    RTC::RTObject_var out = sink->reference();
    RTC::PortService_var inPort = port(out, "in");
    RTC::PortProfile_var profile = inPort->get_port_profile();
    QCOMPARE(nv(profile->properties, "dataport.subscription_type"), QString("Any"));
    QCOMPARE(nv(profile->properties, "dataport.marshaling_types"), QString("cdr"));
    // How an OutPort sends is its own business: an InPort takes the push connector of an
    // OpenRTM-aist OutPort whose subscription type rtmanager's OutPorts do not offer.
    RTC::ConnectorProfile connector;
    connector.name = "from a blocking publisher";
    connector.connector_id = "";
    connector.ports.length(1);
    connector.ports[0] = RTC::PortService::_duplicate(inPort);
    setNv(connector.properties, "dataport.dataflow_type", "push");
    setNv(connector.properties, "dataport.subscription_type", "block");
    QCOMPARE(inPort->connect(connector), RTC::RTC_OK);
    QVERIFY(nv(connector.properties, "dataport.corba_cdr.inport_ior").startsWith("IOR:"));
}

void TestManagerRuntime::seqInReadsEveryFlow_data()
{
    QTest::addColumn<QString>("flow");
    QTest::newRow("push") << "push";
    QTest::newRow("pull") << "pull";
}

// The SeqIn twin reads every cycle, as OpenRTM-aist's SeqIn does: a pull connector, which never
// has a sample waiting, is asked on read.
void TestManagerRuntime::seqInReadsEveryFlow()
{
    QFETCH(QString, flow);
    RtObject *source = create("SeqOut", "SO" + flow.toUtf8());
    RtObject *sink = create("SeqIn", "SI" + flow.toUtf8());
    RTC::RTObject_var out = source->reference();
    RTC::RTObject_var in = sink->reference();
    Properties p;
    p.set("dataport.dataflow_type", flow.toStdString());
    RTC::PortService_var outPort = port(out, "Long");
    RTC::PortService_var inPort = port(in, "Long");
    QCOMPARE(connect(outPort, inPort, p), RTC::RTC_OK);
    RTC::ExecutionContext_var sourceEc = ownedContext(out);
    RTC::ExecutionContext_var sinkEc = ownedContext(in);
    QCOMPARE(sourceEc->activate_component(out), RTC::RTC_OK);
    QCOMPARE(sinkEc->activate_component(in), RTC::RTC_OK);
    QTRY_VERIFY(statusNumber(in, "Long_count") > 5);
}

void TestManagerRuntime::connectionLimits_data()
{
    QTest::addColumn<bool>("inPortLimit");
    QTest::newRow("fan_out: one OutPort, two InPorts") << false;
    QTest::newRow("fan_in: two OutPorts, one InPort") << true;
}

void TestManagerRuntime::connectionLimits()
{
    QFETCH(bool, inPortLimit);
    const QByteArray shared = inPortLimit ? "FANIN" : "FANOUT";
    RtObject *hub = create(inPortLimit ? "ConsoleOut" : "ConsoleIn", shared + "0");
    RTC::RTObject_var hubRef = hub->reference();
    RTC::PortService_var hubPort = port(hubRef, inPortLimit ? "in" : "out");
    std::vector<RTC::PortService_var> peers;
    for (const char *suffix : {"A", "B", "C"}) {
        RtObject *peer
            = create(inPortLimit ? "ConsoleIn" : "ConsoleOut", (shared + suffix).constData());
        RTC::RTObject_var peerRef = peer->reference();
        peers.push_back(port(peerRef, inPortLimit ? "out" : "in"));
    }
    const Properties limited = Properties::parseConf(inPortLimit ? "dataport.inport.fan_in: 1\n"
                                                                 : "dataport.outport.fan_out: 1\n");
    const auto connectPeer = [&](const RTC::PortService_var &peer, const Properties &p) {
        return inPortLimit ? connect(peer, hubPort, p) : connect(hubPort, peer, p);
    };
    QCOMPARE(connectPeer(peers[0], limited), RTC::RTC_OK);
    // A connector that allows one connection of the shared port finds it taken.
    QCOMPARE(connectPeer(peers[1], limited), RTC::PRECONDITION_NOT_MET);
    RTC::ConnectorProfileList_var held = hubPort->get_connector_profiles();
    QCOMPARE(held->length(), CORBA::ULong(1));
    RTC::ConnectorProfileList_var onRefused = peers[1]->get_connector_profiles();
    QCOMPARE(onRefused->length(), CORBA::ULong(0));
    // Without a limit of its own, OpenRTM's default of 100 applies.
    QCOMPARE(connectPeer(peers[2], Properties()), RTC::RTC_OK);
    held = hubPort->get_connector_profiles();
    QCOMPARE(held->length(), CORBA::ULong(2));
}

void TestManagerRuntime::sameDataType_data()
{
    // OpenRTM-aist 1.x saves the short forms; 2.x and our ports use repository ids.
    QTest::addColumn<QString>("a");
    QTest::addColumn<QString>("b");
    QTest::addColumn<bool>("same");
    QTest::newRow("bare name") << "TimedFloat" << "IDL:RTC/TimedFloat:1.0" << true;
    QTest::newRow("scoped name") << "RTC::TimedFloat" << "IDL:RTC/TimedFloat:1.0" << true;
    QTest::newRow("repository id") << "IDL:RTC/TimedFloat:1.0" << "IDL:RTC/TimedFloat:1.0" << true;
    QTest::newRow("bare and scoped") << "TimedFloat" << "RTC::TimedFloat" << true;
    QTest::newRow("other version") << "IDL:RTC/TimedFloat:1.1" << "RTC::TimedFloat" << true;
    QTest::newRow("nested module") << "IDL:Ext/Sub/Pose:1.0" << "Ext::Sub::Pose" << true;
    QTest::newRow("bare, other type") << "TimedLong" << "IDL:RTC/TimedFloat:1.0" << false;
    QTest::newRow("scoped, other type") << "RTC::TimedLong" << "IDL:RTC/TimedFloat:1.0" << false;
    QTest::newRow("sequence of it") << "TimedFloatSeq" << "IDL:RTC/TimedFloat:1.0" << false;
    QTest::newRow("other module") << "Ext::TimedFloat" << "IDL:RTC/TimedFloat:1.0" << false;
    QTest::newRow("other module, ids") << "IDL:Ext/TimedFloat:1.0" << "IDL:RTC/TimedFloat:1.0" << false;
}

void TestManagerRuntime::sameDataType()
{
    QFETCH(QString, a);
    QFETCH(QString, b);
    QFETCH(bool, same);
    QCOMPARE(Runtime::sameDataType(a.toStdString(), b.toStdString()), same);
    QCOMPARE(Runtime::sameDataType(b.toStdString(), a.toStdString()), same);
}

void TestManagerRuntime::connectDataTypeSpellings_data()
{
    QTest::addColumn<QString>("dataType");
    QTest::addColumn<bool>("accepted");
    QTest::newRow("bare") << "TimedFloat" << true;
    QTest::newRow("scoped") << "RTC::TimedFloat" << true;
    QTest::newRow("repository id") << "IDL:RTC/TimedFloat:1.0" << true;
    QTest::newRow("bare, other type") << "TimedLong" << false;
    QTest::newRow("repository id, other type") << "IDL:RTC/TimedLong:1.0" << false;
    QTest::newRow("other module") << "Ext::TimedFloat" << false;
}

// Sensor.out and Controller.in carry RTC::TimedFloat: every spelling of it connects, others do not.
void TestManagerRuntime::connectDataTypeSpellings()
{
    QFETCH(QString, dataType);
    QFETCH(bool, accepted);
    RtObject *sensor = create("Sensor", "S5");
    RtObject *controller = create("Controller", "C5");
    RTC::RTObject_var s = sensor->reference();
    RTC::RTObject_var c = controller->reference();
    RTC::PortService_var outPort = port(s, "out");
    RTC::PortService_var inPort = port(c, "in");
    Properties p;
    p.set("dataport.data_type", dataType.toStdString());
    QCOMPARE(connect(outPort, inPort, p), accepted ? RTC::RTC_OK : RTC::BAD_PARAMETER);
    RTC::ConnectorProfileList_var onIn = inPort->get_connector_profiles();
    QCOMPARE(onIn->length(), CORBA::ULong(accepted ? 1 : 0));
}

// ConsoleIn → Sensor (TimedLong → TimedFloat) → Controller → Motor (TimedFloat → TimedLong, plus
// motor_id) → ConsoleOut: the values arrive converted and shifted by the motor's id.
void TestManagerRuntime::controlLoop()
{
    RtObject *source = create("ConsoleIn", "CI7");
    RtObject *sensor = create("Sensor", "S7");
    RtObject *controller = create("Controller", "C7");
    RtObject *motor = create("Motor", "M7", Properties::parseConf("conf.default.motor_id: 1000\n"));
    RtObject *sink = create("ConsoleOut", "CO7");
    QVERIFY(source && sensor && controller && motor && sink);
    const std::vector<RtObject *> chain {source, sensor, controller, motor, sink};
    for (size_t i = 0; i + 1 < chain.size(); ++i) {
        RTC::RTObject_var from = chain[i]->reference();
        RTC::RTObject_var to = chain[i + 1]->reference();
        RTC::PortService_var out = port(from, "out");
        RTC::PortService_var in = port(to, "in");
        QCOMPARE(connect(out, in, {}), RTC::RTC_OK);
    }
    for (RtObject *component : chain) {
        RTC::RTObject_var rtc = component->reference();
        RTC::ExecutionContext_var ec = ownedContext(rtc);
        QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    }
    RTC::RTObject_var out = sink->reference();
    RTC::RTObject_var in = source->reference();
    RTC::RTObject_var s = sensor->reference();
    QTRY_VERIFY(statusNumber(out, "received_count") > 5);
    const long last = statusNumber(out, "last_value");
    QVERIFY2(last > 1000 && last <= 1000 + statusNumber(in, "sent_count"), qPrintable(QString::number(last)));
    // Sensor reports what it sent as a float: whole numbers without a fraction.
    QVERIFY(!statusOf(s, "last_value").contains('.'));
}

void TestManagerRuntime::servicePort()
{
    RtObject *provider = create("MyServiceProvider", "P0");
    RtObject *consumer = create("MyServiceConsumer", "C0");
    RTC::RTObject_var p = provider->reference();
    RTC::RTObject_var c = consumer->reference();
    RTC::PortService_var pPort = port(p, "MyService");
    RTC::PortService_var cPort = port(c, "MyService");
    RTC::PortProfile_var profile = pPort->get_port_profile();
    QCOMPARE(profile->interfaces.length(), CORBA::ULong(1));
    QCOMPARE(QByteArray(profile->interfaces[0].instance_name), QByteArray("myservice"));
    QCOMPARE(QByteArray(profile->interfaces[0].type_name), QByteArray("SimpleService::MyService"));
    QCOMPARE(profile->interfaces[0].polarity, RTC::PROVIDED);
    RTC::ConnectorProfile connected;
    QCOMPARE(connect(cPort, pPort, {}, &connected), RTC::RTC_OK);
    // A service port, too, refuses a second connection to the same port (as OpenRTM-aist's).
    QCOMPARE(connect(pPort, cPort, {}), RTC::PRECONDITION_NOT_MET);
    const QString ior = nv(connected.properties, "port.SimpleService::MyService.myservice");
    QVERIFY(ior.startsWith("IOR:"));
    CORBA::Object_var service = m_orb->string_to_object(ior.toLatin1().constData());
    RTC::ExecutionContext_var ec = ownedContext(c);
    QCOMPARE(ec->activate_component(c), RTC::RTC_OK);

    // As with OpenRTM-aist, the provider's object answers only while its component is active.
    QVERIFY(service->_non_existent());
    QTRY_COMPARE(statusOf(c, "last_error"), QString("provider unreachable"));
    QCOMPARE(statusOf(c, "echo_count"), QString());
    RTC::ExecutionContext_var providerEc = ownedContext(p);
    QCOMPARE(providerEc->activate_component(p), RTC::RTC_OK);
    QTRY_VERIFY(statusNumber(c, "echo_count") >= 3);
    QVERIFY(statusOf(c, "last_reply").startsWith("echo "));
    QVERIFY(!service->_non_existent());

    // Deactivated, it is gone again until the next activation, under the same reference.
    QCOMPARE(providerEc->deactivate_component(p), RTC::RTC_OK);
    QTRY_VERIFY(service->_non_existent());
    const long answered = statusNumber(c, "echo_count");
    QTRY_VERIFY(statusNumber(c, "echo_count") == answered && service->_non_existent());
    QCOMPARE(providerEc->activate_component(p), RTC::RTC_OK);
    QTRY_VERIFY(statusNumber(c, "echo_count") > answered + 1);
}

QTEST_GUILESS_MAIN(TestManagerRuntime)
#include "tst_managerruntime.moc"
