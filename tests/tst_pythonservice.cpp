// SPDX-License-Identifier: MIT
// Service ports of Python components on RT Studio's runtime: IDL compiled by `rtctl idl --lang
// python` (omniORBpy's layout), Python servants behind a dynamic skeleton, Python consumers calling
// through the runtime, all ordinary CORBA on the wire:
// - the stubs of data/pythonidl/Calc.idl (every construct) import and convert values to CDR and
// back;
// - bad IDL is reported with its file and line;
// - a Python provider and consumer of ours exchange results, out/inout values, sequences,
//   attributes and a user exception; an undeclared exception in a servant comes back as UNKNOWN;
// - stubs of IDL including IDL of its own folder (Canvas.idl, Shapes.idl) under `#pragma prefix`
//   call across processes, a base interface's user exception coming back under its prefixed id;
// - wide characters, unions, object references and any as parameters and results (Kinds.idl): a
//   servant's _this() passed to the provider, which calls it back, the ORB's string_to_object; and
//   the same both ways with a C++ component of ours built against the SDK (data/sdkkinds);
// - OpenRTM-aist-Python's SimpleService example unchanged (shared corpus; skipped with the reason
//   when absent): its consumer's commands reach its provider and the answers come back;
// - a Python component of ours calls rtmanager's C++ MyServiceProvider built-in and OpenRTM-aist's
//   C++ MyServiceProvider example built against the SDK; the C++ MyServiceConsumer built-in and
//   example call its Python servant.
#include "hostrtctl.h"
#include "pythonenvironment.h"
#include "sdkproject.h"

#include <QtTest>

namespace {

constexpr const char *NoPythonCorpus
    = "the OpenRTM-aist-Python examples corpus (shared/conformance/openrtm-python-examples beside the project) "
      "is absent";

constexpr int runTimeoutMs = 30 * 1000;
const QString hostName = QStringLiteral("pysvchost");

QString dataFile(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/pythonidl/")) + name;
}

QString autoTestDir()
{
    return RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-python-examples/AutoTest/");
}

QString simpleServiceDir()
{
    return RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-python-examples/SimpleService/");
}

} // namespace

class TestPythonService : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void stubsOfEveryConstructImportAndConvert();
    void badIdlIsReportedWithItsLine();
    void pythonProviderAndConsumerExchangeCalls();
    void stubsOfIncludingIdlWithPrefixesCall();
    void callsCarryEveryParameterKind();
    void everyParameterKindToAndFromCxx();
    void pythonAndCxxComponentsCallEachOther();
    void pythonComponentAndSdkExamplesCallEachOther();
    void simpleServiceExamplesRunUnchanged();
    void autoTestExamplesRunUnchanged();

private:
    RtctlResult rtctl(const QStringList &arguments) const { return m_host.run(arguments); }
    bool rtctlSucceeds(const QStringList &arguments) const { return m_host.succeeds(arguments); }
    /// Compiles @p idls into a folder of the first one's name under the test's; empty when rtctl
    /// idl fails.
    QString compileIdl(const QStringList &idls);
    /// An rtc.conf registering in the test's name server, @p extraConf after.
    QString writeConf(const QString &name, const QString &extraConf = {});
    /// Starts `python3 @p script -f <conf>` with the stubs in @p stubs; waits until @p instance is
    /// registered.
    QProcess *startScript(const QString &script, const QString &stubs, const QString &instance,
                          const QString &extraConf = {});
    QString printed(QProcess *process) { return m_printed.of(process); }
    /**
     * Ends @p components with `rtctl exit` and waits until their names have left the name server,
     * so that a later test's components of the same names are not mistaken for them.
     */
    bool endComponents(const QStringList &components);
    /// Writes @p command to @p consumer (OpenRTM's SimpleService consumer); true once it printed @p
    /// answer.
    bool commandAnswers(QProcess *consumer, const QByteArray &command, const QString &answer);

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
    LiveTest::HostRtctl m_host {m_live, hostName};
    QProcess *m_manager = nullptr;
    CORBA::ORB_var m_orb;
    LiveTest::PrintedOutput m_printed;
};

void TestPythonService::initTestCase()
{
    QVERIFY(m_work.isValid());
    QVERIFY2(QFileInfo::exists(RTSTUDIO_PYTHON_PATH + QStringLiteral("/omniORB/__init__.py")),
             "build rtpython first");
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_manager = m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), hostName, {}, &error);
    QVERIFY2(m_manager, qPrintable(error));
}

QString TestPythonService::compileIdl(const QStringList &idls)
{
    const QString output = m_work.filePath(QFileInfo(idls.value(0)).completeBaseName());
    const RtctlResult compiled
        = runRtctl(QStringList {"idl", "--lang", "python", "-o", output} + idls);
    if (compiled.code != 0) {
        qWarning().noquote() << compiled.out << compiled.err;
        return {};
    }
    return output;
}

QString TestPythonService::writeConf(const QString &name, const QString &extraConf)
{
    const QString conf = m_work.filePath(name + QStringLiteral(".conf"));
    QFile file(conf);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return {};
    file.write(QStringLiteral(
                   "corba.nameservers: %1\nnaming.formats: %2.host_cxt/%n.rtc\nlogger.enable: NO\n%3\n")
                   .arg(m_live.namingServer(), hostName, LiveTest::NoMasterLine)
                   .toUtf8()
               + extraConf.toUtf8());
    return conf;
}

QProcess *TestPythonService::startScript(const QString &script, const QString &stubs,
                                         const QString &instance, const QString &extraConf)
{
    const QString conf = writeConf(QFileInfo(script).baseName(), extraConf);
    QString error;
    const QProcessEnvironment environment = LiveTest::pythonEnvironment(
        stubs + QLatin1Char(':') + RTSTUDIO_PYTHON_PATH,
        QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD));
    QProcess *process = m_live.startRegistered(
        QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE), {script, QStringLiteral("-f"), conf},
        [this, &instance] { return rtctl({QStringLiteral("ls")}).out.contains(instance); }, &error,
        runTimeoutMs, environment);
    if (!process)
        qWarning().noquote() << error;
    return process;
}

bool TestPythonService::endComponents(const QStringList &components)
{
    for (const QString &component : components) {
        if (!rtctlSucceeds({QStringLiteral("exit"), component}))
            return false;
    }
    return QTest::qWaitFor(
        [&] {
            const QString listed = rtctl({QStringLiteral("ls")}).out;
            return std::none_of(
                components.begin(), components.end(),
                [&listed](const QString &component) { return listed.contains(component); });
        },
        runTimeoutMs);
}

bool TestPythonService::commandAnswers(QProcess *consumer, const QByteArray &command,
                                       const QString &answer)
{
    // The consumer reads one command per execution from its standard input.
    const qsizetype before = printed(consumer).size();
    consumer->write(command + '\n');
    return QTest::qWaitFor([&] { return printed(consumer).indexOf(answer, before) >= 0; },
                           runTimeoutMs);
}

void TestPythonService::stubsOfEveryConstructImportAndConvert()
{
    const QString stubs = compileIdl(
        {dataFile(QStringLiteral("Calc.idl")), dataFile(QStringLiteral("Scopes.idl"))});
    QVERIFY(!stubs.isEmpty());
    for (const char *file :
         {"Calc_idl.py", "PyCalc/__init__.py", "PyCalc__POA/__init__.py", "Scopes_idl.py",
          "Outer/__init__.py", "Outer__POA/__init__.py", "_GlobalIDL/__init__.py"})
        QVERIFY2(QFileInfo::exists(stubs + QLatin1Char('/') + QLatin1String(file)), file);
    QProcess python;
    python.setProcessEnvironment(
        LiveTest::pythonEnvironment(stubs + QLatin1Char(':') + RTSTUDIO_PYTHON_PATH,
                                    QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD)));
    python.start(QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE),
                 {dataFile(QStringLiteral("stubs.py"))});
    QVERIFY(python.waitForFinished(runTimeoutMs));
    const QString output
        = QString::fromLocal8Bit(python.readAllStandardOutput() + python.readAllStandardError());
    QVERIFY2(python.exitStatus() == QProcess::NormalExit && python.exitCode() == 0,
             qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("stubs: ok")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("scopes: ok")), qPrintable(output));
    // Only the modules the files declare: no package for an interface's name.
    QVERIFY(!QFileInfo::exists(stubs + QStringLiteral("/GlobalThing")));
}

void TestPythonService::badIdlIsReportedWithItsLine()
{
    const QString broken = dataFile(QStringLiteral("Broken.idl"));
    const RtctlResult compiled
        = runRtctl({"idl", "--lang", "python", "-o", m_work.filePath("broken"), broken});
    QCOMPARE(compiled.code, 1);
    QVERIFY2(compiled.err.contains(broken + QStringLiteral(":7:3: error:")),
             qPrintable(compiled.err));
    QVERIFY(!QFileInfo::exists(m_work.filePath("broken")));
    QCOMPARE(runRtctl({"idl", "--lang", "cobol", broken}).code, 2);
}

void TestPythonService::pythonProviderAndConsumerExchangeCalls()
{
    const QString stubs = compileIdl({dataFile(QStringLiteral("Calc.idl"))});
    QVERIFY(!stubs.isEmpty());
    QProcess *provider = startScript(dataFile(QStringLiteral("PyCalcProvider.py")), stubs,
                                     QStringLiteral("PyCalcProvider0.rtc"));
    QVERIFY(provider);
    QProcess *consumer = startScript(dataFile(QStringLiteral("PyCalcConsumer.py")), stubs,
                                     QStringLiteral("PyCalcConsumer0.rtc"));
    QVERIFY(consumer);
    QVERIFY(rtctlSucceeds({"con", "PyCalcConsumer0.rtc:Calc", "PyCalcProvider0.rtc:Calc"}));
    // A provider's object answers while its component is active.
    for (const char *component : {"PyCalcProvider0.rtc", "PyCalcConsumer0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(consumer).contains(QLatin1String("consumer: done")),
                              qPrintable(printed(consumer) + printed(provider)), runTimeoutMs);
    const QString out = printed(consumer);
    for (const char *line : {"consumer: total 6.0 7.5\n", "consumer: split (3, 0.25)\n",
                             "consumer: accumulate (10, [1, 2, 3, 4])\n",
                             "consumer: flip MULTIPLY\n", "consumer: later 120 7\n",
                             "consumer: name renamed calls 6\n", "consumer: TooMany 4 6 terms\n",
                             "consumer: UNKNOWN\n"})
        QVERIFY2(out.contains(QLatin1String(line)), qPrintable(QLatin1String(line) + out));
    QVERIFY2(provider->state() == QProcess::Running, "the provider ended");
    QVERIFY2(printed(provider).contains(QLatin1String("provider: total of ['a', 'b', 'c']")),
             qPrintable(printed(provider)));
    QVERIFY(endComponents(
        {QStringLiteral("PyCalcConsumer0.rtc"), QStringLiteral("PyCalcProvider0.rtc")}));
    m_live.stop(consumer);
    m_live.stop(provider);
}

void TestPythonService::stubsOfIncludingIdlWithPrefixesCall()
{
    // Canvas.idl includes Shapes.idl of its folder, whose type ids have a #pragma prefix.
    const QString stubs = compileIdl({dataFile(QStringLiteral("Canvas.idl")), dataFile(QStringLiteral("Shapes.idl"))});
    QVERIFY(!stubs.isEmpty());
    QProcess *provider = startScript(dataFile(QStringLiteral("PyPainterProvider.py")), stubs,
                                     QStringLiteral("PyPainterProvider0.rtc"));
    QVERIFY(provider);
    QProcess *consumer = startScript(dataFile(QStringLiteral("PyPainterConsumer.py")), stubs,
                                     QStringLiteral("PyPainterConsumer0.rtc"));
    QVERIFY(consumer);
    QVERIFY(rtctlSucceeds({"con", "PyPainterConsumer0.rtc:Paint", "PyPainterProvider0.rtc:Paint"}));
    for (const char *component : {"PyPainterProvider0.rtc", "PyPainterConsumer0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(consumer).contains(QLatin1String("consumer: done")),
                              qPrintable(printed(consumer) + printed(provider)), runTimeoutMs);
    const QString out = printed(consumer);
    // A user exception of the base interface crosses under its prefixed id, raised as its class.
    for (const char *line : {"consumer: ids IDL:example.org/PyShapes/Circle:1.0 IDL:PyCanvas/Scene:1.0\n",
                             "consumer: total 15.7080\n", "consumer: Degenerate radius 0\n"})
        QVERIFY2(out.contains(QLatin1String(line)), qPrintable(QLatin1String(line) + out));
    QVERIFY2(printed(provider).contains(QLatin1String("provider: total of two circles")), qPrintable(printed(provider)));
    QVERIFY(endComponents({QStringLiteral("PyPainterConsumer0.rtc"), QStringLiteral("PyPainterProvider0.rtc")}));
    m_live.stop(consumer);
    m_live.stop(provider);
}

void TestPythonService::callsCarryEveryParameterKind()
{
    const QString stubs = compileIdl({dataFile(QStringLiteral("Kinds.idl"))});
    QVERIFY(!stubs.isEmpty());
    QProcess *provider = startScript(dataFile(QStringLiteral("PyKindsProvider.py")), stubs,
                                     QStringLiteral("PyKindsProvider0.rtc"));
    QVERIFY(provider);
    QProcess *consumer = startScript(dataFile(QStringLiteral("PyKindsConsumer.py")), stubs,
                                     QStringLiteral("PyKindsConsumer0.rtc"));
    QVERIFY(consumer);
    QVERIFY(rtctlSucceeds({"con", "PyKindsConsumer0.rtc:Echo", "PyKindsProvider0.rtc:Echo"}));
    for (const char *component : {"PyKindsProvider0.rtc", "PyKindsConsumer0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(consumer).contains(QLatin1String("consumer: done")),
                              qPrintable(printed(consumer) + printed(provider)), runTimeoutMs);
    const QString out = printed(consumer);
    // Wide characters and strings, a union in and inout, anys of a double, a string, an unsigned
    // short, a union, a struct, a TypeCode and a sequence in, out and as the result, references in, out and as the result: the
    // consumer's own servant (_this()) reaches the provider, which calls it back, and comes back
    // callable; the provider's own reference too; the ORB's string_to_object of an IOR.
    for (const QString &line : {QStringLiteral("consumer: letter ('\u00c9', '\u00e9\u00e9\u00e9')\n"),
                                QStringLiteral("consumer: reversed \u4e16 oll\u00e9h\n"),
                                QStringLiteral("consumer: swap (PyKinds.Pick(2, 't'), PyKinds.Pick(1, 5))\n"),
                                QStringLiteral("consumer: wrap True double 2.5\n"),
                                QStringLiteral("consumer: wrap True string 'corba_cdr'\n"),
                                QStringLiteral("consumer: wrap True unsigned short 7\n"),
                                QStringLiteral("consumer: wrap True PyKinds::Pick PyKinds.Pick(1, 5)\n"),
                                QStringLiteral("consumer: wrap True RTC::Time {'sec': 1, 'nsec': 2}\n"),
                                QStringLiteral("consumer: wrap True TypeCode CORBA.TypeCode('PyKinds::Pick')\n"),
                                QStringLiteral("consumer: wrap True sequence<long> [1, 2]\n"),
                                QStringLiteral("consumer: string_to_object _objref_Echo 42\n"),
                                QStringLiteral("consumer: relay 42 _objref_Echo True\n"),
                                QStringLiteral("consumer: relay nil None\n")})
        QVERIFY2(out.contains(line), qPrintable(line + out));
    QVERIFY2(printed(provider).contains(QLatin1String("provider: relay of a reference that answers calls() 42\n")),
             qPrintable(printed(provider)));
    QVERIFY(endComponents({QStringLiteral("PyKindsConsumer0.rtc"), QStringLiteral("PyKindsProvider0.rtc")}));
    m_live.stop(consumer);
    m_live.stop(provider);
}

void TestPythonService::everyParameterKindToAndFromCxx()
{
    // CxxKinds (data/sdkkinds), a C++ component of ours built against the SDK: it provides Echo to
    // PyKindsConsumer and calls PyKindsProvider's.
    const QString dir = m_work.filePath(QStringLiteral("sdk/CxxKinds"));
    QVERIFY(SdkTest::copyTree(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdkkinds"), dir));
    QString log;
    QVERIFY2(SdkTest::buildProject(dir, RTSTUDIO_BUILD_DIR, &log,
                                   {QStringLiteral("-DKINDS_IDL=") + dataFile(QStringLiteral("Kinds.idl"))}),
             qPrintable(log.right(4000)));
    const QString stubs = compileIdl({dataFile(QStringLiteral("Kinds.idl"))});
    QVERIFY(!stubs.isEmpty());
    // (The previous test's Python components have gone from the name server with their processes.)
    QTRY_VERIFY_WITH_TIMEOUT(!rtctl({QStringLiteral("ls")}).out.contains(QLatin1String("PyKinds")), runTimeoutMs);
    QString error;
    QProcess *cxx = m_live.startRegistered(
        dir + QStringLiteral("/build/CxxKindsComp"), {QStringLiteral("-f"), writeConf(QStringLiteral("cxxkinds"))},
        [this] { return rtctl({QStringLiteral("ls")}).out.contains(QLatin1String("CxxKinds0.rtc")); }, &error,
        runTimeoutMs);
    QVERIFY2(cxx, qPrintable(error));
    QProcess *provider = startScript(dataFile(QStringLiteral("PyKindsProvider.py")), stubs,
                                     QStringLiteral("PyKindsProvider0.rtc"));
    QVERIFY(provider);
    QProcess *consumer = startScript(dataFile(QStringLiteral("PyKindsConsumer.py")), stubs,
                                     QStringLiteral("PyKindsConsumer0.rtc"));
    QVERIFY(consumer);
    QVERIFY(rtctlSucceeds({"con", "PyKindsConsumer0.rtc:Echo", "CxxKinds0.rtc:Provided"}));
    QVERIFY(rtctlSucceeds({"con", "CxxKinds0.rtc:Required", "PyKindsProvider0.rtc:Echo"}));
    for (const char *component : {"PyKindsProvider0.rtc", "CxxKinds0.rtc", "PyKindsConsumer0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    // C++ consumer → Python provider: what the Python servant answered, and its call back of the
    // C++ servant whose reference it was given.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(cxx).contains(QLatin1String("cxx consumer: done")),
                              qPrintable(printed(cxx) + printed(provider)), runTimeoutMs);
    for (const QString &line : {QStringLiteral("cxx consumer: letter \u00c9 \u00e9\u00e9\u00e9\n"),
                                QStringLiteral("cxx consumer: reversed \u4e16 oll\u00e9h\n"),
                                QStringLiteral("cxx consumer: swap text t, number 5\n"),
                                QStringLiteral("cxx consumer: wrap -12 long -12\n"),
                                QStringLiteral("cxx consumer: wrap RTC::Time {'sec': 1, 'nsec': 2}\n"),
                                QStringLiteral("cxx consumer: wrap PyKinds::Pick PyKinds.Pick(2, 't')\n"),
                                QStringLiteral("cxx consumer: wrap TypeCode CORBA.TypeCode('PyKinds::Pick')\n"),
                                QStringLiteral("cxx consumer: relay 7 True\n")})
        QVERIFY2(printed(cxx).contains(line), qPrintable(line + printed(cxx)));
    QVERIFY2(printed(provider).contains(QLatin1String("provider: relay of a reference that answers calls() 7\n")),
             qPrintable(printed(provider)));
    // Python consumer → C++ provider.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(consumer).contains(QLatin1String("consumer: done")),
                              qPrintable(printed(consumer) + printed(cxx)), runTimeoutMs);
    for (const QString &line : {QStringLiteral("consumer: letter ('\u00c9', '\u00e9\u00e9\u00e9')\n"),
                                QStringLiteral("consumer: reversed \u4e16 oll\u00e9h\n"),
                                QStringLiteral("consumer: swap (PyKinds.Pick(2, 't'), PyKinds.Pick(1, 5))\n"),
                                QStringLiteral("consumer: wrap True double 2.500000\n"),
                                QStringLiteral("consumer: wrap True string corba_cdr\n"),
                                QStringLiteral("consumer: wrap True unsigned short 7\n"),
                                QStringLiteral("consumer: wrap True Pick number 5\n"),
                                QStringLiteral("consumer: wrap True RTC::Time 1 2\n"),
                                QStringLiteral("consumer: wrap True TypeCode IDL:PyKinds/Pick:1.0\n"),
                                QStringLiteral("consumer: wrap True sequence 1 2\n"),
                                QStringLiteral("consumer: relay 42 _objref_Echo True\n"),
                                QStringLiteral("consumer: relay nil None\n")})
        QVERIFY2(printed(consumer).contains(line), qPrintable(line + printed(consumer)));
    QVERIFY2(printed(cxx).contains(QLatin1String("cxx provider: relay of a reference that answers calls() 42\n")),
             qPrintable(printed(cxx)));
    QVERIFY(endComponents({QStringLiteral("PyKindsConsumer0.rtc"), QStringLiteral("CxxKinds0.rtc"),
                           QStringLiteral("PyKindsProvider0.rtc")}));
    m_live.stop(consumer);
    m_live.stop(cxx);
    m_live.stop(provider);
}

void TestPythonService::pythonAndCxxComponentsCallEachOther()
{
    const QString stubs = compileIdl({dataFile(QStringLiteral("SimpleService.idl"))});
    QVERIFY(!stubs.isEmpty());
    QVERIFY(rtctlSucceeds({"mgr", m_host.managerPath(), "create",
                           "MyServiceProvider?instance_name=CxxProvider", "create",
                           "MyServiceConsumer?instance_name=CxxConsumer"}));
    QProcess *python = startScript(dataFile(QStringLiteral("PyMyService.py")), stubs,
                                   QStringLiteral("PyMyService0.rtc"));
    QVERIFY(python);
    QVERIFY(rtctlSucceeds({"con", "CxxConsumer.rtc:MyService", "PyMyService0.rtc:Provided"}));
    QVERIFY(rtctlSucceeds({"con", "PyMyService0.rtc:Required", "CxxProvider.rtc:MyService"}));
    // Providers first: their objects answer from their component's activation on.
    for (const char *component : {"CxxProvider.rtc", "PyMyService0.rtc", "CxxConsumer.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    // Python consumer → C++ provider: a string, floats, and the two sequences back.
    QTRY_VERIFY2_WITH_TIMEOUT(
        printed(python).contains(QLatin1String("consumer: echoes ['from python']\n")),
        qPrintable(printed(python)), runTimeoutMs);
    QVERIFY2(printed(python).contains(QLatin1String("consumer: echo from python\n")),
             qPrintable(printed(python)));
    QVERIFY2(printed(python).contains(QLatin1String("consumer: value 2.5 history [1.25, 2.5]\n")),
             qPrintable(printed(python)));
    // C++ consumer (it calls echo("echo <n>") every hundredth execution) → Python servant.
    QTRY_VERIFY_WITH_TIMEOUT(
        m_host.status(m_orb, QStringLiteral("CxxConsumer.rtc"), "echo_count").toInt() >= 2,
        runTimeoutMs);
    QVERIFY2(m_host.status(m_orb, QStringLiteral("CxxConsumer.rtc"), "last_reply")
                 .startsWith(QLatin1String("python says echo ")),
             qPrintable(m_host.status(m_orb, QStringLiteral("CxxConsumer.rtc"), "last_reply")));
    QVERIFY2(printed(python).contains(QLatin1String("servant: echo echo 1\n")),
             qPrintable(printed(python)));
    QVERIFY(rtctlSucceeds({"deact", "CxxConsumer.rtc"}));
    QVERIFY(endComponents({QStringLiteral("PyMyService0.rtc")}));
    m_live.stop(python);
}

void TestPythonService::pythonComponentAndSdkExamplesCallEachOther()
{
    // OpenRTM-aist's C++ MyServiceProvider and MyServiceConsumer examples, built against the SDK.
    const QString corpus = RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-examples/");
    if (!QFileInfo::exists(corpus + QStringLiteral("MyServiceProvider/CMakeLists.txt")))
        QSKIP("the OpenRTM-aist examples corpus (shared/conformance/openrtm-examples beside the "
              "project) is absent");
    QStringList programs;
    for (const char *example : {"MyServiceProvider", "MyServiceConsumer"}) {
        const QString dir = m_work.filePath(QStringLiteral("sdk/") + QLatin1String(example));
        QVERIFY(SdkTest::copyTree(corpus + QLatin1String(example), dir));
        QString log;
        QVERIFY2(SdkTest::buildProject(dir, RTSTUDIO_BUILD_DIR, &log),
                 qPrintable(log.right(4000)));
        programs << dir + QStringLiteral("/build/src/") + QLatin1String(example)
                + QStringLiteral("Comp");
    }
    const QString stubs = compileIdl({dataFile(QStringLiteral("SimpleService.idl"))});
    QVERIFY(!stubs.isEmpty());
    QString error;
    QProcess *provider = m_live.startRegistered(
        programs.at(0), {QStringLiteral("-f"), writeConf(QStringLiteral("sdkprovider"))},
        [this] {
            return rtctl({QStringLiteral("ls")})
                .out.contains(QLatin1String("MyServiceProvider0.rtc"));
        },
        &error, runTimeoutMs);
    QVERIFY2(provider, qPrintable(error));
    QProcess *consumer = m_live.startRegistered(
        programs.at(1), {QStringLiteral("-f"), writeConf(QStringLiteral("sdkconsumer"))},
        [this] {
            return rtctl({QStringLiteral("ls")})
                .out.contains(QLatin1String("MyServiceConsumer0.rtc"));
        },
        &error, runTimeoutMs);
    QVERIFY2(consumer, qPrintable(error));
    // The C++ provider's echo() takes ten seconds: longer than the runtime's default call timeout.
    // (An earlier test's PyMyService0 has gone from the name server with its process.)
    QTRY_VERIFY_WITH_TIMEOUT(
        !rtctl({QStringLiteral("ls")}).out.contains(QLatin1String("PyMyService0.rtc")),
        runTimeoutMs);
    QProcess *python = startScript(dataFile(QStringLiteral("PyMyService.py")), stubs,
                                   QStringLiteral("PyMyService0.rtc"),
                                   QStringLiteral("corba.call_timeout: 20000\n"));
    QVERIFY(python);
    QVERIFY(
        rtctlSucceeds({"con", "MyServiceConsumer0.rtc:MyService", "PyMyService0.rtc:Provided"}));
    QVERIFY(
        rtctlSucceeds({"con", "PyMyService0.rtc:Required", "MyServiceProvider0.rtc:MyService"}));
    for (const char *component :
         {"MyServiceProvider0.rtc", "PyMyService0.rtc", "MyServiceConsumer0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    // Python consumer → the C++ provider example.
    QTRY_VERIFY2_WITH_TIMEOUT(
        printed(python).contains(QLatin1String("consumer: echoes ['from python']\n")),
        qPrintable(printed(python) + printed(provider).right(1000)), runTimeoutMs);
    QVERIFY2(printed(python).contains(QLatin1String("consumer: value 2.5 history [1.25, 2.5]\n")),
             qPrintable(printed(python)));
    // The C++ consumer example's commands → the Python servant.
    QVERIFY2(commandAnswers(consumer, "set_value 4.5", QStringLiteral("Set remote value: 4.5")),
             qPrintable(printed(consumer).right(1000)));
    QVERIFY2(commandAnswers(consumer, "get_value", QStringLiteral("Current remote value: 4.5")),
             qPrintable(printed(consumer).right(1000)));
    // The consumer example waits for its next command in onExecute: at the end of its input it goes
    // on.
    consumer->closeWriteChannel();
    QVERIFY(
        endComponents({QStringLiteral("MyServiceConsumer0.rtc"), QStringLiteral("PyMyService0.rtc"),
                       QStringLiteral("MyServiceProvider0.rtc")}));
    m_live.stop(consumer);
    m_live.stop(provider);
    m_live.stop(python);
}

void TestPythonService::simpleServiceExamplesRunUnchanged()
{
    if (!QFileInfo::exists(simpleServiceDir() + QStringLiteral("MyServiceProvider.py")))
        QSKIP(NoPythonCorpus);
    const QString stubs = compileIdl({simpleServiceDir() + QStringLiteral("MyService.idl")});
    QVERIFY(!stubs.isEmpty());
    QProcess *provider = startScript(simpleServiceDir() + QStringLiteral("MyServiceProvider.py"),
                                     stubs, QStringLiteral("MyServiceProvider0.rtc"));
    QVERIFY(provider);
    // The provider's echo() takes ten seconds: longer than the runtime's default call timeout.
    QProcess *consumer = startScript(simpleServiceDir() + QStringLiteral("MyServiceConsumer.py"),
                                     stubs, QStringLiteral("MyServiceConsumer0.rtc"),
                                     QStringLiteral("corba.call_timeout: 20000\n"));
    QVERIFY(consumer);
    QVERIFY(rtctlSucceeds(
        {"con", "MyServiceConsumer0.rtc:MyService", "MyServiceProvider0.rtc:MyService"}));
    for (const char *component : {"MyServiceProvider0.rtc", "MyServiceConsumer0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));

    // The consumer's commands: a float there and back, and the sequences of history.
    QVERIFY(commandAnswers(consumer, "set_value 2.5", QStringLiteral("Set remote value:  2.5")));
    QTRY_VERIFY_WITH_TIMEOUT(printed(provider).contains(QLatin1String("Current value:  2.5")),
                             runTimeoutMs);
    QVERIFY(commandAnswers(consumer, "get_value", QStringLiteral("Current remote value:  2.5")));
    QVERIFY(commandAnswers(consumer, "get_value_history", QStringLiteral("0 :  2.5")));
    // echo() takes ten seconds in the provider; the consumer calls it in a thread of its own.
    QVERIFY(commandAnswers(consumer, "echo hello", QStringLiteral("> ")));
    QTRY_VERIFY_WITH_TIMEOUT(printed(provider).contains(QLatin1String("Message:  hello")),
                             runTimeoutMs);
    QVERIFY(commandAnswers(consumer, "get_echo_history", QStringLiteral("0 :  hello")));
    QTRY_VERIFY_WITH_TIMEOUT(
        printed(provider).contains(QLatin1String("MyService::echo() was finished.")), runTimeoutMs);
    QVERIFY2(commandAnswers(consumer, "get_value", QStringLiteral("echo() finished:  hello")),
             qPrintable(printed(consumer).right(1000)));
    m_live.stop(consumer);
    m_live.stop(provider);
}

// OpenRTM-aist-Python's AutoTest: AutoTestOut reads records from `original-data` in its working
// folder and sends each as a float, a sequence of five floats and an echo() call; AutoTestIn
// writes what it receives to `received-data`. Both files are the same when every record came
// through, which is how OpenRTM-aist's own ConnectTest checks a port of the middleware.
void TestPythonService::autoTestExamplesRunUnchanged()
{
    if (!QFileInfo::exists(autoTestDir() + QStringLiteral("AutoTestIn.py")))
        QSKIP(NoPythonCorpus);
    const QString stubs = compileIdl({autoTestDir() + QStringLiteral("AutoTestService.idl")});
    QVERIFY(!stubs.isEmpty());
    QDir folder(m_work.filePath(QStringLiteral("autotest")));
    QVERIFY(folder.mkpath(QStringLiteral(".")));
    QByteArray records;
    for (int i = 0; i < 4; ++i) {
        records += QByteArray::number(i, 'f', 6) + '\n';
        QByteArrayList floats;
        for (int j = 1; j <= 5; ++j)
            floats << QByteArray::number(i + j / 10.0, 'f', 6);
        records += floats.join(' ') + "\nmessage" + QByteArray::number(i) + '\n';
    }
    QFile original(folder.filePath(QStringLiteral("original-data")));
    QVERIFY(original.open(QIODevice::WriteOnly));
    original.write(records);
    original.close();
    // The examples open their files in the working folder, which they inherit.
    const QString previous = QDir::currentPath();
    QVERIFY(QDir::setCurrent(folder.path()));
    const auto back = qScopeGuard([&previous] { QDir::setCurrent(previous); });
    // The components' settings as the example's rtc.conf names them: AutoTestOut writes ten times a
    // second (autotestout.conf), AutoTestIn keeps the newest sample of each port (autotestin.conf)
    // and reads at the default rate.
    const auto configFile = [](const char *type, const char *file) {
        return QStringLiteral("example.%1.config_file: %2%3\n").arg(QLatin1String(type), autoTestDir(), QLatin1String(file));
    };
    QProcess *in = startScript(autoTestDir() + QStringLiteral("AutoTestIn.py"), stubs, QStringLiteral("AutoTestIn0.rtc"),
                               configFile("AutoTestIn", "autotestin.conf"));
    QVERIFY(in);
    QProcess *out = startScript(autoTestDir() + QStringLiteral("AutoTestOut.py"), stubs,
                                QStringLiteral("AutoTestOut0.rtc"), configFile("AutoTestOut", "autotestout.conf"));
    QVERIFY(out);
    for (const QStringList &link : {QStringList{"AutoTestOut0.rtc:out", "AutoTestIn0.rtc:in"},
                                    QStringList{"AutoTestOut0.rtc:seqout", "AutoTestIn0.rtc:seqin"},
                                    QStringList{"AutoTestOut0.rtc:MyService", "AutoTestIn0.rtc:MyService"}})
        QVERIFY2(rtctlSucceeds(QStringList{"con"} + link),
                 qPrintable(link.join(' ') + QStringLiteral("\nlisted:\n") + rtctl({"ls"}).out
                            + QStringLiteral("\nAutoTestIn (%1):\n").arg(in->state()) + printed(in)
                            + QStringLiteral("\nAutoTestOut (%1):\n").arg(out->state()) + printed(out)));
    QVERIFY(rtctlSucceeds({"act", "AutoTestIn0.rtc"}));
    QVERIFY(rtctlSucceeds({"act", "AutoTestOut0.rtc"}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(in).contains(QLatin1String("fdata: 3.000000")), qPrintable(printed(in)),
                              runTimeoutMs);
    // AutoTestIn closes its file when deactivated.
    QVERIFY(rtctlSucceeds({"deact", "AutoTestOut0.rtc"}));
    QVERIFY(rtctlSucceeds({"deact", "AutoTestIn0.rtc"}));
    const auto received = [&folder] {
        QFile file(folder.filePath(QStringLiteral("received-data")));
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    };
    QTRY_COMPARE_WITH_TIMEOUT(received(), records, runTimeoutMs);
    QVERIFY(endComponents({QStringLiteral("AutoTestIn0.rtc"), QStringLiteral("AutoTestOut0.rtc")}));
    m_live.stop(out);
    m_live.stop(in);
}

QTEST_GUILESS_MAIN(TestPythonService)
#include "tst_pythonservice.moc"
