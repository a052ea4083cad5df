// SPDX-License-Identifier: MIT
// rtmanager's built-in example components against the facts of OpenRTM-aist 2.1's C++ examples
// (module spec, ports and data types, service interfaces, configuration, execution context), read
// through CORBA from a real rtmanager process next to a real omniNames. Systems saved with
// OpenRTM-aist's examples restore onto these components only while the table below holds.
#include "livesystem.h"

#include <Manager.hh>
#include <omniORB4/omniORB.h>

#include "common/nvlist.h"

#include <QtTest>

#include <map>

namespace {

struct DataPortFact
{
    const char *name;
    const char *portType; ///< DataInPort or DataOutPort
    const char *dataType; ///< IDL scoped name as OpenRTM-aist's example declares it
};

struct InterfaceFact
{
    const char *port;
    const char *instance;
    const char *type;
    bool provided;
};

struct ParameterFact
{
    const char *name;
    const char *type; ///< the bound variable's type in the example: int, double, string, vector<double>
    const char *defaultValue;
};

/// `set.name` = value in a configuration set other than "default" (widgets, types, extra sets).
struct SetValueFact
{
    const char *set;
    const char *name;
    const char *value;
};

struct ExampleFact
{
    const char *type;
    const char *description;
    const char *version;
    const char *vendor;
    const char *activityType;
    std::vector<DataPortFact> dataPorts;
    std::vector<InterfaceFact> interfaces;
    std::vector<ParameterFact> parameters;
    std::vector<SetValueFact> setValues;
};

// From OpenRTM-aist v2.1.0 examples/<Type>/ (module spec, onInitialize, header), ConfigSample/
// (ConfigSample.cpp, configsample.conf). Category "example" and max_instance 10 are common to all.
const std::vector<ExampleFact> &openRtmExamples()
{
    static const std::vector<ExampleFact> facts {
        {"ConsoleIn", "Console input component", "2.0.0", "AIST", "PERIODIC",
         {{"out", "DataOutPort", "RTC::TimedLong"}}, {}, {}, {}},
        {"ConsoleOut", "Console output component", "2.0.0", "AIST", "PERIODIC",
         {{"in", "DataInPort", "RTC::TimedLong"}}, {}, {}, {}},
        {"Sensor", "Sensor component", "2.0.0", "AIST", "SPORADIC",
         {{"in", "DataInPort", "RTC::TimedLong"}, {"out", "DataOutPort", "RTC::TimedFloat"}}, {}, {}, {}},
        {"Controller", "Controller component", "2.0.0", "AIST", "SPORADIC",
         {{"in", "DataInPort", "RTC::TimedFloat"}, {"out", "DataOutPort", "RTC::TimedFloat"}}, {}, {}, {}},
        {"Motor", "Motor component", "2.0.0", "AIST", "SPORADIC",
         {{"in", "DataInPort", "RTC::TimedFloat"}, {"out", "DataOutPort", "RTC::TimedLong"}}, {},
         {{"motor_id", "int", "0"}},
         {{"__widget__", "motor_id", "text"}, {"__type__", "motor_id", "int"}}},
        {"SeqOut", "Sequence OutPort component", "2.0.0", "AIST", "PERIODIC",
         {{"Octet", "DataOutPort", "RTC::TimedOctet"},
          {"Short", "DataOutPort", "RTC::TimedShort"},
          {"Long", "DataOutPort", "RTC::TimedLong"},
          {"Float", "DataOutPort", "RTC::TimedFloat"},
          {"Double", "DataOutPort", "RTC::TimedDouble"},
          {"OctetSeq", "DataOutPort", "RTC::TimedOctetSeq"},
          {"ShortSeq", "DataOutPort", "RTC::TimedShortSeq"},
          {"LongSeq", "DataOutPort", "RTC::TimedLongSeq"},
          {"FloatSeq", "DataOutPort", "RTC::TimedFloatSeq"},
          {"DoubleSeq", "DataOutPort", "RTC::TimedDoubleSeq"}},
         {},
         {{"data_type", "string", "serial"}},
         {}},
        {"SeqIn", "Sequence InPort component", "2.0.0", "AIST", "PERIODIC",
         {{"Octet", "DataInPort", "RTC::TimedOctet"},
          {"Short", "DataInPort", "RTC::TimedShort"},
          {"Long", "DataInPort", "RTC::TimedLong"},
          {"Float", "DataInPort", "RTC::TimedFloat"},
          {"Double", "DataInPort", "RTC::TimedDouble"},
          {"OctetSeq", "DataInPort", "RTC::TimedOctetSeq"},
          {"ShortSeq", "DataInPort", "RTC::TimedShortSeq"},
          {"LongSeq", "DataInPort", "RTC::TimedLongSeq"},
          {"FloatSeq", "DataInPort", "RTC::TimedFloatSeq"},
          {"DoubleSeq", "DataInPort", "RTC::TimedDoubleSeq"}},
         {}, {}, {}},
        {"MyServiceProvider", "MyService Provider Sample component", "2.0.0", "AIST", "PERIODIC", {},
         {{"MyService", "myservice", "SimpleService::MyService", true}}, {}, {}},
        {"MyServiceConsumer", "MyService Consumer Sample component", "2.0.0", "AIST", "PERIODIC", {},
         {{"MyService", "myservice", "SimpleService::MyService", false}}, {}, {}},
        {"ConfigSample", "Configuration example component", "1.0", "Noriaki Ando, AIST", "DataFlowComponent", {}, {},
         {{"int_param0", "int", "0"},
          {"int_param1", "int", "1"},
          {"double_param0", "double", "0.11"},
          {"double_param1", "double", "9.9"},
          {"str_param0", "string", "hoge"},
          {"str_param1", "string", "dara"},
          {"vector_param0", "vector<double>", "0.0,1.0,2.0,3.0,4.0"}},
         {{"mode0", "int_param0", "12345"},
          {"mode0", "int_param1", "98765"},
          {"mode0", "str_param0", "mode0"},
          {"mode0", "vector_param0", "0.0,0.1,0.2,0.3,0.4"},
          {"mode1", "int_param0", "-999"},
          {"mode1", "double_param0", "297992458"},
          {"mode1", "str_param1", "AIST"},
          {"mode1", "vector_param0", "1,2,3,4,5,6,7,8,9"},
          {"__widget__", "int_param0", "slider.10"},
          {"__widget__", "double_param0", "slider.10"},
          {"__widget__", "str_param0", "radio"},
          {"__constraints__", "int_param0", "0<=x<=150"},
          {"__constraints__", "str_param0", "(default,mode0,mode1)"}}},
    };
    return facts;
}

const ExampleFact &fact(const QString &type)
{
    for (const ExampleFact &f : openRtmExamples()) {
        if (type == QLatin1String(f.type))
            return f;
    }
    qFatal("no facts for %s", qPrintable(type));
}

QStringList names(const SDOPackage::NVList &list)
{
    QStringList all;
    for (CORBA::ULong i = 0; i < list.length(); ++i)
        all << QString::fromUtf8(list[i].name.in());
    all.sort();
    return all;
}

/// "RTC::TimedFloat" → "IDL:RTC/TimedFloat:1.0", as OpenRTM-aist 2.x advertises port data types.
QString repositoryId(const char *scoped)
{
    return QStringLiteral("IDL:%1:1.0").arg(QString::fromLatin1(scoped).replace(QLatin1String("::"), QLatin1String("/")));
}

bool parsesAs(const QString &value, const QString &type)
{
    bool ok = true;
    if (type == QLatin1String("int"))
        value.toInt(&ok);
    else if (type == QLatin1String("double"))
        value.toDouble(&ok);
    else if (type == QLatin1String("vector<double>")) {
        for (const QString &element : value.split(QLatin1Char(','))) {
            element.trimmed().toDouble(&ok);
            if (!ok)
                break;
        }
    }
    return ok;
}

} // namespace

class TestManagerExamples : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();

    void moduleSpec_data() { addRows(); }
    void moduleSpec();
    void componentProfile_data() { addRows(); }
    void componentProfile();
    void dataPorts_data() { addRows(); }
    void dataPorts();
    void serviceInterfaces_data() { addRows(); }
    void serviceInterfaces();
    void configuration_data() { addRows(); }
    void configuration();
    void executionContext_data() { addRows(); }
    void executionContext();

private:
    static void addRows();
    RTC::RTObject_ptr component(const QString &type) const;

    CORBA::ORB_var m_orb;
    std::unique_ptr<LiveTest::LiveSystem> m_live;
    RTM::Manager_var m_manager;
    std::map<QString, RTC::RTObject_var> m_components;
};

void TestManagerExamples::addRows()
{
    QTest::addColumn<QString>("type");
    for (const ExampleFact &f : openRtmExamples())
        QTest::newRow(f.type) << QString::fromLatin1(f.type);
}

void TestManagerExamples::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    omniORB::setClientCallTimeout(20000);
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startNameServer(&error), qPrintable(error));
    const quint16 port = LiveTest::freePort();
    // No exec_cxt.* in rtc.conf, as in the examples' own rtc.conf files.
    const QStringList options {"corba.nameservers=" + m_live->namingServer(),
                               "naming.formats=exhost.host_cxt/%n.rtc",
                               "manager.naming_formats=exhost.host_cxt/%n.mgr"};
    QVERIFY2(m_live->startManager(RTMANAGER_PATH, port, options, &error), qPrintable(error));
    CORBA::Object_var object = m_orb->string_to_object(LiveTest::managerLocation(port).constData());
    m_manager = RTM::Manager::_narrow(object);
    QVERIFY(!CORBA::is_nil(m_manager));
    for (const ExampleFact &f : openRtmExamples()) {
        RTC::RTObject_var rtc = m_manager->create_component(f.type);
        QVERIFY2(!CORBA::is_nil(rtc), f.type);
        m_components[QString::fromLatin1(f.type)] = rtc;
    }
}

void TestManagerExamples::cleanupTestCase()
{
    m_components.clear();
    m_manager = RTM::Manager::_nil();
    m_live.reset();
    m_orb->destroy();
}

RTC::RTObject_ptr TestManagerExamples::component(const QString &type) const
{
    const auto found = m_components.find(type);
    return found == m_components.end() ? RTC::RTObject::_nil() : RTC::RTObject::_duplicate(found->second);
}

void TestManagerExamples::moduleSpec()
{
    QFETCH(QString, type);
    const ExampleFact &f = fact(type);
    RTM::ModuleProfileList_var factories = m_manager->get_factory_profiles();
    int matches = 0;
    for (CORBA::ULong i = 0; i < factories->length(); ++i) {
        const SDOPackage::NVList &p = factories[i].properties;
        if (nv(p, "implementation_id") != type)
            continue;
        ++matches;
        QCOMPARE(nv(p, "type_name"), type);
        QCOMPARE(nv(p, "description"), QString::fromUtf8(f.description));
        QCOMPARE(nv(p, "version"), QString::fromUtf8(f.version));
        QCOMPARE(nv(p, "vendor"), QString::fromUtf8(f.vendor));
        QCOMPARE(nv(p, "category"), QStringLiteral("example"));
        QCOMPARE(nv(p, "activity_type"), QString::fromUtf8(f.activityType));
        QCOMPARE(nv(p, "max_instance"), QStringLiteral("10"));
        QCOMPARE(nv(p, "language"), QStringLiteral("C++"));
        QCOMPARE(nv(p, "lang_type"), QStringLiteral("compile"));
    }
    QCOMPARE(matches, 1);
}

void TestManagerExamples::componentProfile()
{
    QFETCH(QString, type);
    const ExampleFact &f = fact(type);
    RTC::RTObject_var rtc = component(type);
    QVERIFY(!CORBA::is_nil(rtc));
    RTC::ComponentProfile_var profile = rtc->get_component_profile();
    QCOMPARE(QString::fromUtf8(profile->instance_name.in()), type + QStringLiteral("0"));
    QCOMPARE(QString::fromUtf8(profile->type_name.in()), type);
    QCOMPARE(QString::fromUtf8(profile->description.in()), QString::fromUtf8(f.description));
    QCOMPARE(QString::fromUtf8(profile->version.in()), QString::fromUtf8(f.version));
    QCOMPARE(QString::fromUtf8(profile->vendor.in()), QString::fromUtf8(f.vendor));
    QCOMPARE(QString::fromUtf8(profile->category.in()), QStringLiteral("example"));
    QCOMPARE(profile->port_profiles.length(), CORBA::ULong(f.dataPorts.size() + f.interfaces.size()));
}

void TestManagerExamples::dataPorts()
{
    QFETCH(QString, type);
    const ExampleFact &f = fact(type);
    RTC::RTObject_var rtc = component(type);
    RTC::ComponentProfile_var profile = rtc->get_component_profile();
    QStringList expected;
    for (const DataPortFact &port : f.dataPorts) {
        expected << QStringLiteral("%1.%2 %3 %4").arg(profile->instance_name.in(), port.name, port.portType,
                                                      repositoryId(port.dataType));
    }
    QStringList live;
    for (CORBA::ULong i = 0; i < profile->port_profiles.length(); ++i) {
        const RTC::PortProfile &port = profile->port_profiles[i];
        const QString portType = nv(port.properties, "port.port_type");
        if (portType == QLatin1String("CorbaPort"))
            continue;
        live << QStringLiteral("%1 %2 %3").arg(port.name.in(), portType, nv(port.properties, "dataport.data_type"));
    }
    QCOMPARE(live, expected);
}

void TestManagerExamples::serviceInterfaces()
{
    QFETCH(QString, type);
    const ExampleFact &f = fact(type);
    RTC::RTObject_var rtc = component(type);
    RTC::ComponentProfile_var profile = rtc->get_component_profile();
    QStringList expected;
    for (const InterfaceFact &i : f.interfaces) {
        expected << QStringLiteral("%1.%2 %3 %4 %5")
                        .arg(profile->instance_name.in(), i.port, i.instance, i.type,
                             i.provided ? QStringLiteral("provided") : QStringLiteral("required"));
    }
    QStringList live;
    for (CORBA::ULong p = 0; p < profile->port_profiles.length(); ++p) {
        const RTC::PortProfile &port = profile->port_profiles[p];
        if (nv(port.properties, "port.port_type") != QLatin1String("CorbaPort"))
            continue;
        for (CORBA::ULong i = 0; i < port.interfaces.length(); ++i) {
            const RTC::PortInterfaceProfile &itf = port.interfaces[i];
            live << QStringLiteral("%1 %2 %3 %4")
                        .arg(port.name.in(), itf.instance_name.in(), itf.type_name.in(),
                             itf.polarity == RTC::PROVIDED ? QStringLiteral("provided")
                                                           : QStringLiteral("required"));
        }
    }
    QCOMPARE(live, expected);
}

void TestManagerExamples::configuration()
{
    QFETCH(QString, type);
    const ExampleFact &f = fact(type);
    RTC::RTObject_var rtc = component(type);
    SDOPackage::Configuration_var config = rtc->get_configuration();
    SDOPackage::ConfigurationSet_var active = config->get_active_configuration_set();
    QCOMPARE(QByteArray(active->id), QByteArray("default"));
    QStringList expectedNames;
    for (const ParameterFact &parameter : f.parameters) {
        expectedNames << QString::fromLatin1(parameter.name);
        const QString live = nv(active->configuration_data, parameter.name);
        QCOMPARE(live, QString::fromUtf8(parameter.defaultValue));
        QVERIFY2(parsesAs(live, QString::fromLatin1(parameter.type)), parameter.name);
    }
    expectedNames.sort();
    // No parameter the example does not have.
    QCOMPARE(names(active->configuration_data), expectedNames);
    for (const SetValueFact &value : f.setValues) {
        SDOPackage::ConfigurationSet_var set = config->get_configuration_set(value.set);
        QCOMPARE(nv(set->configuration_data, value.name), QString::fromUtf8(value.value));
    }
}

void TestManagerExamples::executionContext()
{
    QFETCH(QString, type);
    RTC::RTObject_var rtc = component(type);
    RTC::ExecutionContextList_var owned = rtc->get_owned_contexts();
    QCOMPARE(owned->length(), CORBA::ULong(1));
    // The examples' <Type>.conf files set exec_cxt.periodic.rate 1000, also the manager's default.
    QCOMPARE(owned[0]->get_rate(), 1000.0);
    QCOMPARE(owned[0]->get_kind(), RTC::PERIODIC);
}

QTEST_GUILESS_MAIN(TestManagerExamples)
#include "tst_managerexamples.moc"
