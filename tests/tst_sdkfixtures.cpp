// SPDX-License-Identifier: MIT
// Every profile the Builder's tests know, and the bundled examples' components, generated in C++,
// built against the component SDK of this build tree, loaded into one rtmanager and created there;
// the example pair is connected to built-in components and activated, and the state machine
// generated for an EventPort follows the events built-in sources send it. Together the profiles
// cover every port kind, the data types the Builder offers, provided and required service ports of a
// multi-module user IDL and every configuration type including vectors.
#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkproject.h"
#include "turnstileedits.h"

#include <idltypelibrary.h>

#include <QtTest>

class TestSdkFixtures : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void generatedProjectRuns_data();
    void generatedProjectRuns();
    // Before examplesConnectToBuiltins, which replaces the built-in ConsoleIn and ConsoleOut
    // types this test drives and watches with generated ones.
    void generatedStateMachineFollowsEvents();
    void examplesConnectToBuiltins();
    void everyDataTypeTheBuilderOffers();

private:
    RtctlResult rtctl(const QStringList &arguments);
    QString host() const { return QStringLiteral("/%1/fixhost.host_cxt").arg(m_live.namingServer()); }
    /// Generates and builds @p profile into m_work/<name>; the module path or empty.
    QString generateAndBuild(const QString &profile, const QString &name, const QStringList &options);

    QString receivedValues(const QString &component);

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
    CORBA::ORB_var m_orb;
};

RtctlResult TestSdkFixtures::rtctl(const QStringList &arguments)
{
    return runRtctlAt(host(), arguments);
}

void TestSdkFixtures::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QVERIFY(m_work.isValid());
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList options{"corba.nameservers=" + m_live.namingServer(), "naming.formats=fixhost.host_cxt/%n.rtc",
                              "manager.naming_formats=fixhost.host_cxt/%n.mgr"};
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, LiveTest::freePort(), options, &error), qPrintable(error));
}

QString TestSdkFixtures::generateAndBuild(const QString &profile, const QString &name, const QStringList &options)
{
    const QString dir = m_work.filePath(name);
    const RtctlResult generated = runRtctl(QStringList{"gen", profile, "--lang", "cpp", "-o", dir} + options);
    if (generated.code != 0) {
        qWarning().noquote() << generated.out << generated.err;
        return {};
    }
    QString log;
    if (!SdkTest::buildProject(dir, RTSTUDIO_BUILD_DIR, &log)) {
        qWarning().noquote() << log;
        return {};
    }
    return dir;
}

void TestSdkFixtures::generatedProjectRuns_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("type");
    QTest::addColumn<QStringList>("options");
    const QString codegen = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/");
    const QStringList idl{"--idl-dir", codegen + "idl"};
    QTest::newRow("every configuration type, with its test component")
        << codegen + "ConfigComp.xml" << "ConfigComp" << (idl + QStringList{"--test-component"});
    QTest::newRow("data ports of many types") << codegen + "DataPortsComp.xml" << "DataPortsComp" << idl;
    QTest::newRow("services of a multi-module IDL") << codegen + "ServicesComp.xml" << "ServicesComp" << idl;
    QTest::newRow("documented") << codegen + "DocumentedComp.xml" << "DocumentedComp" << idl;
    QTest::newRow("OpenRTP's sample") << codegen + "SampleComp.xml" << "SampleComp" << idl;
    // FSM and multi-mode kinds run their data-flow part.
    QTest::newRow("all component kinds") << RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/KindsProbe.xml") << "KindsProbe"
                                         << QStringList{"--idl-dir", RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/SdkGreeter")};
}

void TestSdkFixtures::generatedProjectRuns()
{
    QFETCH(QString, profile);
    QFETCH(QString, type);
    QFETCH(QStringList, options);
    const QString dir = generateAndBuild(profile, type, options);
    QVERIFY2(!dir.isEmpty(), "generated project builds against the SDK");
    QVERIFY(QFile::exists(dir + "/build/src/" + type + "Comp"));
    const QString module = dir + "/build/src/" + type + ".so";
    const RtctlResult r = rtctl({"mgr", host() + "/manager.mgr", "load", module, "create", type});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    const QString instance = r.lines().value(0).trimmed();
    QVERIFY2(instance.startsWith(type), qPrintable(r.out));
    QVERIFY2(rtctl({"act", instance + ".rtc"}).code == 0, qPrintable(instance));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", instance + ".rtc"}).out.contains("Active"), 10000);
}

void TestSdkFixtures::examplesConnectToBuiltins()
{
    // The bundled example system's components, generated from their profiles, replace the
    // built-in types of the same name in this manager and connect like them.
    const QString examples = RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/RTCs/");
    const QString manager = host() + "/manager.mgr";
    RtctlResult r = rtctl({"mgr", manager, "create", "ConsoleIn?instance_name=BuiltinIn", "create",
                           "ConsoleOut?instance_name=BuiltinOut"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QStringList created;
    for (const QString &profile : {QStringLiteral("ConsoleIn0.xml"), QStringLiteral("ConsoleOut0.xml")}) {
        const QString dir = generateAndBuild(examples + profile, "example_" + QFileInfo(profile).completeBaseName(), {});
        QVERIFY2(!dir.isEmpty(), qPrintable(profile));
        const QStringList modules = QDir(dir + "/build/src").entryList({"*.so"}, QDir::Files);
        QCOMPARE(modules.size(), 1);
        const QString type = QFileInfo(modules.first()).completeBaseName();
        r = rtctl({"mgr", manager, "load", dir + "/build/src/" + modules.first(), "create",
                   type + "?instance_name=Generated" + type});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        created << "Generated" + type + ".rtc";
    }
    // Generated ConsoleIn feeds the built-in sink; the built-in source feeds generated ConsoleOut.
    for (const QStringList &link : {QStringList{created.at(0) + ":out", "BuiltinOut.rtc:in"},
                                    QStringList{"BuiltinIn.rtc:out", created.at(1) + ":in"}}) {
        r = rtctl(QStringList{"con"} + link);
        QVERIFY2(r.code == 0, qPrintable(link.join(' ') + ": " + r.out + r.err));
    }
    const QStringList all = created + QStringList{"BuiltinIn.rtc", "BuiltinOut.rtc"};
    r = rtctl(QStringList{"act"} + all);
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    for (const QString &component : all)
        QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", component}).out.contains("Active"), 10000);
}

namespace {

/// An RTC profile with one data port of every type in @p types, ins and outs alternating.
QByteArray everyTypeProfile(const Codegen::IdlTypeLibrary &library, const QList<Codegen::IdlDataType> &types)
{
    QByteArray ports;
    int index = 0;
    for (const Codegen::IdlDataType &type : types) {
        const QString file = QFileInfo(library.fileOf(type.scopedName)).fileName();
        ports += QStringLiteral("    <rtc:DataPorts xsi:type=\"rtcExt:dataport_ext\" rtcExt:position=\"LEFT\" "
                                "rtc:idlFile=\"%1\" rtc:type=\"%2\" rtc:name=\"p%3\" rtc:portType=\"%4\"/>\n")
                     .arg(file, type.scopedName)
                     .arg(index)
                     .arg(index % 2 ? QStringLiteral("DataOutPort") : QStringLiteral("DataInPort"))
                     .toUtf8();
        ++index;
    }
    return QByteArrayLiteral(
               "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n"
               "<rtc:RtcProfile rtc:version=\"0.3\" rtc:id=\"RTC:RTStudioTests:Test:EveryType:1.0.0\" "
               "xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\" "
               "xmlns:rtcExt=\"http://www.openrtp.org/namespaces/rtc_ext\" "
               "xmlns:rtcDoc=\"http://www.openrtp.org/namespaces/rtc_doc\" "
               "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n"
               "    <rtc:BasicInfo xsi:type=\"rtcExt:basic_info_ext\" rtc:version=\"1.0.0\" "
               "rtc:vendor=\"RTStudioTests\" rtc:maxInstances=\"1\" rtc:executionType=\"PeriodicExecutionContext\" "
               "rtc:executionRate=\"10.0\" rtc:description=\"A port of every data type\" rtc:category=\"Test\" "
               "rtc:componentKind=\"DataFlowComponent\" rtc:activityType=\"PERIODIC\" "
               "rtc:componentType=\"STATIC\" rtc:name=\"EveryType\"/>\n")
           + ports
           + QByteArrayLiteral("    <rtc:Language xsi:type=\"rtcExt:language_ext\" rtc:kind=\"C++\"/>\n"
                               "</rtc:RtcProfile>\n");
}

} // namespace

void TestSdkFixtures::everyDataTypeTheBuilderOffers()
{
    // The Builder's data type list comes from the bundled OpenRTM IDL, as here.
    const Codegen::IdlTypeLibrary library({RTSTUDIO_SOURCE_DIR + QStringLiteral("/corba/idl")});
    const QList<Codegen::IdlDataType> types = library.dataTypes();
    QVERIFY2(types.size() > 100, qPrintable(QString::number(types.size())));
    QFile profile(m_work.filePath("EveryType.xml"));
    QVERIFY(profile.open(QIODevice::WriteOnly));
    profile.write(everyTypeProfile(library, types));
    profile.close();
    const QString dir = generateAndBuild(profile.fileName(), "EveryType", {});
    QVERIFY2(!dir.isEmpty(), "a port of every data type builds against the SDK");
    const RtctlResult r = rtctl({"mgr", host() + "/manager.mgr", "load", dir + "/build/src/EveryType.so", "create",
                                 "EveryType"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    const RtctlResult ports = rtctl({"cat", "-l", "EveryType0.rtc"});
    QVERIFY2(ports.code == 0, qPrintable(ports.err));
    for (const Codegen::IdlDataType &type : types) {
        // RTC.idl and SDOPackage.idl put their ids under a prefix (omg.org, org.omg).
        const QString path = QString(type.scopedName).replace("::", "/");
        const QRegularExpression id("IDL:([\\w.]+/)?" + QRegularExpression::escape(path) + ":1\\.0\\b");
        QVERIFY2(ports.out.contains(id), qPrintable(type.scopedName));
    }
    QVERIFY(rtctl({"act", "EveryType0.rtc"}).code == 0);
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "EveryType0.rtc"}).out.contains("Active"), 10000);
}

QString TestSdkFixtures::receivedValues(const QString &component)
{
    return LiveTest::componentStatus(
        m_orb, QStringLiteral("corbaname::%1#fixhost.host_cxt/%2").arg(m_live.namingServer(), component),
        "received_values");
}

void TestSdkFixtures::generatedStateMachineFollowsEvents()
{
    // EventPorts: the generated static FSM with the user's condition, driven by built-in sources
    // through connectors that name the event (fsm_event_name); the sink sees each state change.
    const QString dir = m_work.filePath("Turnstile");
    QString log;
    QVERIFY2(Turnstile::generate(dir, &log), qPrintable(log));
    QVERIFY2(SdkTest::buildProject(dir, RTSTUDIO_BUILD_DIR, &log), qPrintable(log));

    const QString manager = host() + "/manager.mgr";
    RtctlResult r = rtctl({"mgr", manager, "load", dir + "/build/src/Turnstile.so", "create", "Turnstile?instance_name=Gate",
               "create", "ConsoleIn?instance_name=Coins&exec_cxt.periodic.rate=20", "create",
               "ConsoleIn?instance_name=Pushes&exec_cxt.periodic.rate=4", "create",
               "ConsoleOut?instance_name=GateState"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    for (const QStringList &link : {QStringList{"-p", "fsm_event_name=coin", "Coins.rtc:out", "Gate.rtc:control"},
                                    QStringList{"Gate.rtc:state", "GateState.rtc:in"}}) {
        r = rtctl(QStringList{"con"} + link);
        QVERIFY2(r.code == 0, qPrintable(link.join(' ') + ": " + r.out + r.err));
    }
    r = rtctl({"act", "GateState.rtc", "Gate.rtc", "Coins.rtc"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    // Locked at first; coins 1 … 9 fail the condition, 10 opens; later coins keep it open.
    QTRY_COMPARE_WITH_TIMEOUT(receivedValues("GateState.rtc"), QStringLiteral("0,1"), 20000);

    // Pushes: the first one locks the gate again, the next one raises the alarm, which only a
    // reset leaves. They come far apart (4 Hz) against the gate's 100 Hz, so that each one is
    // handled in its own cycle and the state between them is written.
    QVERIFY(rtctl({"deact", "Coins.rtc"}).code == 0);
    r = rtctl({"con", "-p", "fsm_event_name=push", "Pushes.rtc:out", "Gate.rtc:control"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY(rtctl({"act", "Pushes.rtc"}).code == 0);
    QTRY_COMPARE_WITH_TIMEOUT(receivedValues("GateState.rtc"), QStringLiteral("0,1,0,2"), 20000);
    QVERIFY(rtctl({"deact", "Pushes.rtc", "Gate.rtc"}).code == 0);
}

QTEST_GUILESS_MAIN(TestSdkFixtures)
#include "tst_sdkfixtures.moc"
