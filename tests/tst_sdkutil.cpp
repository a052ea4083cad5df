// SPDX-License-Identifier: MIT
// OpenRTM-aist's utility headers on the component SDK: name/value lists, sequence helpers, type
// names and IORs in process; CORBA_RTCUtil against live components of an in-process manager, and
// CorbaNaming against a real omniNames.
#include "sdkinprocess.h"

#include <rtm/ByteDataStreamBase.h>
#include <rtm/CORBA_CdrMemoryStream.h>
#include <rtm/CORBA_IORUtil.h>
#include <rtm/CORBA_RTCUtil.h>
#include <rtm/CORBA_SeqUtil.h>
#include <rtm/CorbaNaming.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>
#include <rtm/Manager.h>
#include <rtm/NVUtil.h>
#include <rtm/RTCUtil.h>
#include <rtm/Typename.h>
#include <rtm/idl/BasicDataTypeUtil.h>

#include <SimpleService.hh>

#include "livesystem.h"

#include <QtTest>

#include <atomic>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

const char *const sourceSpec[] = {"implementation_id",
                                  "UtilSource",
                                  "type_name",
                                  "UtilSource",
                                  "description",
                                  "counter",
                                  "version",
                                  "1.0.0",
                                  "vendor",
                                  "RTStudioTests",
                                  "category",
                                  "utiltest",
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
                                  "conf.default.step",
                                  "1",
                                  "conf.default.fail",
                                  "0",
                                  "conf.fast.step",
                                  "10",
                                  "conf.fast.fail",
                                  "0",
                                  "exec_cxt.periodic.rate",
                                  "100",
                                  ""};

/// Counts up on "out"; fails in onExecute while its parameter "fail" is not 0.
class UtilSource : public RTC::DataFlowComponentBase
{
public:
    explicit UtilSource(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_outOut("out", m_out)
        , m_servicePort("Service")
    { }
    RTC::ReturnCode_t onInitialize() override
    {
        m_out.data = 0;
        addOutPort("out", m_outOut);
        m_servicePort.registerConsumer("myservice", "SimpleService::MyService", m_service);
        addPort(m_servicePort);
        bindParameter("step", m_step, "1");
        bindParameter("fail", m_fail, "0");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        if (m_fail != 0)
            return RTC::RTC_ERROR;
        seenStep = m_step;
        m_out.data += m_step;
        m_outOut.write();
        return RTC::RTC_OK;
    }

    std::atomic<int> seenStep {0};

private:
    int m_step = 1;
    RTC::TimedLong m_out;
    RTC::OutPort<RTC::TimedLong> m_outOut;
    RTC::CorbaPort m_servicePort;
    RTC::CorbaConsumer<SimpleService::MyService> m_service;
    int m_fail = 0;
};

const char *const sinkSpec[] = {"implementation_id",
                                "UtilSink",
                                "type_name",
                                "UtilSink",
                                "version",
                                "1.0.0",
                                "vendor",
                                "RTStudioTests",
                                "category",
                                "utiltest",
                                "language",
                                "C++",
                                "exec_cxt.periodic.rate",
                                "100",
                                ""};

class UtilSink : public RTC::DataFlowComponentBase
{
public:
    explicit UtilSink(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_inIn("in", m_in)
    { }
    RTC::ReturnCode_t onInitialize() override
    {
        addInPort("in", m_inIn);
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        while (m_inIn.isNew()) {
            m_inIn.read();
            ++received;
        }
        return RTC::RTC_OK;
    }

    std::atomic<int> received {0};

private:
    RTC::TimedLong m_in;
    RTC::InPort<RTC::TimedLong> m_inIn;
};

SDOPackage::NVList makeList(std::initializer_list<std::pair<const char *, const char *>> entries)
{
    SDOPackage::NVList list;
    for (const auto &entry : entries)
        CORBA_SeqUtil::push_back(list, NVUtil::newNV(entry.first, entry.second));
    return list;
}

bool contains(const coil::vstring &list, const std::string &value)
{
    return std::find(list.begin(), list.end(), value) != list.end();
}

/// The name server at `address`, once its root context answers: omniNames accepts connections a
/// moment before it serves its objects.
std::unique_ptr<RTC::CorbaNaming> connectNaming(CORBA::ORB_ptr orb, const std::string &address)
{
    QDeadlineTimer deadline(10000);
    for (;;) {
        try {
            return std::unique_ptr<RTC::CorbaNaming>(new RTC::CorbaNaming(orb, address.c_str()));
        } catch (const std::bad_alloc &) {
            if (deadline.hasExpired())
                return nullptr;
            QTest::qWait(20);
        }
    }
}

struct Sum
{
    long total = 0;
    void operator()(CORBA::Long value) { total += value; }
};

} // namespace

class TestSdkUtil : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();

    void nvListsAndProperties();
    void nvStringValues();
    void nvDump();
    void sequenceHelpers();
    void typeNames();
    void cdrSerializers();
    void serializerRegistry();
    void iorDecodeAndEncode();
    void corbaUris_data();
    void corbaUris();
    void rtcUris();
    void componentKinds();
    void lifeCycleThroughContexts();
    void ratesAndParticipants();
    void portNamesAndConnections();
    void configurationSets();
    void namingBindAndResolve();
    void namingStringNames();
    void portsByUrl();

private:
    UtilSource *createSource();
    UtilSink *createSink();

    RTC::Manager *m_manager = nullptr;
    std::vector<RTC::RTObject_impl *> m_created;
};

void TestSdkUtil::initTestCase()
{
    m_manager = SdkTest::startInProcessManager("tst_sdkutil");
    QVERIFY(m_manager != nullptr);
    coil::Properties source(sourceSpec), sink(sinkSpec);
    QVERIFY(m_manager->registerFactory(source, RTC::Create<UtilSource>, RTC::Delete<UtilSource>));
    QVERIFY(m_manager->registerFactory(sink, RTC::Create<UtilSink>, RTC::Delete<UtilSink>));
}

void TestSdkUtil::cleanupTestCase()
{
    QVERIFY(SdkTest::stopInProcessManager(m_manager));
}

void TestSdkUtil::init()
{
    // Each test starts without the components of the one before.
    for (RTC::RTObject_impl *component : m_manager->getComponents())
        m_manager->deleteComponent(component);
    QTRY_VERIFY_WITH_TIMEOUT(m_manager->getComponents().empty(), 5000);
}

UtilSource *TestSdkUtil::createSource()
{
    return dynamic_cast<UtilSource *>(m_manager->createComponent("UtilSource"));
}

UtilSink *TestSdkUtil::createSink()
{
    return dynamic_cast<UtilSink *>(m_manager->createComponent("UtilSink"));
}

void TestSdkUtil::nvListsAndProperties()
{
    coil::Properties prop;
    prop.setProperty("dataport.interface_type", "corba_cdr");
    prop.setProperty("dataport.dataflow_type", "push");
    SDOPackage::NVList list;
    NVUtil::copyFromProperties(list, prop);
    QCOMPARE(list.length(), CORBA::ULong(2));
    QCOMPARE(NVUtil::find_index(list, "dataport.dataflow_type") >= 0, true);
    QCOMPARE(NVUtil::toString(list, "dataport.interface_type"), std::string("corba_cdr"));

    coil::Properties back = NVUtil::toProperties(list);
    QCOMPARE(back.getProperty("dataport.dataflow_type"), std::string("push"));
    coil::Properties into;
    into.setProperty("kept", "yes");
    NVUtil::copyToProperties(into, list);
    QCOMPARE(into.getProperty("kept"), std::string("yes"));
    QCOMPARE(into.getProperty("dataport.interface_type"), std::string("corba_cdr"));

    // Non-string values are skipped, not converted.
    CORBA_SeqUtil::push_back(list, NVUtil::newNV("number", CORBA::Long(5)));
    QVERIFY(!NVUtil::toProperties(list).hasKey("number"));

    // merge: the properties' keys replace, the others stay.
    coil::Properties update;
    update.setProperty("dataport.dataflow_type", "pull");
    NVUtil::mergeFromProperties(list, update);
    QCOMPARE(list.length(), CORBA::ULong(3));
    QCOMPARE(NVUtil::toString(list, "dataport.dataflow_type"), std::string("pull"));
    QCOMPARE(NVUtil::toString(list, "dataport.interface_type"), std::string("corba_cdr"));

    SDOPackage::NVList more = makeList({{"a", "1"}, {"b", "2"}});
    NVUtil::append(list, more);
    QCOMPARE(list.length(), CORBA::ULong(5));
    QCOMPARE(NVUtil::toString(list, "b"), std::string("2"));

    const SDOPackage::NameValue flag = NVUtil::newNVBool("flag", true);
    CORBA::Boolean flagValue = false;
    QVERIFY(flag.value >>= CORBA::Any::to_boolean(flagValue));
    QVERIFY(flagValue);
    const SDOPackage::NameValue octet = NVUtil::newNVOctet("octet", 7);
    CORBA::Octet octetValue = 0;
    QVERIFY(octet.value >>= CORBA::Any::to_octet(octetValue));
    QCOMPARE(int(octetValue), 7);
    const SDOPackage::NameValue character = NVUtil::newNVChar("char", 'x');
    CORBA::Char charValue = 0;
    QVERIFY(character.value >>= CORBA::Any::to_char(charValue));
    QCOMPARE(charValue, 'x');
    const SDOPackage::NameValue copied = NVUtil::newNVAny("any", octet.value);
    QVERIFY(copied.value >>= CORBA::Any::to_octet(octetValue));
}

void TestSdkUtil::nvStringValues()
{
    SDOPackage::NVList list = makeList({{"dataport.data_type", "IDL:RTC/TimedLong:1.0"}});
    CORBA_SeqUtil::push_back(list, NVUtil::newNV("count", CORBA::Long(3)));

    QVERIFY(NVUtil::isString(list, "dataport.data_type"));
    QVERIFY(!NVUtil::isString(list, "count"));
    QVERIFY(!NVUtil::isString(list, "missing"));
    QVERIFY(NVUtil::isStringValue(list, "dataport.data_type", "IDL:RTC/TimedLong:1.0"));
    QVERIFY(!NVUtil::isStringValue(list, "dataport.data_type", "IDL:RTC/TimedShort:1.0"));
    QCOMPARE(NVUtil::toString(list, "count"), std::string());
    QCOMPARE(NVUtil::toString(list, "missing"), std::string());
    QCOMPARE(NVUtil::find_index(list, "count"), CORBA::Long(1));
    QCOMPARE(NVUtil::find_index(list, "missing"), CORBA::Long(-1));

    CORBA::Long count = 0;
    QVERIFY(NVUtil::find(list, "count") >>= count);
    QCOMPARE(count, CORBA::Long(3));
    bool thrown = false;
    try {
        NVUtil::find(list, "missing");
    } catch (const std::string &) {
        thrown = true;
    }
    QVERIFY(thrown);

    QVERIFY(NVUtil::appendStringValue(list, "flows", "push"));
    QCOMPARE(NVUtil::toString(list, "flows"), std::string("push"));
    QVERIFY(NVUtil::appendStringValue(list, "flows", "pull"));
    QVERIFY(NVUtil::appendStringValue(list, "flows", "push"));
    QCOMPARE(NVUtil::toString(list, "flows"), std::string("push,pull"));
}

void TestSdkUtil::nvDump()
{
    SDOPackage::NVList list = makeList({{"a", "1"}});
    CORBA_SeqUtil::push_back(list, NVUtil::newNV("n", CORBA::Double(1.5)));
    const std::string expected = "a: 1\nn: not a string value\n";
    QCOMPARE(NVUtil::toString(list), expected);
    std::ostringstream viaDump, viaOperator;
    NVUtil::dump(viaDump, list);
    {
        using NVUtil::operator<<;
        viaOperator << list;
    }
    QCOMPARE(viaDump.str(), expected);
    QCOMPARE(viaOperator.str(), expected);
}

void TestSdkUtil::sequenceHelpers()
{
    CORBA::LongSeq seq;
    for (CORBA::Long value : {1, 2, 3})
        CORBA_SeqUtil::push_back(seq, value);
    QCOMPARE(seq.length(), CORBA::ULong(3));
    QCOMPARE(CORBA_SeqUtil::for_each(seq, Sum()).total, 6L);
    QCOMPARE(CORBA_SeqUtil::find(seq, [](CORBA::Long v) { return v == 3; }), CORBA::Long(2));
    QCOMPARE(CORBA_SeqUtil::find(seq, [](CORBA::Long v) { return v == 9; }), CORBA::Long(-1));

    CORBA::Long zero = 0, last = 9;
    CORBA_SeqUtil::insert(seq, zero, 0);
    CORBA_SeqUtil::insert(seq, last, 100); // past the end: appended
    QCOMPARE(seq.length(), CORBA::ULong(5));
    QCOMPARE(seq[0], CORBA::Long(0));
    QCOMPARE(seq[1], CORBA::Long(1));
    QCOMPARE((CORBA_SeqUtil::front<CORBA::LongSeq, CORBA::Long>(seq)), CORBA::Long(0));
    QCOMPARE((CORBA_SeqUtil::back<CORBA::LongSeq, CORBA::Long>(seq)), CORBA::Long(9));

    CORBA_SeqUtil::erase(seq, 0);
    QCOMPARE(seq[0], CORBA::Long(1));
    CORBA_SeqUtil::erase(seq, 10); // out of range: nothing
    QCOMPARE(seq.length(), CORBA::ULong(4));
    CORBA_SeqUtil::erase_if(seq, [](CORBA::Long v) { return v == 2; });
    QCOMPARE(seq.length(), CORBA::ULong(3));
    QCOMPARE(seq[1], CORBA::Long(3));

    CORBA::LongSeq other;
    CORBA_SeqUtil::push_back(other, CORBA::Long(42));
    CORBA_SeqUtil::push_back_list(seq, other);
    QCOMPARE(seq.length(), CORBA::ULong(4));
    QCOMPARE(seq[3], CORBA::Long(42));
    CORBA_SeqUtil::clear(seq);
    QCOMPARE(seq.length(), CORBA::ULong(0));

    // Strings: a duplicated string is adopted by the sequence, as in MyServiceProvider.
    SimpleService::EchoList echoes;
    CORBA_SeqUtil::push_back(echoes, CORBA::string_dup("hello"));
    QCOMPARE(std::string(echoes[0]), std::string("hello"));

    // Object references: stringified by the process's ORB and resolvable again.
    UtilSource *source = createSource();
    QVERIFY(source);
    RTC::RTCList components;
    CORBA_SeqUtil::push_back(components, RTC::RTObject::_duplicate(source->getObjRef()));
    const coil::vstring iors = CORBA_SeqUtil::refToVstring(components);
    QCOMPARE(iors.size(), size_t(1));
    QVERIFY(iors[0].rfind("IOR:", 0) == 0);
    CORBA::Object_var back = m_manager->getORB()->string_to_object(iors[0].c_str());
    QVERIFY(back->_is_equivalent(source->getObjRef()));
}

void TestSdkUtil::typeNames()
{
    QCOMPARE(std::string(CORBA_Util::toTypename<RTC::TimedLong>()), std::string("TimedLong"));
    QCOMPARE(std::string(CORBA_Util::toRepositoryId<RTC::TimedLong>()),
             std::string("IDL:RTC/TimedLong:1.0"));
    QCOMPARE(std::string(CORBA_Util::toRepositoryIdOfStruct<RTC::CameraImage>()),
             std::string("IDL:RTC/CameraImage:1.0"));
    QVERIFY(CORBA_Util::is_corba_object<RTC::RTObject>::value);
    QVERIFY(!CORBA_Util::is_corba_object<RTC::TimedLong>::value);
    QCOMPARE(std::string(CORBA_Util::toTypename<RTC::RTObject>()), std::string("RTObject"));
    QCOMPARE(std::string(CORBA_Util::toRepositoryIdOfObject<RTC::RTObject>()),
             std::string("IDL:omg.org/RTC/RTObject:1.0"));
    QCOMPARE(std::string(CORBA_Util::toRepositoryId<SimpleService::MyService>()),
             std::string("IDL:SimpleService/MyService:1.0"));

    RTC::TimedOctetSeq from, to;
    from.tm.sec = 4;
    from.data.length(3);
    from.data[2] = 0x7f;
    CORBA_Util::copyData(to, from);
    QCOMPARE(to.tm.sec, CORBA::ULong(4));
    QCOMPARE(to.data.length(), CORBA::ULong(3));
    QCOMPARE(int(to.data[2]), 0x7f);
}

void TestSdkUtil::cdrSerializers()
{
    RTC::TimedLong value;
    value.tm.sec = 12;
    value.tm.nsec = 34;
    value.data = 0x01020304;
    for (bool little : {true, false}) {
        RTC::CORBA_CdrSerializer<RTC::TimedLong> out;
        out.isLittleEndian(little);
        QVERIFY(out.serialize(value));
        QCOMPARE(out.getDataLength(), 12ul); // three 32-bit numbers
        std::vector<unsigned char> bytes(out.getDataLength());
        out.readData(bytes.data(), bytes.size());
        // The data field is the last four octets, in the chosen order.
        QCOMPARE(int(bytes[8]), little ? 0x04 : 0x01);
        QCOMPARE(int(bytes[11]), little ? 0x01 : 0x04);

        RTC::CORBA_CdrSerializer<RTC::TimedLong> in;
        in.isLittleEndian(little);
        in.writeData(bytes.data(), bytes.size());
        RTC::TimedLong back;
        back.data = 0;
        QVERIFY(in.deserialize(back));
        QCOMPARE(back.data, value.data);
        QCOMPARE(back.tm.sec, CORBA::ULong(12));
        QCOMPARE(back.tm.nsec, CORBA::ULong(34));

        RTC::CORBA_CdrSerializer<RTC::TimedLong> copy(in);
        RTC::TimedLong again;
        QVERIFY(copy.deserialize(again));
        QCOMPARE(again.data, value.data);
    }
    // Too few bytes for the type.
    RTC::CORBA_CdrSerializer<RTC::TimedString> truncated;
    const unsigned char few[] = {1, 0, 0, 0, 2, 0, 0, 0, 50, 0, 0, 0};
    truncated.writeData(few, sizeof(few));
    RTC::TimedString text;
    QVERIFY(!truncated.deserialize(text));
}

void TestSdkUtil::serializerRegistry()
{
    QVERIFY(RTC::getSerializerList<RTC::TimedLong>().empty());
    CdrMemoryStreamInit<RTC::TimedLong>();
    QCOMPARE(RTC::getSerializerList<RTC::TimedLong>(), std::vector<std::string> {"cdr"});
    QVERIFY(RTC::getSerializerList<RTC::TimedShort>().empty());
    QCOMPARE(RTC::addDataTypeToMarshalingType<RTC::TimedLong>("cdr"),
             std::string("IDL:RTC/TimedLong:1.0:cdr"));

    RTC::ByteDataStreamBase *made = RTC::createSerializer<RTC::TimedLong>("cdr");
    QVERIFY(made != nullptr);
    auto *typed = dynamic_cast<RTC::ByteDataStream<RTC::TimedLong> *>(made);
    QVERIFY(typed != nullptr);
    RTC::TimedLong value;
    value.tm.sec = 0;
    value.tm.nsec = 0;
    value.data = 77;
    QVERIFY(typed->serialize(value));
    QCOMPARE(made->getDataLength(), 12ul);
    QVERIFY(RTC::SerializerFactory::instance().isProducerOf(made));
    QCOMPARE(RTC::SerializerFactory::instance().deleteObject(made), coil::FactoryReturn::OK);
    QVERIFY(made == nullptr);
    QVERIFY(RTC::createSerializer<RTC::TimedLong>("json") == nullptr);

    RTC::removeSerializer<RTC::TimedLong>("cdr");
    QVERIFY(RTC::getSerializerList<RTC::TimedLong>().empty());
    QVERIFY(RTC::createSerializer<RTC::TimedLong>("cdr") == nullptr);
}

void TestSdkUtil::iorDecodeAndEncode()
{
    UtilSource *source = createSource();
    QVERIFY(source);
    CORBA::ORB_ptr orb = m_manager->getORB();
    CORBA::String_var text = orb->object_to_string(source->getObjRef());

    IOP::IOR ior;
    QVERIFY(CORBA_IORUtil::toIOR(text.in(), ior));
    QCOMPARE(std::string(ior.type_id),
             std::string("IDL:openrtm.aist.go.jp/OpenRTM/DataFlowComponent:1.0"));
    const std::vector<IIOP::Address> endpoints = CORBA_IORUtil::getEndpoints(ior);
    QVERIFY(!endpoints.empty());
    QCOMPARE(std::string(endpoints.front().host), std::string("127.0.0.1"));
    QVERIFY(endpoints.front().port != 0);

    std::string encoded;
    QVERIFY(CORBA_IORUtil::toString(ior, encoded));
    CORBA::Object_var again = orb->string_to_object(encoded.c_str());
    QVERIFY(again->_is_equivalent(source->getObjRef()));

    const std::string info = CORBA_IORUtil::formatIORinfo(text.in());
    QVERIFY2(info.find("OpenRTM/DataFlowComponent") != std::string::npos, info.c_str());
    QVERIFY2(info.find("127.0.0.1:" + std::to_string(endpoints.front().port)) != std::string::npos,
             info.c_str());

    std::string moved(text.in());
    QVERIFY(CORBA_IORUtil::replaceEndpoint(moved, "localhost"));
    IOP::IOR movedIor;
    QVERIFY(CORBA_IORUtil::toIOR(moved.c_str(), movedIor));
    const std::vector<IIOP::Address> movedEndpoints = CORBA_IORUtil::getEndpoints(movedIor);
    QCOMPARE(std::string(movedEndpoints.front().host), std::string("localhost"));
    QCOMPARE(movedEndpoints.front().port, endpoints.front().port);
    // Still the same object, now reached through "localhost".
    CORBA::Object_var movedObject = orb->string_to_object(moved.c_str());
    RTC::RTObject_var movedRtc = RTC::RTObject::_narrow(movedObject);
    QVERIFY(CORBA_RTCUtil::is_existing(movedRtc));

    IOP::IOR broken;
    QVERIFY(!CORBA_IORUtil::toIOR("IOR:zz", broken));
    QVERIFY(!CORBA_IORUtil::toIOR("corbaloc::localhost/x", broken));
    std::string notAnIor = "nothing";
    QVERIFY(!CORBA_IORUtil::replaceEndpoint(notAnIor, "localhost"));
}

void TestSdkUtil::corbaUris_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("url");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");
    QTest::addColumn<bool>("addressOnly");
    QTest::newRow("host:port") << "localhost:2809"
                               << "corbaloc:iiop:localhost:2809/NameService"
                               << "localhost" << 2809 << true;
    QTest::newRow("host") << "ns.example"
                          << "corbaloc:iiop:ns.example/NameService"
                          << "ns.example" << 2809 << true;
    QTest::newRow("giop") << "giop:tcp:10.0.0.1:5005"
                          << "corbaloc:iiop:10.0.0.1:5005/NameService"
                          << "10.0.0.1" << 5005 << false;
    QTest::newRow("iiop url") << "iiop://h:1234"
                              << "corbaloc:iiop:h:1234/NameService"
                              << "h" << 1234 << false;
    QTest::newRow("corbaloc") << "corbaloc::h:99"
                              << "corbaloc::h:99/NameService"
                              << "h" << 99 << false;
    QTest::newRow("corbaloc with key") << "corbaloc:iiop:h:99/Other"
                                       << "corbaloc:iiop:h:99/Other"
                                       << "h" << 99 << false;
    QTest::newRow("corbaname") << "corbaname::h:99"
                               << "corbaname::h:99#NameService"
                               << "" << 0 << false;
}

void TestSdkUtil::corbaUris()
{
    QFETCH(QString, input);
    const CORBA_RTCUtil::CorbaURI uri(input.toStdString(), "NameService");
    QTEST(QString::fromStdString(uri.toString()), "url");
    QTEST(QString::fromStdString(uri.getHost()), "host");
    QTEST(int(uri.getPort()), "port");
    QTEST(uri.isAddressOnly(), "addressOnly");
}

void TestSdkUtil::rtcUris()
{
    const CORBA_RTCUtil::RTCURIObject byName("rtcname://localhost:2809/host.host_cxt/Comp0");
    QVERIFY(byName.isRTCNameURI());
    QVERIFY(!byName.isRTCLocURI());
    QCOMPARE(byName.getAddress(), std::string("corbaloc::localhost:2809"));
    QCOMPARE(byName.getRTCName(), std::string("host.host_cxt/Comp0"));

    const CORBA_RTCUtil::RTCURIObject byManager("rtcloc.iiop://*/example/Comp0");
    QVERIFY(byManager.isRTCLocURI());
    QCOMPARE(byManager.getAddress(), std::string("*"));
    QCOMPARE(byManager.getRTCName(), std::string("example/Comp0"));

    const CORBA_RTCUtil::RTCURIObject web("rtcname.http://h:8080#ctx/Comp0");
    QCOMPARE(web.getAddress(), std::string("http://h:8080"));
    QCOMPARE(web.getRTCName(), std::string("ctx/Comp0"));

    const CORBA_RTCUtil::RTCURIObject wrongKind("rtcloc://h:2810/c/Comp0", true, false);
    QVERIFY(!wrongKind.isRTCLocURI());
    QVERIFY(!wrongKind.isRTCNameURI());
    QCOMPARE(wrongKind.getAddress(), std::string());
    QVERIFY(!CORBA_RTCUtil::RTCURIObject("Comp0").isRTCNameURI());
}

void TestSdkUtil::componentKinds()
{
    UtilSource *source = createSource();
    QVERIFY(source);
    QVERIFY(RTC_Utils::isDataFlowComponent(source->getObjRef()));
    QVERIFY(!RTC_Utils::isFsmObject(source->getObjRef()));
    QVERIFY(!RTC_Utils::isFsmParticipant(source->getObjRef()));
    QVERIFY(!RTC_Utils::isMultiModeObject(source->getObjRef()));
    QVERIFY(!RTC_Utils::isDataFlowComponent(CORBA::Object::_nil()));
}

void TestSdkUtil::lifeCycleThroughContexts()
{
    UtilSource *source = createSource();
    QVERIFY(source);
    RTC::RTObject_var rtc = RTC::RTObject::_duplicate(source->getObjRef());

    const coil::Properties profile = CORBA_RTCUtil::get_component_profile(rtc);
    QCOMPARE(profile.getProperty("type_name"), std::string("UtilSource"));
    QCOMPARE(profile.getProperty("category"), std::string("utiltest"));
    QVERIFY(CORBA_RTCUtil::get_component_profile(RTC::RTObject::_nil()).propertyNames().empty());
    QVERIFY(CORBA_RTCUtil::is_existing(rtc));
    QVERIFY(!CORBA_RTCUtil::is_existing(RTC::RTObject::_nil()));
    QVERIFY(CORBA_RTCUtil::is_alive_in_default_ec(rtc));

    RTC::ExecutionContext_var ec = CORBA_RTCUtil::get_actual_ec(rtc);
    QVERIFY(!CORBA::is_nil(ec));
    QCOMPARE(CORBA_RTCUtil::get_ec_id(rtc, ec), RTC::UniqueId(0));
    RTC::ExecutionContext_var none = CORBA_RTCUtil::get_actual_ec(rtc, 5);
    QVERIFY(CORBA::is_nil(none));
    RTC::ExecutionContext_var noParticipation = CORBA_RTCUtil::get_actual_ec(rtc, 1000);
    QVERIFY(CORBA::is_nil(noParticipation));

    QVERIFY(CORBA_RTCUtil::is_in_inactive(rtc));
    QCOMPARE(CORBA_RTCUtil::activate(rtc), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(CORBA_RTCUtil::is_in_active(rtc), 5000);
    RTC::LifeCycleState state = RTC::CREATED_STATE;
    QVERIFY(CORBA_RTCUtil::get_state(state, rtc));
    QCOMPARE(state, RTC::ACTIVE_STATE);
    QVERIFY(!CORBA_RTCUtil::get_state(state, rtc, 3));

    // A failing onExecute takes the component to ERROR; reset brings it back to INACTIVE.
    QVERIFY(CORBA_RTCUtil::set_configuration(rtc, "default", "fail", "1"));
    QTRY_VERIFY_WITH_TIMEOUT(CORBA_RTCUtil::is_in_error(rtc), 5000);
    QVERIFY(CORBA_RTCUtil::set_configuration(rtc, "default", "fail", "0"));
    QCOMPARE(CORBA_RTCUtil::reset(rtc), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(CORBA_RTCUtil::is_in_inactive(rtc), 5000);

    QCOMPARE(CORBA_RTCUtil::activate(rtc), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(CORBA_RTCUtil::is_in_active(rtc), 5000);
    QCOMPARE(CORBA_RTCUtil::deactivate(rtc), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(CORBA_RTCUtil::is_in_inactive(rtc), 5000);

    QCOMPARE(CORBA_RTCUtil::activate(rtc, 7), RTC::BAD_PARAMETER);
    QCOMPARE(CORBA_RTCUtil::deactivate(RTC::RTObject::_nil()), RTC::BAD_PARAMETER);
    QCOMPARE(CORBA_RTCUtil::reset(rtc, 1001), RTC::BAD_PARAMETER);
}

void TestSdkUtil::ratesAndParticipants()
{
    UtilSource *source = createSource();
    UtilSink *sink = createSink();
    QVERIFY(source && sink);
    RTC::RTObject_var rtc = RTC::RTObject::_duplicate(source->getObjRef());
    RTC::RTObject_var other = RTC::RTObject::_duplicate(sink->getObjRef());

    QVERIFY(CORBA_RTCUtil::get_default_rate(rtc) > 0.0);
    QCOMPARE(CORBA_RTCUtil::set_default_rate(rtc, 250.0), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::get_default_rate(rtc), 250.0);
    QCOMPARE(CORBA_RTCUtil::get_current_rate(rtc, 0), 250.0);
    QCOMPARE(CORBA_RTCUtil::set_current_rate(rtc, 0, 40.0), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::get_current_rate(rtc, 0), 40.0);
    QCOMPARE(CORBA_RTCUtil::set_current_rate(rtc, 4, 40.0), RTC::BAD_PARAMETER);
    QCOMPARE(CORBA_RTCUtil::get_current_rate(rtc, 4), double(RTC::BAD_PARAMETER));

    QCOMPARE(CORBA_RTCUtil::add_rtc_to_default_ec(rtc, other), RTC::RTC_OK);
    // The context's profile lists its owner too.
    auto participates = [&rtc](RTC::RTObject_ptr component) {
        RTC::RTCList participants = CORBA_RTCUtil::get_participants_rtc(rtc);
        return CORBA_SeqUtil::find(participants,
                                   [component](const RTC::RTObject_ptr each) {
                                       return each->_is_equivalent(component);
                                   })
            >= 0;
    };
    QVERIFY(participates(other));
    // The sink now participates in the source's context: id 1000 is that context.
    RTC::ExecutionContext_var sourceEc = CORBA_RTCUtil::get_actual_ec(rtc);
    QCOMPARE(CORBA_RTCUtil::get_ec_id(other, sourceEc), RTC::UniqueId(1000));
    RTC::ExecutionContext_var viaSink = CORBA_RTCUtil::get_actual_ec(other, 1000);
    QVERIFY(!CORBA::is_nil(viaSink) && viaSink->_is_equivalent(sourceEc));

    QCOMPARE(CORBA_RTCUtil::remove_rtc_to_default_ec(rtc, other), RTC::RTC_OK);
    QVERIFY(!participates(other));
    QCOMPARE(CORBA_RTCUtil::add_rtc_to_default_ec(rtc, RTC::RTObject::_nil()), RTC::BAD_PARAMETER);
}

void TestSdkUtil::portNamesAndConnections()
{
    UtilSource *source = createSource();
    UtilSink *sink = createSink();
    UtilSink *second = createSink();
    QVERIFY(source && sink && second);
    RTC::RTObject_var src = RTC::RTObject::_duplicate(source->getObjRef());
    RTC::RTObject_var dst = RTC::RTObject::_duplicate(sink->getObjRef());
    RTC::RTObject_var dst2 = RTC::RTObject::_duplicate(second->getObjRef());
    const std::string srcName = source->getInstanceName();
    const std::string dstName = sink->getInstanceName();
    const std::string outName = srcName + ".out", inName = dstName + ".in";

    const coil::vstring ports = CORBA_RTCUtil::get_port_names(src);
    QCOMPARE(ports.size(), size_t(2));
    QVERIFY(contains(ports, outName));
    QVERIFY(contains(ports, srcName + ".Service"));
    QCOMPARE(CORBA_RTCUtil::get_outport_names(src), coil::vstring {outName});
    QCOMPARE(CORBA_RTCUtil::get_svcport_names(src), coil::vstring {srcName + ".Service"});
    QVERIFY(CORBA_RTCUtil::get_inport_names(src).empty());
    QCOMPARE(CORBA_RTCUtil::get_inport_names(dst), coil::vstring {inName});

    RTC::PortService_var out = CORBA_RTCUtil::get_port_by_name(src, outName);
    RTC::PortService_var in = CORBA_RTCUtil::get_port_by_name(dst, inName);
    QVERIFY(!CORBA::is_nil(out) && !CORBA::is_nil(in));
    RTC::PortService_var missing = CORBA_RTCUtil::get_port_by_name(src, "nothing");
    QVERIFY(CORBA::is_nil(missing));
    QVERIFY(CORBA_RTCUtil::find_port(outName)(out));
    QVERIFY(!CORBA_RTCUtil::find_port(inName)(out));

    coil::Properties prop;
    prop.setProperty("dataport.subscription_type", "flush");
    QCOMPARE(CORBA_RTCUtil::connect_by_name("flow", prop, src, outName, dst, inName), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::connect_by_name("bad", prop, src, "none", dst, inName),
             RTC::BAD_PARAMETER);
    QCOMPARE(CORBA_RTCUtil::connect("self", prop, out, out), RTC::BAD_PARAMETER);
    QCOMPARE(CORBA_RTCUtil::get_connector_names(out), coil::vstring {"flow"});
    QCOMPARE(CORBA_RTCUtil::get_connector_names(dst, inName), coil::vstring {"flow"});
    const coil::vstring ids = CORBA_RTCUtil::get_connector_ids(out);
    QCOMPARE(ids.size(), size_t(1));
    QVERIFY(!ids.front().empty());
    QCOMPARE(CORBA_RTCUtil::get_connector_ids(dst, inName), ids);
    QVERIFY(CORBA_RTCUtil::already_connected(out, in));
    QVERIFY(CORBA_RTCUtil::already_connected(in, out));
    QVERIFY(!CORBA_RTCUtil::already_connected(out, out));

    // The connector's defaults and the given property reached the ports.
    RTC::ConnectorProfileList_var profiles = out->get_connector_profiles();
    QCOMPARE(NVUtil::toString(profiles[0].properties, "dataport.dataflow_type"),
             std::string("push"));
    QCOMPARE(NVUtil::toString(profiles[0].properties, "dataport.interface_type"),
             std::string("corba_cdr"));
    QCOMPARE(NVUtil::toString(profiles[0].properties, "dataport.subscription_type"),
             std::string("flush"));

    // Data flows through the connection.
    QCOMPARE(CORBA_RTCUtil::activate(src), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::activate(dst), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(sink->received > 2, 5000);
    QCOMPARE(CORBA_RTCUtil::deactivate(src), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::deactivate(dst), RTC::RTC_OK);

    QCOMPARE(CORBA_RTCUtil::disconnect_connector_name(out, "nope"), RTC::BAD_PARAMETER);
    QCOMPARE(CORBA_RTCUtil::disconnect_connector_name(out, "flow"), RTC::RTC_OK);
    QVERIFY(CORBA_RTCUtil::get_connector_names(out).empty());
    QVERIFY(CORBA_RTCUtil::get_connector_names(in).empty());

    QCOMPARE(CORBA_RTCUtil::connect("byid", prop, out, in), RTC::RTC_OK);
    QCOMPARE(
        CORBA_RTCUtil::disconnect_connector_id(in, CORBA_RTCUtil::get_connector_ids(out).front()),
        RTC::RTC_OK);
    QVERIFY(CORBA_RTCUtil::get_connector_ids(out).empty());

    // connect_multi skips targets it is connected to already.
    RTC::PortService_var in2
        = CORBA_RTCUtil::get_port_by_name(dst2, second->getInstanceName() + std::string(".in"));
    QCOMPARE(CORBA_RTCUtil::connect("first", prop, out, in), RTC::RTC_OK);
    RTC::PortServiceList targets;
    CORBA_SeqUtil::push_back(targets, RTC::PortService::_duplicate(in));
    CORBA_SeqUtil::push_back(targets, RTC::PortService::_duplicate(in2));
    CORBA_SeqUtil::push_back(targets, RTC::PortService::_duplicate(out));
    QCOMPARE(CORBA_RTCUtil::connect_multi("multi", prop, out, targets), RTC::RTC_OK);
    const coil::vstring names = CORBA_RTCUtil::get_connector_names(out);
    QCOMPARE(names.size(), size_t(2));
    QVERIFY(contains(names, "first") && contains(names, "multi"));

    QCOMPARE(CORBA_RTCUtil::disconnect_name(out, second->getInstanceName() + std::string(".in")),
             RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::get_connector_names(out), coil::vstring {"first"});
    QCOMPARE(CORBA_RTCUtil::disconnect_name(out, outName), RTC::BAD_PARAMETER);
    QCOMPARE(CORBA_RTCUtil::disconnect_all(out), RTC::RTC_OK);
    QVERIFY(CORBA_RTCUtil::get_connector_names(out).empty());
    QVERIFY(!CORBA_RTCUtil::already_connected(out, in));
    QCOMPARE(CORBA_RTCUtil::disconnect_all(RTC::PortService::_nil()), RTC::BAD_PARAMETER);

    // A one-port connector profile.
    RTC::ConnectorProfile_var alone = CORBA_RTCUtil::create_connector(
        "alone", coil::Properties(), out, RTC::PortService::_nil());
    QCOMPARE(alone->ports.length(), CORBA::ULong(1));
    QCOMPARE(std::string(alone->name), std::string("alone"));
}

void TestSdkUtil::configurationSets()
{
    UtilSource *source = createSource();
    QVERIFY(source);
    RTC::RTObject_var rtc = RTC::RTObject::_duplicate(source->getObjRef());

    QCOMPARE(CORBA_RTCUtil::get_active_configuration_name(rtc), std::string("default"));
    QCOMPARE(CORBA_RTCUtil::get_configuration(rtc, "fast").getProperty("step"), std::string("10"));
    QCOMPARE(CORBA_RTCUtil::get_parameter_by_key(rtc, "default", "step"), std::string("1"));
    QCOMPARE(CORBA_RTCUtil::get_active_configuration(rtc).getProperty("step"), std::string("1"));
    // Running, the component applies changed parameters before its next onExecute.
    QCOMPARE(CORBA_RTCUtil::activate(rtc), RTC::RTC_OK);
    QTRY_COMPARE_WITH_TIMEOUT(source->seenStep.load(), 1, 5000);

    // Setting a parameter of the active set reaches the bound variable.
    QVERIFY(CORBA_RTCUtil::set_active_configuration(rtc, "step", "3"));
    QCOMPARE(CORBA_RTCUtil::get_parameter_by_key(rtc, "default", "step"), std::string("3"));
    QTRY_COMPARE_WITH_TIMEOUT(source->seenStep.load(), 3, 5000);

    // set_configuration activates the set it changes.
    QVERIFY(CORBA_RTCUtil::set_configuration(rtc, "fast", "step", "20"));
    QCOMPARE(CORBA_RTCUtil::get_active_configuration_name(rtc), std::string("fast"));
    QCOMPARE(CORBA_RTCUtil::get_active_configuration(rtc).getProperty("step"), std::string("20"));
    QTRY_COMPARE_WITH_TIMEOUT(source->seenStep.load(), 20, 5000);
    QCOMPARE(CORBA_RTCUtil::get_parameter_by_key(rtc, "default", "step"), std::string("3"));
}

void TestSdkUtil::namingBindAndResolve()
{
    LiveTest::LiveSystem live;
    QString error;
    QVERIFY2(live.startNameServer(&error), qPrintable(error));
    const std::string address = "127.0.0.1:" + std::to_string(live.namingPort());

    UtilSource *source = createSource();
    QVERIFY(source);
    CORBA::ORB_ptr orb = m_manager->getORB();
    std::unique_ptr<RTC::CorbaNaming> connected = connectNaming(orb, address);
    QVERIFY(connected);
    RTC::CorbaNaming &naming = *connected;
    QCOMPARE(std::string(naming.getNameServer()), "corbaloc:iiop:" + address + "/NameService");
    QVERIFY(naming.isAlive());

    // force: the missing contexts on the way are made.
    naming.bindByString("util.host_cxt/sub.cxt/Src0.rtc", source->getObjRef());
    QVERIFY(naming.isNamingContext("util.host_cxt"));
    QVERIFY(naming.isNamingContext("util.host_cxt/sub.cxt"));
    CORBA::Object_var found = naming.resolve("util.host_cxt/sub.cxt/Src0.rtc");
    QVERIFY(found->_is_equivalent(source->getObjRef()));
    QVERIFY(!naming.isNamingContext("util.host_cxt/sub.cxt/Src0.rtc"));

    bool alreadyBound = false;
    try {
        naming.bindByString("util.host_cxt/sub.cxt/Src0.rtc", source->getObjRef());
    } catch (const RTC::CorbaNaming::AlreadyBound &) {
        alreadyBound = true;
    }
    QVERIFY(alreadyBound);
    bool notFound = false;
    try {
        naming.bindByString("other.host_cxt/Src0.rtc", source->getObjRef(), false);
    } catch (const RTC::CorbaNaming::NotFound &) {
        notFound = true;
    }
    QVERIFY(notFound);

    // rebind replaces; rebind with force makes contexts too.
    RTC::ExecutionContext_var ec = CORBA_RTCUtil::get_actual_ec(source->getObjRef());
    naming.rebindByString("util.host_cxt/sub.cxt/Src0.rtc", ec);
    CORBA::Object_var replaced = naming.resolveStr("util.host_cxt/sub.cxt/Src0.rtc");
    QVERIFY(replaced->_is_equivalent(ec));
    naming.rebindByString("util.host_cxt/deep.cxt/deeper.cxt/Ec.ec", ec);
    CORBA::Object_var deep = naming.resolve("util.host_cxt/deep.cxt/deeper.cxt/Ec.ec");
    QVERIFY(deep->_is_equivalent(ec));

    naming.bindByString("util.host_cxt/sub.cxt/Other.rtc", source->getObjRef());
    CosNaming::BindingList_var all;
    naming.list("util.host_cxt/sub.cxt", all);
    QCOMPARE(all->length(), CORBA::ULong(2));
    CosNaming::BindingList_var ofKind;
    naming.listByKind("util.host_cxt", "cxt", ofKind);
    QCOMPARE(ofKind->length(), CORBA::ULong(0)); // contexts are not objects
    naming.listByKind("util.host_cxt/sub.cxt", "rtc", ofKind);
    QCOMPARE(ofKind->length(), CORBA::ULong(2));

    CosNaming::NamingContext_var made = naming.bindNewContext("made.cxt/inner.cxt");
    QVERIFY(!CORBA::is_nil(made));
    QVERIFY(naming.isNamingContext("made.cxt/inner.cxt"));

    naming.unbind("util.host_cxt/sub.cxt/Other.rtc");
    naming.list("util.host_cxt/sub.cxt", all);
    QCOMPARE(all->length(), CORBA::ULong(1));

    CosNaming::NamingContext_var root = naming.getRootContext();
    CosNaming::BindingList_var top;
    CosNaming::BindingIterator_var rest;
    RTC::CorbaNaming::list(root, 10, top, rest);
    QCOMPARE(top->length(), CORBA::ULong(2)); // util.host_cxt and made.cxt

    naming.clearAll();
    CosNaming::BindingList_var afterClear;
    RTC::CorbaNaming::list(root, 10, afterClear, rest);
    QCOMPARE(afterClear->length(), CORBA::ULong(0));

    bool badServer = false;
    try {
        RTC::CorbaNaming nowhere(orb, "");
    } catch (const std::bad_alloc &) {
        badServer = true;
    }
    QVERIFY(badServer);
}

void TestSdkUtil::namingStringNames()
{
    const CosNaming::Name name = RTC::CorbaNaming::toName("host.host_cxt/Comp0.rtc");
    QCOMPARE(name.length(), CORBA::ULong(2));
    QCOMPARE(std::string(name[0].id), std::string("host"));
    QCOMPARE(std::string(name[0].kind), std::string("host_cxt"));
    QCOMPARE(std::string(name[1].kind), std::string("rtc"));
    CORBA::String_var text = RTC::CorbaNaming::toString(name);
    QCOMPARE(std::string(text.in()), std::string("host.host_cxt/Comp0.rtc"));

    // Separators inside ids are escaped and come back.
    CosNaming::Name odd;
    odd.length(2);
    odd[0].id = CORBA::string_dup("a.b");
    odd[0].kind = CORBA::string_dup("");
    odd[1].id = CORBA::string_dup("x/y");
    odd[1].kind = CORBA::string_dup("k");
    CORBA::String_var oddText = RTC::CorbaNaming::toString(odd);
    QCOMPARE(std::string(oddText.in()), std::string("a\\.b/x\\/y.k"));
    const CosNaming::Name oddBack = RTC::CorbaNaming::toName(oddText);
    QCOMPARE(oddBack.length(), CORBA::ULong(2));
    QCOMPARE(std::string(oddBack[0].id), std::string("a.b"));
    QCOMPARE(std::string(oddBack[0].kind), std::string(""));
    QCOMPARE(std::string(oddBack[1].id), std::string("x/y"));
    QCOMPARE(std::string(oddBack[1].kind), std::string("k"));

    const CosNaming::Name sub = RTC::CorbaNaming::subName(name, 1);
    QCOMPARE(sub.length(), CORBA::ULong(1));
    QCOMPARE(std::string(sub[0].id), std::string("Comp0"));
    QCOMPARE(RTC::CorbaNaming::subName(name, 0, 0).length(), CORBA::ULong(1));
    QCOMPARE(RTC::CorbaNaming::subName(name, 2).length(), CORBA::ULong(0));

    bool invalid = false;
    try {
        RTC::CorbaNaming::toName("");
    } catch (const RTC::CorbaNaming::InvalidName &) {
        invalid = true;
    }
    QVERIFY(invalid);
}

void TestSdkUtil::portsByUrl()
{
    LiveTest::LiveSystem live;
    QString error;
    QVERIFY2(live.startNameServer(&error), qPrintable(error));
    const std::string address = "127.0.0.1:" + std::to_string(live.namingPort());

    UtilSource *source = createSource();
    UtilSink *sink = createSink();
    QVERIFY(source && sink);
    const std::string srcName = source->getInstanceName();
    const std::string dstName = sink->getInstanceName();
    std::unique_ptr<RTC::CorbaNaming> naming = connectNaming(m_manager->getORB(), address);
    QVERIFY(naming);
    naming->bindByString(("util.host_cxt/" + srcName + ".rtc").c_str(), source->getObjRef());

    const std::string byName = "rtcname://" + address + "/util.host_cxt/" + srcName + ".out";
    RTC::PortService_var out = CORBA_RTCUtil::get_port_by_url(byName);
    QVERIFY(!CORBA::is_nil(out));
    RTC::PortProfile_var outProfile = out->get_port_profile();
    QCOMPARE(std::string(outProfile->name), srcName + ".out");
    RTC::PortService_var anywhere
        = CORBA_RTCUtil::get_port_by_url("rtcname://" + address + "/*/" + srcName + ".out");
    QVERIFY(!CORBA::is_nil(anywhere) && anywhere->_is_equivalent(out));
    // "*": the name servers the manager is configured with; an unreachable one is passed over.
    coil::Properties &config = m_manager->getConfig();
    const std::string configured = config.getProperty("corba.nameservers");
    config.setProperty("corba.nameservers", "127.0.0.1:1, " + address);
    RTC::PortService_var viaConfig
        = CORBA_RTCUtil::get_port_by_url("rtcname://*/util.host_cxt/" + srcName + ".out");
    config.setProperty("corba.nameservers", configured);
    QVERIFY(!CORBA::is_nil(viaConfig) && viaConfig->_is_equivalent(out));
    RTC::PortService_var local
        = CORBA_RTCUtil::get_port_by_url("rtcloc://*/utiltest/" + dstName + ".in");
    QVERIFY(!CORBA::is_nil(local));
    RTC::PortService_var wrongCategory
        = CORBA_RTCUtil::get_port_by_url("rtcloc://*/other/" + dstName + ".in");
    QVERIFY(CORBA::is_nil(wrongCategory));
    RTC::PortService_var plain = CORBA_RTCUtil::get_port_by_url(srcName + ".out");
    QVERIFY(CORBA::is_nil(plain));
    RTC::PortService_var unbound = CORBA_RTCUtil::get_port_by_url(
        "rtcname://" + address + "/util.host_cxt/" + dstName + ".in");
    QVERIFY(CORBA::is_nil(unbound));

    // Disconnecting by URL.
    QCOMPARE(CORBA_RTCUtil::connect("viaurl", coil::Properties(), out, local), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::disconnect_connector_name(byName, "viaurl"), RTC::RTC_OK);
    QVERIFY(CORBA_RTCUtil::get_connector_names(out).empty());
    QCOMPARE(CORBA_RTCUtil::connect("viaurl", coil::Properties(), out, local), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::disconnect_connector_id(byName,
                                                    CORBA_RTCUtil::get_connector_ids(out).front()),
             RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::connect("viaurl", coil::Properties(), out, local), RTC::RTC_OK);
    QCOMPARE(CORBA_RTCUtil::disconnect_all(byName), RTC::RTC_OK);
    QVERIFY(CORBA_RTCUtil::get_connector_names(out).empty());
    QCOMPARE(CORBA_RTCUtil::disconnect_all(std::string("rtcname://" + address + "/none.rtc.x")),
             RTC::BAD_PARAMETER);
}

QTEST_GUILESS_MAIN(TestSdkUtil)
#include "tst_sdkutil.moc"
