// SPDX-License-Identifier: MIT
// Every profile the Builder's tests know, and the bundled examples' components, generated in C++,
// built against the component SDK of this build tree, loaded into one rtmanager and created there;
// the example pair is connected to built-in components and activated. Together the profiles cover
// every port kind, the data types the Builder offers, provided and required service ports of a
// multi-module user IDL and every configuration type including vectors.
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkproject.h"

#include <QtTest>

class TestSdkFixtures : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void generatedProjectRuns_data();
    void generatedProjectRuns();
    void examplesConnectToBuiltins();

private:
    RtctlResult rtctl(const QStringList &arguments);
    QString host() const { return QStringLiteral("/%1/fixhost.host_cxt").arg(m_live.namingServer()); }
    /// Generates and builds @p profile into m_work/<name>; the module path or empty.
    QString generateAndBuild(const QString &profile, const QString &name, const QStringList &options);

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
};

RtctlResult TestSdkFixtures::rtctl(const QStringList &arguments)
{
    return runRtctl(arguments, {{QStringLiteral("RTCSH_CWD"), host()}, {QStringLiteral("RTCTREE_NAMESERVERS"), QString()}});
}

void TestSdkFixtures::initTestCase()
{
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
    const QString codegen = QStringLiteral(RTSTUDIO_TEST_DATA_DIR "/codegen/");
    const QStringList idl{"--idl-dir", codegen + "idl"};
    QTest::newRow("every configuration type, with its test component")
        << codegen + "ConfigComp.xml" << "ConfigComp" << (idl + QStringList{"--test-component"});
    QTest::newRow("data ports of many types") << codegen + "DataPortsComp.xml" << "DataPortsComp" << idl;
    QTest::newRow("services of a multi-module IDL") << codegen + "ServicesComp.xml" << "ServicesComp" << idl;
    QTest::newRow("documented") << codegen + "DocumentedComp.xml" << "DocumentedComp" << idl;
    QTest::newRow("OpenRTP's sample") << codegen + "SampleComp.xml" << "SampleComp" << idl;
    // FSM and multi-mode kinds run their data-flow part.
    QTest::newRow("all component kinds") << QStringLiteral(RTSTUDIO_TEST_DATA_DIR "/sdk/KindsProbe.xml") << "KindsProbe"
                                         << QStringList{"--idl-dir", RTSTUDIO_TEST_DATA_DIR "/sdk/SdkGreeter"};
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
    const QString examples = QStringLiteral(RTSTUDIO_SOURCE_DIR "/resources/examples/ConsoleInOut/RTCs/");
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

QTEST_GUILESS_MAIN(TestSdkFixtures)
#include "tst_sdkfixtures.moc"
