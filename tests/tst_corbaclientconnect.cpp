// SPDX-License-Identifier: MIT
#include "corbaerror.h"
#include "portconnection.h"

#include <QTest>

using namespace Corba;

// rtcon's compatibility rules on port profiles, without any remote call.
class TestCorbaClientConnect : public QObject
{
    Q_OBJECT

private slots:
    void defaultsFollowTheSourcePort();
    void givenPropertiesOverrideDefaults();
    void checks_data();
    void checks();
    void defaultName();
    void commonValues_data();
    void commonValues();
    void refusedBeforeAnyRemoteCall();
};

namespace {

PortInfo dataPort(const QString &name, const QString &direction, const QString &dataType,
                  const QString &flows = QStringLiteral("push, pull"))
{
    PortInfo port;
    port.name = name;
    port.properties = {{"port.port_type", direction},
                       {"dataport.data_type", dataType},
                       {"dataport.dataflow_type", flows},
                       {"dataport.interface_type", "corba_cdr"},
                       {"dataport.subscription_type", "flush, new, periodic"}};
    return port;
}

PortInfo out(const QString &name, const QString &type = QStringLiteral("IDL:RTC/TimedLong:1.0"))
{
    return dataPort(name, QStringLiteral("DataOutPort"), type);
}

PortInfo in(const QString &name, const QString &type = QStringLiteral("IDL:RTC/TimedLong:1.0"))
{
    return dataPort(name, QStringLiteral("DataInPort"), type);
}

PortInfo service(const QString &name, std::vector<PortInterfaceInfo> interfaces)
{
    PortInfo port;
    port.name = name;
    port.properties = {{"port.port_type", "CorbaPort"}};
    port.interfaces = std::move(interfaces);
    return port;
}

const PortInterfaceInfo provided {"myservice", "SimpleService::MyService", true};
const PortInterfaceInfo required {"myservice", "SimpleService::MyService", false};
const PortInterfaceInfo otherRequired {"other0", "SimpleService::MyService", false};

} // namespace

Q_DECLARE_METATYPE(std::vector<Corba::PortInfo>)

void TestCorbaClientConnect::defaultsFollowTheSourcePort()
{
    const Properties properties
        = PortConnection::effectiveProperties({out("A0.out"), in("B0.in")}, {});
    QCOMPARE(propertyValue(properties, "dataport.dataflow_type"), QString("push"));
    QCOMPARE(propertyValue(properties, "dataport.interface_type"), QString("corba_cdr"));
    QCOMPARE(propertyValue(properties, "dataport.subscription_type"), QString("new"));
    QCOMPARE(propertyValue(properties, "dataport.data_type"), QString("IDL:RTC/TimedLong:1.0"));
    // Given in→out, the data type still comes from the output port.
    const Properties reversed = PortConnection::effectiveProperties(
        {in("B0.in", "IDL:RTC/TimedDouble:1.0"), out("A0.out")}, {});
    QCOMPARE(propertyValue(reversed, "dataport.data_type"), QString("IDL:RTC/TimedLong:1.0"));
    // Service ports get no dataport defaults.
    QVERIFY(PortConnection::effectiveProperties(
                {service("P0.s", {provided}), service("C0.s", {required})}, {})
                .isEmpty());
}

void TestCorbaClientConnect::givenPropertiesOverrideDefaults()
{
    const Properties properties = PortConnection::effectiveProperties(
        {out("A0.out"), in("B0.in")}, {{"dataport.subscription_type", "flush"}, {"user.key", "v"}});
    QCOMPARE(propertyValue(properties, "dataport.subscription_type"), QString("flush"));
    QCOMPARE(propertyValue(properties, "user.key"), QString("v"));
    QCOMPARE(properties.size(), 5);
}

void TestCorbaClientConnect::checks_data()
{
    QTest::addColumn<std::vector<PortInfo>>("ports");
    QTest::addColumn<Properties>("given");
    QTest::addColumn<QString>("problem");

    const Properties none;
    QTest::newRow("out to in") << std::vector<PortInfo> {out("A0.out"), in("B0.in")} << none << "";
    QTest::newRow("in to out") << std::vector<PortInfo> {in("B0.in"), out("A0.out")} << none << "";
    QTest::newRow("out to two ins")
        << std::vector<PortInfo> {out("A0.out"), in("B0.in"), in("C0.in")} << none << "";
    QTest::newRow("out to out") << std::vector<PortInfo> {out("A0.out"), out("B0.out")} << none
                                << "B0.out is not an input port";
    QTest::newRow("in to in") << std::vector<PortInfo> {in("A0.in"), in("B0.in")} << none
                              << "A0.in is not an output port";
    QTest::newRow("one port") << std::vector<PortInfo> {out("A0.out")} << none
                              << "a connection needs at least two";
    QTest::newRow("data type mismatch")
        << std::vector<PortInfo> {out("A0.out"), in("B0.in", "IDL:RTC/TimedDouble:1.0")} << none
        << "B0.in does not allow dataport.data_type=IDL:RTC/TimedLong:1.0";
    QTest::newRow("flow not offered")
        << std::vector<PortInfo> {out("A0.out"),
                                  dataPort("B0.in", "DataInPort", "IDL:RTC/TimedLong:1.0", "push")}
        << Properties {{"dataport.dataflow_type", "pull"}}
        << "B0.in does not allow dataport.dataflow_type=pull (allowed: push)";
    QTest::newRow("any accepts everything")
        << std::vector<PortInfo> {dataPort("A0.out", "DataOutPort", "IDL:RTC/TimedLong:1.0", "Any"),
                                  dataPort("B0.in", "DataInPort", "IDL:RTC/TimedLong:1.0",
                                           "push, Any")}
        << Properties {{"dataport.dataflow_type", "duplex"}} << "";
    QTest::newRow("case of values ignored")
        << std::vector<PortInfo> {out("A0.out"), in("B0.in")}
        << Properties {{"dataport.dataflow_type", "PUSH"}} << "";
    QTest::newRow("unknown subscription")
        << std::vector<PortInfo> {out("A0.out"), in("B0.in")}
        << Properties {{"dataport.subscription_type", "sometimes"}}
        << "A0.out does not allow dataport.subscription_type=sometimes";
    QTest::newRow("other keys unchecked")
        << std::vector<PortInfo> {out("A0.out"), in("B0.in")} << Properties {{"x.y", "z"}} << "";
    QTest::newRow("data to service")
        << std::vector<PortInfo> {out("A0.out"), service("C0.s", {required})} << none
        << "C0.s is not an input port";
    QTest::newRow("service pair") << std::vector<PortInfo> {service("P0.s", {provided}),
                                                            service("C0.s", {required})}
                                  << none << "";
    QTest::newRow("service same polarity")
        << std::vector<PortInfo> {service("P0.s", {provided}), service("Q0.s", {provided})} << none
        << "interface 'myservice' of P0.s has no required counterpart in Q0.s";
    QTest::newRow("service instance names differ")
        << std::vector<PortInfo> {service("C0.s", {required}), service("D0.s", {otherRequired})}
        << none << "interface 'myservice' of C0.s has no provided counterpart in D0.s";
    QTest::newRow("service to data")
        << std::vector<PortInfo> {service("P0.s", {provided}), in("B0.in")} << none
        << "B0.in is not a service port";
}

void TestCorbaClientConnect::checks()
{
    QFETCH(std::vector<PortInfo>, ports);
    QFETCH(Properties, given);
    QFETCH(QString, problem);
    const QString found
        = PortConnection::problem(ports, PortConnection::effectiveProperties(ports, given));
    if (problem.isEmpty())
        QVERIFY2(found.isEmpty(), qPrintable(found));
    else
        QVERIFY2(found.startsWith(problem), qPrintable(found));
}

void TestCorbaClientConnect::commonValues_data()
{
    QTest::addColumn<QString>("outValues");
    QTest::addColumn<QString>("inValues");
    QTest::addColumn<QStringList>("common");
    // OpenRTM-aist's OutPorts list their subscription types and its InPorts say "Any".
    QTest::newRow("any InPort") << "block,flush,new,nonblock,periodic"
                                << "Any"
                                << QStringList {"block", "flush", "new", "nonblock", "periodic"};
    QTest::newRow("any OutPort") << "ANY"
                                 << "flush, new" << QStringList {"flush", "new"};
    QTest::newRow("both list") << "flush,new,periodic"
                               << "new, periodic,block" << QStringList {"new", "periodic"};
    QTest::newRow("case") << "push,pull"
                          << "PULL" << QStringList {"pull"};
    QTest::newRow("nothing common") << "flush"
                                    << "new" << QStringList {};
    QTest::newRow("neither says") << ""
                                  << "" << QStringList {};
}

void TestCorbaClientConnect::commonValues()
{
    QFETCH(QString, outValues);
    QFETCH(QString, inValues);
    QFETCH(QStringList, common);
    PortInfo source = out("SeqOut0.Long");
    PortInfo sink = in("SeqIn0.Long");
    const QString key = QStringLiteral("dataport.subscription_type");
    for (auto [port, values] : {std::pair {&source, outValues}, std::pair {&sink, inValues}}) {
        port->properties.removeIf([&](const auto &p) { return p.first == key; });
        if (!values.isEmpty())
            port->properties.append({key, values});
    }
    QCOMPARE(PortConnection::commonValues({source, sink}, key), common);
}

void TestCorbaClientConnect::defaultName()
{
    QCOMPARE(PortConnection::defaultName({out("ConsoleIn0.out"), in("ConsoleOut0.in")}),
             QString("out_in"));
}

void TestCorbaClientConnect::refusedBeforeAnyRemoteCall()
{
    // The ports have no references at all: the check must refuse before anything is called.
    try {
        PortConnection::connect({out("A0.out"), out("B0.out")}, {}, "/ns/A0.rtc:out");
        QFAIL("connect succeeded");
    } catch (const Error &e) {
        QCOMPARE(e.kind(), Error::Kind::Incompatible);
        QVERIFY2(e.message().startsWith("/ns/A0.rtc:out: cannot connect: B0.out is not an input"),
                 qPrintable(e.message()));
    }
}

QTEST_GUILESS_MAIN(TestCorbaClientConnect)
#include "tst_corbaclientconnect.moc"
