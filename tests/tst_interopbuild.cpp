// SPDX-License-Identifier: MIT
// The generated C++ project runs on a real OpenRTM-aist 2.x as well as on the component SDK: the
// SdkGreeter fixture is generated with `rtctl gen`, finished with the same user code as in
// tst_sdkgenerated, configured with OpenRTM-aist's own CMake package and built. The standalone
// SdkGreeterComp registers in omniNames and is activated and reconfigured with rtctl (OpenRTM
// keeps a changed set inactive until it is activated: the new gain must reach the bound variable,
// seen through data from rtmanager's ConsoleIn to its ConsoleOut across both runtimes; the vector
// limits too), and
// OpenRTM's rtcd2 loads the module from the load path and creates an instance. The code
// generator's other fixtures (tests/data/codegen) build against OpenRTM-aist too, and its
// rtcprof2 reads their modules.
//
// Needs the prefix of an OpenRTM-aist installation (CMake cache variable RTSTUDIO_OPENRTM_PREFIX,
// ctest label "interop"); without one the test is skipped.
#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkgreeteredits.h"
#include "sdkproject.h"
#include "turnstileedits.h"

#include <QtTest>

#include <functional>

namespace {

const QString fixtureDir = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/SdkGreeter");
const QString openRtmPrefix = QStringLiteral(RTSTUDIO_OPENRTM_PREFIX);

/// Configures the generated project in @p dir with OpenRTM-aist's CMake package and builds it
/// in `dir`/build; false with the tools' output in @p log.
bool buildAgainstOpenRtm(const QString &dir, QString *log)
{
    return SdkTest::buildProject(dir, openRtmPrefix, log);
}

/// How a process that should still run ended, with what it wrote.
QString exitReport(QProcess *process)
{
    return QStringLiteral("state %1, error '%2', exit status %3, code %4, output: %5")
        .arg(int(process->state()))
        .arg(process->errorString())
        .arg(int(process->exitStatus()))
        .arg(process->exitCode())
        .arg(QString::fromLocal8Bit(process->readAllStandardOutput().right(2000)));
}

} // namespace

class TestInteropBuild : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void builtWithOpenRtmPackage();
    void codegenFixturesBuild_data();
    void codegenFixturesBuild();
    void standaloneComponentIsDrivenByRtctl();
    void configurationSetIsActivated();
    void moduleLoadsIntoRtcd();
    void moduleLoadedAndCreatedThroughRtctl();
    void generatedStateMachineRuns();

private:
    RtctlResult rtctl(const QStringList &arguments);
    QString componentPath(const QString &context, const QString &name) const;
    QStringList managerOptions(const QString &context) const;
    QString lastValue(const QString &path);
    /// Waits (20 s at most) until the last value of `sink` is a `wanted` one; the values seen on
    /// the way in `seen`.
    bool waitForSink(const QString &sink, const std::function<bool(long)> &wanted, QString *seen);

    QTemporaryDir m_work;
    QString m_project;
    QString m_buildLog;
    LiveTest::LiveSystem m_live;
    CORBA::ORB_var m_orb;
};

RtctlResult TestInteropBuild::rtctl(const QStringList &arguments)
{
    return runRtctl(arguments, {{QStringLiteral("RTCTREE_NAMESERVERS"), QString()}});
}

QString TestInteropBuild::componentPath(const QString &context, const QString &name) const
{
    return QStringLiteral("/%1/%2.host_cxt/%3.rtc").arg(m_live.namingServer(), context, name);
}

/// Options of an OpenRTM-aist manager (`-o key:value`) that keep it to this test's name server.
/// Without a manager servant it looks for no master manager (by default one on port 2810, which
/// another program may serve, and a master can shut its slaves down).
QStringList TestInteropBuild::managerOptions(const QString &context) const
{
    const QStringList options {
        "corba.nameservers:" + m_live.namingServer(),
        "corba.endpoints:127.0.0.1:", "naming.formats:" + context + ".host_cxt/%n.rtc",
        "manager.corba_servant:NO", "logger.enable:NO"};
    QStringList arguments;
    for (const QString &option : options)
        arguments << "-o" << option;
    return arguments;
}

QString TestInteropBuild::lastValue(const QString &path)
{
    // rtmanager's ConsoleOut reports what it received last in its status list.
    return LiveTest::componentStatus(
        m_orb, QStringLiteral("corbaname::%1#%2").arg(m_live.namingServer(), path.section('/', 2)), "last_value");
}

bool TestInteropBuild::waitForSink(const QString &sink, const std::function<bool(long)> &wanted,
                                   QString *seen)
{
    QStringList values;
    const bool found = QTest::qWaitFor(
        [&] {
            const QString value = lastValue(sink);
            if (values.isEmpty() || values.last() != value)
                values << value;
            return !value.isEmpty() && wanted(value.toLong());
        },
        20000);
    *seen = values.mid(qMax(0, int(values.size()) - 40)).join(' ');
    return found;
}

void TestInteropBuild::initTestCase()
{
    if (openRtmPrefix.isEmpty())
        QSKIP("skipped: no OpenRTM-aist");
    const QString config = openRtmPrefix + "/lib/cmake/openrtm-2.1/OpenRTMConfig.cmake";
    QVERIFY2(QFile::exists(config), qPrintable("RTSTUDIO_OPENRTM_PREFIX has no " + config));
    LiveTest::useOpenRtm(openRtmPrefix);

    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QVERIFY(m_work.isValid());
    m_project = m_work.filePath("SdkGreeter");
    const QStringList generate {
        "gen", fixtureDir + "/RTC.xml", "--lang", "cpp", "-o", m_project, "--idl-dir", fixtureDir};
    RtctlResult generated = runRtctl(generate);
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QString error;
    for (const SdkTest::UserEdit &edit : SdkGreeter::userEdits)
        QVERIFY2(SdkTest::applyEdit(m_project, edit, &error), qPrintable(error));
    RtctlResult merged = runRtctl(generate + QStringList {"--merge"});
    QVERIFY2(merged.code == 0, qPrintable(merged.out + merged.err));

    QVERIFY2(buildAgainstOpenRtm(m_project, &m_buildLog), qPrintable(m_buildLog));
    QVERIFY(QFile::exists(m_project + "/build/src/SdkGreeter.so"));
    QVERIFY(QFile::exists(m_project + "/build/src/SdkGreeterComp"));

    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
}

void TestInteropBuild::cleanupTestCase()
{
    m_live.stopAll();
}

void TestInteropBuild::builtWithOpenRtmPackage()
{
    // The project found OpenRTM-aist's package, not the SDK of a build tree.
    QFile cache(m_project + "/build/CMakeCache.txt");
    QVERIFY(cache.open(QIODevice::ReadOnly));
    const QByteArray text = cache.readAll();
    const QRegularExpression dir(QStringLiteral("^OpenRTM_DIR:PATH=(.*)$"),
                                 QRegularExpression::MultilineOption);
    const QRegularExpressionMatch match = dir.match(QString::fromUtf8(text));
    QVERIFY2(match.hasMatch(), "OpenRTM_DIR not in the cache");
    QCOMPARE(QDir(match.captured(1)).canonicalPath(),
             QDir(openRtmPrefix + "/lib/cmake/openrtm-2.1").canonicalPath());
    // and the module links OpenRTM-aist's runtime library.
    QProcess ldd;
    ldd.start("ldd", {m_project + "/build/src/SdkGreeter.so"});
    QVERIFY(ldd.waitForFinished(20000));
    QVERIFY2(ldd.readAllStandardOutput().contains("libRTC2.so"),
             "SdkGreeter.so does not use libRTC2");
}

void TestInteropBuild::codegenFixturesBuild_data()
{
    QTest::addColumn<QString>("name");
    for (const char *name :
         {"ConfigComp", "DataPortsComp", "DocumentedComp", "SampleComp", "ServicesComp"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

void TestInteropBuild::codegenFixturesBuild()
{
    // The golden-file fixtures of the code generator cover the templates' other branches.
    QFETCH(QString, name);
    const QString fixtures = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen");
    const QString dir = m_work.filePath("codegen/" + name);
    const RtctlResult generated = runRtctl({"gen", fixtures + '/' + name + ".xml", "--lang", "cpp",
                                            "-o", dir, "--idl-dir", fixtures + "/idl"});
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QString log;
    QVERIFY2(buildAgainstOpenRtm(dir, &log), qPrintable(log));
    // OpenRTM-aist's profiler loads the module and reads its specification through <Name>Init.
    QProcess rtcprof;
    rtcprof.start(openRtmPrefix + "/bin/rtcprof2", {dir + "/build/src/" + name + ".so"});
    QVERIFY(rtcprof.waitForFinished(30000));
    const QByteArray profile = rtcprof.readAll();
    QVERIFY2(profile.contains("implementation_id: " + name.toUtf8()), profile.constData());
}

void TestInteropBuild::standaloneComponentIsDrivenByRtctl()
{
    QString error;
    QProcess *comp = m_live.startProcess(m_project + "/build/src/SdkGreeterComp",
                                         QStringList {"-f", m_project + "/rtc.conf"}
                                             + managerOptions("interop"),
                                         QString(), &error, 0);
    QVERIFY2(comp != nullptr, qPrintable(error));
    const QString path = componentPath("interop", "SdkGreeter0");
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", path}).code == 0, 30000);
    RtctlResult r = rtctl({"act", path});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", path}).out.contains("Active"), 10000);
    QVERIFY2(comp->state() == QProcess::Running, qPrintable(exitReport(comp)));
}

void TestInteropBuild::configurationSetIsActivated()
{
    const QString greeter = componentPath("interop", "SdkGreeter0");
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", greeter}).out.contains("Active"), 10000);

    // rtmanager's ConsoleIn counts up into the OpenRTM component, which scales by its gain.
    QString error;
    const QStringList options {"corba.nameservers=" + m_live.namingServer(),
                               "naming.formats=ours.host_cxt/%n.rtc",
                               "manager.naming_formats=ours.host_cxt/%n.mgr",
                               "manager.components.precreate=ConsoleIn?exec_cxt.periodic.rate=50,"
                               "ConsoleOut?instance_name=Scaled"};
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, LiveTest::freePort(), options, &error),
             qPrintable(error));
    const QString source = componentPath("ours", "ConsoleIn0");
    const QString sink = componentPath("ours", "Scaled");
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", sink}).code == 0, 20000);
    RtctlResult r = rtctl({"con", source + ":out", greeter + ":in"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"con", greeter + ":out", sink + ":in"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    // Wide limits first (a vector parameter read by the generated VectorConvert.h), so that no
    // value is clamped while the counter grows.
    r = rtctl({"conf", greeter, "set", "limits", "0, 1000000000"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"act", source, sink});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    // The default gain 2.
    QString seen;
    QVERIFY2(waitForSink(
                 sink, [](long v) { return v > 0 && v % 2 == 0 && v % 3 != 0; }, &seen),
             qPrintable("gain 2, values seen: " + seen));

    r = rtctl({"conf", greeter, "set", "gain", "3"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    // OpenRTM-aist reports no active set between the set and its activation: rtctl activated it.
    r = rtctl({"conf", "--json", greeter});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QCOMPARE(r.json().object()["active"].toString(), QString("default"));
    QCOMPARE(rtctl({"conf", greeter, "get", "gain"}).out, QString("3\n"));
    QVERIFY2(waitForSink(
                 sink, [](long v) { return v > 0 && v % 3 == 0 && v % 2 != 0; }, &seen),
             qPrintable("gain 3, values seen: " + seen));
    r = rtctl({"conf", greeter, "set", "limits", "0,7"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_COMPARE_WITH_TIMEOUT(lastValue(sink), QString("7"), 20000);
}

void TestInteropBuild::moduleLoadsIntoRtcd()
{
    QFile conf(m_work.filePath("rtcd.conf"));
    QVERIFY(conf.open(QIODevice::WriteOnly | QIODevice::Text));
    conf.write("manager.modules.load_path: " + m_project.toUtf8()
               + "/build/src\n"
                 "manager.components.precreate: SdkGreeter\n");
    conf.close();
    QString error;
    QProcess *rtcd = m_live.startProcess(
        openRtmPrefix + "/bin/rtcd2", QStringList {"-f", conf.fileName()} + managerOptions("rtcd"),
        QString(), &error, 0);
    QVERIFY2(rtcd != nullptr, qPrintable(error));
    const QString path = componentPath("rtcd", "SdkGreeter0");
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", path}).code == 0, 30000);
    RtctlResult r = rtctl({"ls", QStringLiteral("/%1/rtcd.host_cxt").arg(m_live.namingServer())});
    QVERIFY2(r.out.contains("SdkGreeter0.rtc"), qPrintable(r.out + r.err));
    QVERIFY2(rtcd->state() == QProcess::Running, qPrintable(exitReport(rtcd)));
}

void TestInteropBuild::moduleLoadedAndCreatedThroughRtctl()
{
    // An rtcd2 master as users run it: it loads the module by name from its load path and creates
    // the component in a slave process it starts; the slave is then driven by its own path.
    const quint16 masterPort = LiveTest::freePort();
    QString error;
    QProcess *master = m_live.startRtcdMaster(openRtmPrefix, m_work.filePath("master.conf"), masterPort,
                                              "loaded", {"manager.modules.load_path: " + m_project + "/build/src"},
                                              &error);
    QVERIFY2(master != nullptr, qPrintable(error));
    const QString dir = QStringLiteral("/%1/loaded.host_cxt").arg(m_live.namingServer());
    const QString masterPath = dir + "/manager.mgr";
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"mgr", masterPath, "list"}).code == 0, 30000);

    // Loading and creating start rtcprof2 and a slave rtcd2: slow on a busy machine.
    RtctlResult r = rtctl({"mgr", "--timeout", "30000", masterPath, "load", "SdkGreeter.so", "list"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains("/build/src/SdkGreeter.so"), qPrintable(r.out));
    QVERIFY2(r.out.contains("  SdkGreeter\n"), qPrintable(r.out));
    r = rtctl({"mgr", "--timeout", "30000", masterPath, "create", "SdkGreeter?instance_name=Loaded0"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QCOMPARE(r.out, QString("Loaded0\n"));
    const QString loaded = dir + "/Loaded0.rtc";
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", loaded}).code == 0, 10000);
    QCOMPARE(rtctl({"act", loaded}).code, 0);
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", loaded}).out.contains("Active"), 10000);

    // The slave rtcd2 started, reached below its master: a module loaded by its file and a
    // second component created there directly.
    const QString slave = masterPath + "/slave0.mgr";
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"ls", slave}).lines().contains("Loaded0.rtc"), 10000);
    r = rtctl({"mgr", "--timeout", "30000", slave, "load", m_project + "/build/src/SdkGreeter.so", "create",
               "SdkGreeter?instance_name=Direct0", "list"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.startsWith("Direct0\n"), qPrintable(r.out));
    QVERIFY2(r.out.contains("  Direct0  SdkGreeter") && r.out.contains("  Loaded0  SdkGreeter"),
             qPrintable(r.out));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", dir + "/Direct0.rtc"}).code == 0, 10000);
    QCOMPARE(rtctl({"act", slave + "/Direct0.rtc"}).code, 0);
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", dir + "/Direct0.rtc"}).out.contains("Active"), 10000);

    // Deleted through the master, which leaves it to the slave.
    for (const char *name : {"Loaded0", "Direct0"}) {
        r = rtctl({"mgr", masterPath, "delete", name});
        QVERIFY2(r.code == 0, qPrintable(r.err));
    }
    QTRY_VERIFY_WITH_TIMEOUT(!rtctl({"ls", dir}).out.contains("Loaded0.rtc"), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(!rtctl({"ls", dir}).out.contains("Direct0.rtc"), 10000);
    QVERIFY2(master->state() == QProcess::Running, qPrintable(exitReport(master)));
}

void TestInteropBuild::generatedStateMachineRuns()
{
    // The state machine generated for an EventPort builds against OpenRTM-aist's StaticFSM and
    // Macho and starts in its initial state, which the user's code writes to rtmanager's sink.
    // (OpenRTM-aist 2.1.0's own EventInPort declares no marshaling type, so it refuses every
    // connection; the events themselves are exercised against the SDK in tst_sdkfixtures.)
    const QString dir = m_work.filePath("Turnstile");
    QString log;
    QVERIFY2(Turnstile::generate(dir, &log), qPrintable(log));
    QVERIFY2(buildAgainstOpenRtm(dir, &log), qPrintable(log));

    QString error;
    QProcess *comp = m_live.startProcess(dir + "/build/src/TurnstileComp",
                                         QStringList {"-f", dir + "/rtc.conf"} + managerOptions("fsm"), QString(),
                                         &error, 0);
    QVERIFY2(comp != nullptr, qPrintable(error));
    const QString gate = componentPath("fsm", "Turnstile0");
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", gate}).code == 0, 30000);
    const QStringList options {"corba.nameservers=" + m_live.namingServer(), "naming.formats=sink.host_cxt/%n.rtc",
                               "manager.naming_formats=sink.host_cxt/%n.mgr",
                               "manager.components.precreate=ConsoleOut?instance_name=GateState"};
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, LiveTest::freePort(), options, &error), qPrintable(error));
    const QString sink = componentPath("sink", "GateState");
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", sink}).code == 0, 20000);
    RtctlResult r = rtctl({"con", gate + ":state", sink + ":in"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"act", sink, gate});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_COMPARE_WITH_TIMEOUT(lastValue(sink), QString("0"), 20000);
    QVERIFY2(comp->state() == QProcess::Running, qPrintable(exitReport(comp)));
}

QTEST_GUILESS_MAIN(TestInteropBuild)
#include "tst_interopbuild.moc"
