// SPDX-License-Identifier: MIT
// The deployment engine's offline parts: connector properties, IOR keys, data type names, saved
// component ids, live-path detection, restore order and reports.
#include "componentmapper.h"
#include "deployreport.h"
#include "liveports.h"
#include "profileio.h"
#include "restoreplan.h"
#include "rtsprofile.h"

#include <QtTest>

using namespace Deploy;

class TestDeployPlan : public QObject
{
    Q_OBJECT

private slots:
    void iorKeys_data();
    void iorKeys();
    void dataTypes_data();
    void dataTypes();
    void typeNames();
    void livePaths_data();
    void livePaths();
    void connectorProperties();
    void restoreOrder();
    void createArgument();
    void reportText();
    void portLookup();
};

void TestDeployPlan::iorKeys_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<bool>("ior");
    QTest::newRow("inport ior") << "dataport.corba_cdr.inport_ior" << true;
    QTest::newRow("inport ref") << "dataport.corba_cdr.inport_ref" << true;
    QTest::newRow("outport ior") << "dataport.corba_cdr.outport_ior" << true;
    QTest::newRow("component IOR") << "IOR" << true;
    QTest::newRow("buffer") << "dataport.inport.buffer.length" << false;
    QTest::newRow("subscription") << "dataport.subscription_type" << false;
    QTest::newRow("refresh is no ref") << "dataport.refresh" << false;
}

void TestDeployPlan::iorKeys()
{
    QFETCH(QString, key);
    QFETCH(bool, ior);
    QCOMPARE(isIorKey(key), ior);
}

void TestDeployPlan::dataTypes_data()
{
    QTest::addColumn<QString>("a");
    QTest::addColumn<QString>("b");
    QTest::addColumn<bool>("same");
    QTest::newRow("repository id") << "IDL:RTC/TimedLong:1.0"
                                   << "RTC::TimedLong" << true;
    QTest::newRow("short") << "TimedLong"
                           << "RTC::TimedLong" << true;
    QTest::newRow("equal") << "RTC::TimedLong"
                           << "RTC::TimedLong" << true;
    QTest::newRow("other type") << "IDL:RTC/TimedLong:1.0"
                                << "RTC::TimedDouble" << false;
    QTest::newRow("other module") << "Foo::TimedLong"
                                  << "RTC::TimedLong" << false;
}

void TestDeployPlan::dataTypes()
{
    QFETCH(QString, a);
    QFETCH(QString, b);
    QFETCH(bool, same);
    QCOMPARE(sameDataType(a, b), same);
    QCOMPARE(sameDataType(b, a), same);
}

void TestDeployPlan::typeNames()
{
    QCOMPARE(ComponentMapper::typeNameOf("RTC:AIST:example:ConsoleIn:2.0.0"), QString("ConsoleIn"));
    QCOMPARE(ComponentMapper::typeNameOf("ConsoleIn"), QString("ConsoleIn"));
}

void TestDeployPlan::livePaths_data()
{
    QTest::addColumn<QString>("pathUri");
    QTest::addColumn<bool>("live");
    QTest::newRow("naming path") << "localhost/host.host_cxt/ConsoleIn0.rtc" << true;
    QTest::newRow("offline RTC.xml") << "RTCs/ConsoleIn0.xml" << false;
    QTest::newRow("yaml") << "RTCs/x.rtc.yaml" << false;
    QTest::newRow("file uri") << "file:///tmp/ConsoleIn0.rtc" << false;
    QTest::newRow("empty") << "" << false;
}

void TestDeployPlan::livePaths()
{
    QFETCH(QString, pathUri);
    QFETCH(bool, live);
    QCOMPARE(ComponentMapper::isLivePath(pathUri), live);
}

void TestDeployPlan::connectorProperties()
{
    Profile::RtsDataPortConnector connector;
    connector.dataType = "IDL:RTC/TimedLong:1.0";
    connector.interfaceType = "corba_cdr";
    connector.dataflowType = "push";
    Profile::setRtsProperty(connector.properties, "dataport.dataflow_type", "pull");
    Profile::setRtsProperty(connector.properties, "dataport.corba_cdr.outport_ior", "IOR:01");
    Profile::setRtsProperty(connector.properties, "dataport.inport.buffer.length", "8");
    // No subscription type saved (rtshell #13): simply not given.
    const Corba::Properties properties = dataConnectorProperties(connector);
    QCOMPARE(properties,
             Corba::Properties({{"dataport.interface_type", "corba_cdr"},
                                {"dataport.dataflow_type", "pull"},
                                {"dataport.data_type", "IDL:RTC/TimedLong:1.0"},
                                {"dataport.inport.buffer.length", "8"}}));
}

void TestDeployPlan::restoreOrder()
{
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(
        RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/deploy/broken.xml"), &diagnostics);
    QVERIFY(loaded && loaded->rts);
    Profile::RtsProfile profile = *loaded->rts;
    QList<ComponentMapping> components(2);
    components[0].instanceName = "Src0";
    components[1].instanceName = "Sink0";
    components[1].required = false;
    // An optional end makes the connector optional; required connectors run first.
    profile.dataPortConnectors.append(profile.dataPortConnectors.first());
    profile.dataPortConnectors.last().connectorId = "third";
    profile.dataPortConnectors.last().target.instanceName = "Src0";
    const QList<ConnectorPlan> plans = connectorPlans(profile, components);
    QCOMPARE(plans.size(), 3);
    QCOMPARE(plans.at(0).connectorId, QString("third"));
    QVERIFY(plans.at(0).required);
    QVERIFY(!plans.at(1).required);
    QCOMPARE(plans.at(1).connectorId, QString("conn-good"));
    QCOMPARE(plans.at(1).sourcePort, QString("Src0.out"));
}

void TestDeployPlan::createArgument()
{
    Profile::RtsComponent component;
    component.id = "RTC:AIST:example:ConsoleOut:2.0.0";
    component.instanceName = "Out7";
    component.pathUri = "localhost/hostB.host_cxt/Out7.rtc";
    Profile::RtsExecutionContext ec;
    ec.id = "0";
    ec.rate = "25.0";
    component.executionContexts.append(ec);
    TargetOptions options;
    QCOMPARE(ComponentMapper(options).createArgument(component),
             QString("ConsoleOut?instance_name=Out7&exec_cxt.periodic.rate=25"));
    options.hostManagers.insert("hostB", "127.0.0.1:2811");
    QCOMPARE(ComponentMapper(options).createArgument(component),
             QString("ConsoleOut?instance_name=Out7&exec_cxt.periodic.rate=25"
                     "&manager_address=127.0.0.1:2811"));
}

void TestDeployPlan::reportText()
{
    DeployReport report;
    DeployStep step;
    step.action = "connect";
    step.subject = "c1";
    step.status = StepStatus::Failed;
    step.message = "no port x";
    report.steps.append(step);
    report.ok = false;
    report.error = "connect c1: no port x";
    QCOMPARE(report.toText(),
             QString("failed connect c1: no port x\nfailed: connect c1: no port x\n"));
    QCOMPARE(report.stepsWith(StepStatus::Failed).size(), 1);
    QCOMPARE(report.stepsWith(StepStatus::Done).size(), 0);
    QCOMPARE(stepStatusName(StepStatus::RolledBack), QString("rolled back"));
}

void TestDeployPlan::portLookup()
{
    Corba::PortInfo out;
    out.name = "Src0.out";
    Corba::ConnectorInfo connector;
    connector.id = "c1";
    out.connectors.push_back(connector);
    const std::vector<Corba::PortInfo> ports = {out};
    QCOMPARE(findPort(ports, "Src0.out", "Src0"), &ports.front());
    QCOMPARE(findPort(ports, "out", "Src0"), &ports.front());
    QCOMPARE(findPort(ports, "Src0.in", "Src0"), nullptr);
    QCOMPARE(shortPortName("Src0.out", "Src0"), QString("out"));
    QVERIFY(findConnector(out, "c1"));
    QVERIFY(!findConnector(out, "c2"));
}

QTEST_GUILESS_MAIN(TestDeployPlan)
#include "tst_deployplan.moc"
