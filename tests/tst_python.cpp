// SPDX-License-Identifier: MIT
// Python components on RT Studio's runtime (python/: OpenRTM_aist and RTC without omniORBpy), run
// as programs with python3 from the build tree's packages, registered in a name server and driven
// with rtctl like any component:
// - OpenRTM-aist-Python's SimpleIO example (ConsoleIn.py, ConsoleOut.py) unchanged from the shared
//   conformance corpus (skipped with the reason when it is absent), feeding rtmanager's built-in
//   sink as well;
// - a component of ours (data/python/PyScaler.py) between rtmanager's built-in source and sink;
// - an exception in a callback (data/python/PyFaulty.py): Error state, traceback, process alive;
// - OpenRTM-aist-Python's SeqIO example unchanged, its ten data types also reaching rtmanager's SeqIn;
// - two Python components of one process, configuration parameters, a generated Python project;
// - the IDL types' Python classes and CDR (data/python/datatypes.py), from the build tree and installed;
// - a name server's contexts walked from Python (data/python/naming.py), and OpenRTM-aist-Python's
//   AutoTest/rtc_handle.py unchanged doing so (data/python/rtchandle.py).
#include "hostrtctl.h"
#include "pythonscripts.h"

#include <QtTest>

namespace {

constexpr int runTimeoutMs = 30 * 1000;
const QString hostName = QStringLiteral("pyhost");
constexpr const char *NoPythonCorpus
    = "the OpenRTM-aist-Python examples corpus (shared/conformance/openrtm-python-examples beside the project) "
      "is absent";

} // namespace

class TestPython : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void dataTypesConvert();
    void simpleIoExamplesRunUnchanged();
    void seqIoExamplesRunUnchanged();
    void componentExchangesDataWithBuiltins();
    void callbackExceptionMovesComponentToError();
    void componentsOfOneProcessExchangeData();
    void serializerReadsAnotherDataType();
    void configurationReachesBoundVariables();
    void namingContextsFromPython();
    void rtcHandleWalksTheNameServer();
    void generatedComponentRuns();
    void installedPackagesWork();

private:
    RtctlResult rtctl(const QStringList &arguments) const;
    /// Runs rtctl and fails the test (returning false) when it does not succeed.
    bool rtctlSucceeds(const QStringList &arguments) const;
    QString status(const QString &component, const char *name) const;
    /// The state `rtctl ls -l` shows for @p component (Active, Inactive, Error); empty when not listed.
    QString state(const QString &component) const;
    /// Starts `python3 @p script -f <conf>`; waits until @p instance is in the name server.
    QProcess *startScript(const QString &script, const QString &instance, const QStringList &confLines = {});
    /// Runs python3 @p script @p arguments to its end; what it printed (both streams), and in
    /// @p ok whether it exited with 0.
    QString runPython(const QString &script, const QStringList &arguments, bool *ok);
    /// Starts data/python/PyConfig.py (a component without ports) once the previous one is gone.
    QProcess *startConfigComponent();
    /// Ends PyConfig0 and its process.
    void stopConfigComponent(QProcess *config);
    /// What @p process printed so far on standard output (kept across calls).
    QString printed(QProcess *process);

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
    LiveTest::HostRtctl m_host{m_live, hostName};
    QProcess *m_manager = nullptr;
    CORBA::ORB_var m_orb;
    LiveTest::PrintedOutput m_printed;
    LiveTest::PythonScripts m_scripts{m_live,
                                      m_host,
                                      hostName,
                                      QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE),
                                      RTSTUDIO_PYTHON_PATH,
                                      QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD),
                                      m_work.path()};
};

RtctlResult TestPython::rtctl(const QStringList &arguments) const
{
    return m_host.run(arguments);
}

bool TestPython::rtctlSucceeds(const QStringList &arguments) const
{
    return m_host.succeeds(arguments);
}

QString TestPython::status(const QString &component, const char *name) const
{
    return m_host.status(m_orb, component, name);
}

QString TestPython::state(const QString &component) const
{
    return m_host.state(component);
}

QProcess *TestPython::startScript(const QString &script, const QString &instance, const QStringList &confLines)
{
    return m_scripts.start(script, {instance}, runTimeoutMs, confLines);
}

QString TestPython::printed(QProcess *process)
{
    return m_printed.of(process);
}

void TestPython::initTestCase()
{
    QVERIFY(m_work.isValid());
    QVERIFY2(QFileInfo::exists(RTSTUDIO_PYTHON_PATH + QStringLiteral("/OpenRTM_aist/__init__.py")), "build rtpython first");
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_manager = m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), hostName, {}, &error);
    QVERIFY2(m_manager, qPrintable(error));
}

QString TestPython::runPython(const QString &script, const QStringList &arguments, bool *ok)
{
    QProcess python;
    python.setProcessEnvironment(m_scripts.environment());
    python.start(QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE), QStringList{script} + arguments);
    const bool finished = python.waitForFinished(runTimeoutMs);
    if (!finished)
        python.kill();
    python.waitForFinished();
    *ok = finished && python.exitStatus() == QProcess::NormalExit && python.exitCode() == 0;
    return QString::fromLocal8Bit(python.readAllStandardOutput() + python.readAllStandardError());
}

void TestPython::dataTypesConvert()
{
    bool ok = false;
    const QString output = runPython(LiveTest::pythonTestScript(QStringLiteral("datatypes.py")), {}, &ok);
    QVERIFY2(ok, qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("datatypes: ok")), qPrintable(output));
}

void TestPython::simpleIoExamplesRunUnchanged()
{
    const QString example = LiveTest::pythonCorpusDir() + QStringLiteral("/SimpleIO/");
    if (!QFileInfo::exists(example + QStringLiteral("ConsoleIn.py")))
        QSKIP(NoPythonCorpus);
    const QString manager = m_host.managerPath();
    QVERIFY(rtctlSucceeds({"mgr", manager, "create", "ConsoleOut?instance_name=SimpleIoSink"}));
    QProcess *out = startScript(example + QStringLiteral("ConsoleOut.py"), QStringLiteral("ConsoleOut0.rtc"));
    QVERIFY(out);
    QProcess *in = startScript(example + QStringLiteral("ConsoleIn.py"), QStringLiteral("ConsoleIn0.rtc"));
    QVERIFY(in);
    // ConsoleIn.py reads one number from standard input each cycle.
    QByteArray numbers;
    for (int i = 1; i <= 500; ++i)
        numbers += QByteArray::number(i) + '\n';
    in->write(numbers);
    QVERIFY(rtctlSucceeds({"con", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"}));
    QVERIFY(rtctlSucceeds({"con", "ConsoleIn0.rtc:out", "SimpleIoSink.rtc:in"}));
    for (const char *component : {"ConsoleOut0.rtc", "SimpleIoSink.rtc", "ConsoleIn0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));

    QTRY_VERIFY_WITH_TIMEOUT(printed(in).contains(QLatin1String("Sending to subscriber:  3\n")), runTimeoutMs);
    // A `new` subscription may skip samples: at least three of the numbers sent, in order.
    const auto received = [&] {
        QList<int> values;
        const QRegularExpression line(QStringLiteral("Received:  (\\d+)\n"));
        QRegularExpressionMatchIterator it = line.globalMatch(printed(out));
        while (it.hasNext())
            values << it.next().captured(1).toInt();
        return values;
    };
    QTRY_VERIFY_WITH_TIMEOUT(received().size() >= 3, runTimeoutMs);
    const QList<int> counts = received();
    QVERIFY2(std::is_sorted(counts.begin(), counts.end()) && counts.first() >= 1 && counts.last() <= 500,
             qPrintable(printed(out).left(2000)));
    QVERIFY2(QRegularExpression(QStringLiteral("TimeStamp:  [1-9][0-9]* \\[s\\]")).match(printed(out)).hasMatch(),
             qPrintable(printed(out).left(2000)));
    // The examples' connector listeners: the connection on both sides, each sample decoded for them.
    QVERIFY2(printed(out).contains(QLatin1String("Listener:        ON_CONNECT")), qPrintable(printed(out).left(2000)));
    QVERIFY2(printed(in).contains(QLatin1String("Listener:        ON_CONNECT")), qPrintable(printed(in).left(2000)));
    QVERIFY2(QRegularExpression(QStringLiteral("ON_RECEIVED\\n.*\\n.*\\nData: +[1-9][0-9]*\\n")).match(printed(out)).hasMatch(),
             qPrintable(printed(out).left(2000)));
    QTRY_VERIFY_WITH_TIMEOUT(status(QStringLiteral("SimpleIoSink.rtc"), "received_count").toInt() >= 3, runTimeoutMs);
    QCOMPARE(LiveTest::integers(status(QStringLiteral("SimpleIoSink.rtc"), "received_values")).value(0) > 0, true);
    QVERIFY(rtctlSucceeds({"deact", "ConsoleIn0.rtc"}));
    m_live.stop(in);
    m_live.stop(out);
}

void TestPython::seqIoExamplesRunUnchanged()
{
    const QString example = LiveTest::pythonCorpusDir() + QStringLiteral("/SeqIO/");
    if (!QFileInfo::exists(example + QStringLiteral("SeqIn.py")))
        QSKIP(NoPythonCorpus);
    const QString manager = m_host.managerPath();
    QVERIFY(rtctlSucceeds({"mgr", manager, "create", "SeqIn?instance_name=SeqSink"}));
    QProcess *out = startScript(example + QStringLiteral("SeqOut.py"), QStringLiteral("SequenceOutComponent0.rtc"));
    QVERIFY(out);
    QProcess *in = startScript(example + QStringLiteral("SeqIn.py"), QStringLiteral("SequenceInComponent0.rtc"));
    QVERIFY(in);
    const QStringList ports{"Octet", "Short", "Long", "Float", "Double",
                            "OctetSeq", "ShortSeq", "LongSeq", "FloatSeq", "DoubleSeq"};
    for (const QString &port : ports) {
        const QString source = QStringLiteral("SequenceOutComponent0.rtc:") + port;
        QVERIFY(rtctlSucceeds({"con", source, "SequenceInComponent0.rtc:" + port}));
        QVERIFY(rtctlSucceeds({"con", source, "SeqSink.rtc:" + port}));
    }
    for (const char *component : {"SeqSink.rtc", "SequenceInComponent0.rtc", "SequenceOutComponent0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    // SeqOut.py sends letters A to J as octets; SeqIn.py prints each with its character.
    const QRegularExpression octet(QStringLiteral(" (6[5-9]|7[0-4])\\[[A-J]\\] "));
    QTRY_VERIFY2_WITH_TIMEOUT(octet.match(printed(in)).hasMatch(), qPrintable(printed(in).right(3000)), runTimeoutMs);
    QVERIFY2(printed(in).contains(QLatin1String("Sequence Data")), qPrintable(printed(in).right(2000)));
    // rtmanager's C++ SeqIn takes every one of the ten types from the Python component.
    for (const QString &port : ports)
        QTRY_VERIFY2_WITH_TIMEOUT(status(QStringLiteral("SeqSink.rtc"), qPrintable(port + "_count")).toInt() > 0,
                                  qPrintable(port), runTimeoutMs);
    for (const char *component : {"SequenceOutComponent0.rtc", "SequenceInComponent0.rtc"})
        QVERIFY(rtctlSucceeds({"deact", component}));
    m_live.stop(in);
    m_live.stop(out);
}

void TestPython::componentExchangesDataWithBuiltins()
{
    const QString manager = m_host.managerPath();
    QVERIFY(rtctlSucceeds({"mgr", manager, "create", "ConsoleIn?instance_name=ScalerFeed", "create",
                           "ConsoleOut?instance_name=ScalerSink"}));
    QProcess *scaler = startScript(LiveTest::pythonTestScript(QStringLiteral("PyScaler.py")), QStringLiteral("PyScaler0.rtc"));
    QVERIFY(scaler);
    QVERIFY(rtctlSucceeds({"con", "ScalerFeed.rtc:out", "PyScaler0.rtc:in"}));
    QVERIFY(rtctlSucceeds({"con", "PyScaler0.rtc:out", "ScalerSink.rtc:in"}));
    for (const char *component : {"ScalerSink.rtc", "PyScaler0.rtc", "ScalerFeed.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));

    QTRY_VERIFY_WITH_TIMEOUT(status(QStringLiteral("ScalerSink.rtc"), "received_count").toInt() >= 3, runTimeoutMs);
    // What the C++ sink received went through the Python component: the source's counts times 1000.
    const QList<qint64> values = LiveTest::integers(status(QStringLiteral("ScalerSink.rtc"), "received_values"));
    QVERIFY(!values.isEmpty());
    for (const qint64 value : values)
        QVERIFY2(value > 0 && value % 1000 == 0, qPrintable(QString::number(value)));
    // ... and the Python component saw each of them (a `new` subscription may skip samples, so not every count).
    const QString seen = QStringLiteral("scaled %1\n").arg(values.last() / 1000);
    QTRY_VERIFY_WITH_TIMEOUT(printed(scaler).contains(seen), runTimeoutMs);
    for (const char *component : {"ScalerFeed.rtc", "PyScaler0.rtc"})
        QVERIFY(rtctlSucceeds({"deact", component}));
    m_live.stop(scaler);
}

void TestPython::callbackExceptionMovesComponentToError()
{
    // The component's logger writes to a file: the traceback must be logged there.
    const QString log = m_work.filePath(QStringLiteral("faulty.log"));
    QProcess *faulty = startScript(LiveTest::pythonTestScript(QStringLiteral("PyFaulty.py")), QStringLiteral("PyFaulty0.rtc"),
                                   {QStringLiteral("logger.enable: YES"), QStringLiteral("logger.file_name: ") + log});
    QVERIFY(faulty);
    QCOMPARE(state(QStringLiteral("PyFaulty0.rtc")), QStringLiteral("Inactive"));
    QVERIFY(rtctlSucceeds({"act", "PyFaulty0.rtc"}));
    QTRY_COMPARE_WITH_TIMEOUT(state(QStringLiteral("PyFaulty0.rtc")), QStringLiteral("Error"), runTimeoutMs);
    const auto logged = [&log] {
        QFile file(log);
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
    };
    QTRY_VERIFY_WITH_TIMEOUT(logged().contains(QLatin1String("RuntimeError: faulty on purpose")), runTimeoutMs);
    QVERIFY2(logged().contains(QLatin1String("PyFaulty0: onExecute() raised an exception")), qPrintable(logged()));
    QVERIFY2(logged().contains(QLatin1String("Traceback (most recent call last)")), qPrintable(logged()));
    // The class whose constructor raised was not created, and said why.
    QTRY_VERIFY_WITH_TIMEOUT(printed(faulty).contains(QLatin1String("PyBroken created: None\n")), runTimeoutMs);
    QVERIFY2(logged().contains(QLatin1String("ValueError: broken on purpose")), qPrintable(logged()));
    QVERIFY(!rtctl({QStringLiteral("ls")}).out.contains(QLatin1String("PyBroken")));
    // The process lives on and the component recovers through onReset.
    QCOMPARE(faulty->state(), QProcess::Running);
    QVERIFY(rtctlSucceeds({"reset", "PyFaulty0.rtc"}));
    QTRY_VERIFY_WITH_TIMEOUT(printed(faulty).contains(QLatin1String("PyFaulty reset")), runTimeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(state(QStringLiteral("PyFaulty0.rtc")), QStringLiteral("Inactive"), runTimeoutMs);
    m_live.stop(faulty);
}

void TestPython::componentsOfOneProcessExchangeData()
{
    QProcess *pair = startScript(LiveTest::pythonTestScript(QStringLiteral("PyPair.py")), QStringLiteral("PySink0.rtc"));
    QVERIFY(pair);
    // flush is the subscription the SDK short-cuts between C++ ports of one process; Python's
    // samples, which exist only as CDR, must still arrive.
    QVERIFY(rtctlSucceeds({"con", "-p", "dataport.subscription_type=flush", "PySource0.rtc:out", "PySink0.rtc:in"}));
    for (const char *component : {"PySink0.rtc", "PySource0.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    QTRY_VERIFY_WITH_TIMEOUT(printed(pair).contains(QLatin1String("sink got 3\n")), runTimeoutMs);
    // Components go on rtctl exit and the program ends cleanly on SIGTERM, as a C++ one.
    QVERIFY(rtctlSucceeds({"exit", "PySink0.rtc"}));
    QTRY_VERIFY_WITH_TIMEOUT(!rtctl({QStringLiteral("ls")}).out.contains(QLatin1String("PySink0.rtc")), runTimeoutMs);
    QCOMPARE(pair->state(), QProcess::Running);
    pair->terminate();
    QVERIFY(pair->waitForFinished(runTimeoutMs));
    QCOMPARE(pair->exitStatus(), QProcess::NormalExit);
    QCOMPARE(pair->exitCode(), 0);
    m_live.stop(pair);
}

void TestPython::serializerReadsAnotherDataType()
{
    // PySerialized.py's serializer reads the source's TimedLong samples as quarters, TimedDouble, for
    // the sink's InPort and its data listener; without it the two types do not connect.
    QProcess *pair = startScript(LiveTest::pythonTestScript(QStringLiteral("PySerialized.py")), QStringLiteral("PyDoubleSink0.rtc"));
    QVERIFY(pair);
    const QString source = QStringLiteral("PyLongSource0.rtc:out");
    const QString sink = QStringLiteral("PyDoubleSink0.rtc:in");
    const QList<std::pair<QString, QString>> plain{{"dataport.data_type", "IDL:RTC/TimedLong:1.0"},
                                                   {"dataport.interface_type", "corba_cdr"},
                                                   {"dataport.dataflow_type", "push"},
                                                   {"dataport.subscription_type", "flush"}};
    // The source's connection to the sink with one more property, that connection's marshaling type.
    const auto connect = [&](const char *side, const char *marshaling) {
        return m_host.connectThroughOrb(m_orb, source, sink,
                                        QList<std::pair<QString, QString>>(plain)
                                            << std::pair<QString, QString>(side, marshaling));
    };
    QVERIFY(!m_host.connectThroughOrb(m_orb, source, sink, plain));
    QVERIFY(connect("dataport.inport.marshaling_type", "cdr:RTC/TimedLong:RTC/TimedDouble"));
    QVERIFY(rtctlSucceeds({"act", "PyDoubleSink0.rtc", "PyLongSource0.rtc"}));
    // The listener hears every sample; the sink's buffer may have overwritten the first ones before its
    // first execution (a busy machine), so any quarter that is not a whole number shows the serializer.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(pair).contains(QLatin1String("listener got 0.75\n")), qPrintable(printed(pair)),
                              runTimeoutMs);
    const QRegularExpression quarter(QStringLiteral("^sink got \\d+\\.(25|5|75)$"),
                                     QRegularExpression::MultilineOption);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(pair).contains(quarter), qPrintable(printed(pair)), runTimeoutMs);
    QVERIFY(rtctlSucceeds({"deact", "PyLongSource0.rtc", "PyDoubleSink0.rtc"}));
    // The OutPort's side: its serializer writes eighths as TimedDouble, which the InPort reads as plain cdr.
    QVERIFY(rtctlSucceeds({"dis", source, sink}));
    QVERIFY(connect("dataport.outport.marshaling_type", "cdr:RTC/TimedDouble:RTC/TimedLong"));
    QVERIFY(rtctlSucceeds({"act", "PyDoubleSink0.rtc", "PyLongSource0.rtc"}));
    const QRegularExpression eighth(QStringLiteral("^sink got \\d+\\.(125|375|625|875)$"), QRegularExpression::MultilineOption);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(pair).contains(eighth), qPrintable(printed(pair)), runTimeoutMs);
    QVERIFY(rtctlSucceeds({"deact", "PyLongSource0.rtc", "PyDoubleSink0.rtc"}));
    // Two connections of one InPort, each read by its own marshaling type: the serializer's quarters
    // and PyDoubleSource's plain TimedDouble samples.
    QVERIFY(rtctlSucceeds({"dis", source, sink}));
    QVERIFY(connect("dataport.inport.marshaling_type", "cdr:RTC/TimedLong:RTC/TimedDouble"));
    QVERIFY(rtctlSucceeds({"con", "PyDoubleSource0.rtc:out", sink}));
    const qsizetype before = printed(pair).size();
    QVERIFY(rtctlSucceeds({"act", "PyDoubleSink0.rtc", "PyLongSource0.rtc", "PyDoubleSource0.rtc"}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(pair).mid(before).contains(quarter)
                                  && printed(pair).mid(before).contains(QLatin1String("sink got 1000.125\n")),
                              qPrintable(printed(pair).mid(before).right(3000)), runTimeoutMs);
    QVERIFY(rtctlSucceeds({"deact", "PyLongSource0.rtc", "PyDoubleSource0.rtc", "PyDoubleSink0.rtc"}));
    // A serializer no module registered: that connection's writes fail, the other connection's go on.
    QVERIFY(rtctlSucceeds({"dis", source, sink}));
    QVERIFY(connect("dataport.outport.marshaling_type", "cdr:RTC/TimedDouble:RTC/Nothing"));
    // What the sink read since this activation: the lines after its last "sink activated" (earlier
    // phases' lines may still be on their way when it starts).
    const QLatin1String activated("sink activated\n");
    const qsizetype activations = printed(pair).count(activated);
    QVERIFY(rtctlSucceeds({"act", "PyDoubleSink0.rtc", "PyLongSource0.rtc", "PyDoubleSource0.rtc"}));
    const auto sinkLines = [&] {
        const QString text = printed(pair);
        QStringList lines;
        for (const QString &line : text.mid(text.lastIndexOf(activated)).split(QLatin1Char('\n')))
            if (line.startsWith(QLatin1String("sink got ")))
                lines << line;
        return lines;
    };
    QTRY_VERIFY_WITH_TIMEOUT(printed(pair).count(activated) > activations && sinkLines().size() >= 20, runTimeoutMs);
    QVERIFY(rtctlSucceeds({"deact", "PyLongSource0.rtc", "PyDoubleSource0.rtc", "PyDoubleSink0.rtc"}));
    QVERIFY2(sinkLines().filter(QLatin1String("sink got 1000.125")).size() == sinkLines().size(), qPrintable(sinkLines().join(QLatin1Char('\n')).left(2000)));
    m_live.stop(pair);
}

void TestPython::configurationReachesBoundVariables()
{
    QProcess *config = startConfigComponent();
    QVERIFY(config);
    QVERIFY(rtctlSucceeds({"act", "PyConfig0.rtc"}));
    // The defaults, converted to the types of the variables' values.
    QTRY_VERIFY_WITH_TIMEOUT(printed(config).contains(QLatin1String(
                                 "int_param=1 double_param=0.5 str_param='text' vector_param=[1.5, 2.5] flag_param=False\n")),
                             runTimeoutMs);
    for (const QStringList &change : {QStringList{"int_param", "17"}, QStringList{"vector_param", "3,4.25,5"},
                                      QStringList{"str_param", "changed text"}, QStringList{"flag_param", "YES"}})
        QVERIFY(rtctlSucceeds(QStringList{"conf", "PyConfig0.rtc", "set"} + change));
    QTRY_VERIFY_WITH_TIMEOUT(
        printed(config).contains(QLatin1String("int_param=17 double_param=0.5 str_param='changed text' "
                                               "vector_param=[3.0, 4.25, 5.0] flag_param=True\n")),
        runTimeoutMs);
    // A value that does not convert leaves the variable as it was.
    QVERIFY(rtctlSucceeds({"conf", "PyConfig0.rtc", "set", "double_param", "abc"}));
    QVERIFY(rtctlSucceeds({"conf", "PyConfig0.rtc", "set", "int_param", "18"}));
    QTRY_VERIFY_WITH_TIMEOUT(printed(config).contains(QLatin1String("int_param=18 double_param=0.5 ")), runTimeoutMs);
    stopConfigComponent(config);
}

QProcess *TestPython::startConfigComponent()
{
    const auto gone = [this] { return !rtctl({QStringLiteral("ls")}).out.contains(QLatin1String("PyConfig0")); };
    if (!QTest::qWaitFor(gone, runTimeoutMs))
        return nullptr;
    return startScript(LiveTest::pythonTestScript(QStringLiteral("PyConfig.py")), QStringLiteral("PyConfig0.rtc"));
}

void TestPython::stopConfigComponent(QProcess *config)
{
    // Its exit takes its name out of the name server, which a killed process would leave there.
    rtctlSucceeds({"exit", "PyConfig0.rtc"});
    m_live.stop(config);
}

void TestPython::namingContextsFromPython()
{
    // naming.py lists the name server's bindings through CosNaming (two at a time, so through the
    // BindingIterator too), resolves PyConfig0 by its name and sets int_param through its reference.
    QProcess *config = startConfigComponent();
    QVERIFY(config);
    QVERIFY(rtctlSucceeds({"act", "PyConfig0.rtc"}));
    bool ok = false;
    const QString output = runPython(LiveTest::pythonTestScript(QStringLiteral("naming.py")),
                                     {m_live.namingServer(), QStringLiteral("PyConfig0.rtc"), QStringLiteral("int_param"),
                                      QStringLiteral("23")}, &ok);
    QVERIFY2(ok && output.contains(QLatin1String("naming: ok\n")), qPrintable(output));
    QVERIFY2(output.contains(QStringLiteral("naming: object %1.host_cxt/PyConfig0.rtc RTC\n").arg(hostName)), qPrintable(output));
    QVERIFY2(output.contains(QStringLiteral("naming: object %1.host_cxt/manager.mgr \n").arg(hostName)), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("naming: int_param was 1\n")), qPrintable(output));
    QTRY_VERIFY_WITH_TIMEOUT(printed(config).contains(QLatin1String("int_param=23 ")), runTimeoutMs);
    stopConfigComponent(config);
}

void TestPython::rtcHandleWalksTheNameServer()
{
    const QString autoTest = LiveTest::pythonCorpusDir() + QStringLiteral("/AutoTest");
    if (!QFileInfo::exists(autoTest + QStringLiteral("/rtc_handle.py")))
        QSKIP(NoPythonCorpus);
    QVERIFY(rtctlSucceeds({"mgr", m_host.managerPath(), "create", "ConsoleIn?instance_name=HandleFeed"}));
    QProcess *config = startConfigComponent();
    QVERIFY(config);
    bool ok = false;
    const QString output = runPython(LiveTest::pythonTestScript(QStringLiteral("rtchandle.py")),
                                     {autoTest, m_live.namingServer(), QStringLiteral("PyConfig0.rtc")}, &ok);
    QVERIFY2(ok, qPrintable(output));
    const QString path = hostName + QStringLiteral(".host_cxt/");
    for (const QString &line : {QStringLiteral("objcet %1PyConfig0.rtc was listed.\n").arg(path),
                                QStringLiteral("handle for %1PyConfig0.rtc was created.\n").arg(path),
                                QStringLiteral("objcet %1manager.mgr was listed.\n").arg(path),
                                // The module names its connectors with Python 2's string.join, which
                                // Python 3 lacks: a component with ports gets no handle.
                                QStringLiteral("%1HandleFeed.rtc is not alive.\n").arg(path),
                                QStringLiteral("rtchandle: instance PyConfig0 ports 0\n"),
                                QStringLiteral("rtchandle: int_param 1\n"),
                                QStringLiteral("rtchandle: activate RTC_OK\n"),
                                QStringLiteral("rtchandle: state ACTIVE_STATE\n"),
                                QStringLiteral("rtchandle: deactivate RTC_OK\n"),
                                QStringLiteral("rtchandle: by name True\n"),
                                QStringLiteral("rtchandle: nvlist {'a': 'b', 'n': 3}\n"),
                                QStringLiteral("rtchandle: rtc_handle10_11 RtcHandle\n")})
        QVERIFY2(output.contains(line), qPrintable(line + output));
    QVERIFY(rtctlSucceeds({"mgr", m_host.managerPath(), "delete", "HandleFeed"}));
    stopConfigComponent(config);
}

void TestPython::generatedComponentRuns()
{
    // The Builder's Python project as generated (data ports, OpenRTM_aist.instantiateDataType).
    const QString project = m_work.filePath(QStringLiteral("generated"));
    const RtctlResult generated = runRtctl({"gen", RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/buildergenerate/Counter.xml"), "--lang",
                                            "python", "-o", project});
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QProcess *counter = startScript(project + QStringLiteral("/Counter.py"), QStringLiteral("Counter0.rtc"));
    QVERIFY(counter);
    QVERIFY(rtctlSucceeds({"act", "Counter0.rtc"}));
    QTRY_COMPARE_WITH_TIMEOUT(state(QStringLiteral("Counter0.rtc")), QStringLiteral("Active"), runTimeoutMs);
    const RtctlResult profile = rtctl({"cat", "Counter0.rtc"});
    QVERIFY2(profile.out.contains(QLatin1String("DataInPort: in")) && profile.out.contains(QLatin1String("DataOutPort: count")),
             qPrintable(profile.out));
    m_live.stop(counter);
}

void TestPython::installedPackagesWork()
{
    // The SDK component installs the packages and the extension beside the IDL they read.
    const QString prefix = m_work.filePath(QStringLiteral("prefix"));
    QProcess install;
    install.start(QStringLiteral(CMAKE_COMMAND),
                  {"--install", RTSTUDIO_BUILD_DIR, "--prefix", prefix, "--component", "sdk"});
    QVERIFY(install.waitForFinished(runTimeoutMs * 4));
    QVERIFY2(install.exitCode() == 0, install.readAllStandardError().constData());
    const QString packages = prefix + QStringLiteral("/lib/python3/dist-packages");
    QVERIFY(QFileInfo::exists(packages + QStringLiteral("/OpenRTM_aist/__init__.py")));
    QProcess python;
    python.setProcessEnvironment(m_scripts.environment(packages));
    python.start(QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE),
                 {LiveTest::pythonTestScript(QStringLiteral("datatypes.py")), QStringLiteral("--expect-prefix"), prefix});
    QVERIFY(python.waitForFinished(runTimeoutMs));
    const QString output = QString::fromLocal8Bit(python.readAllStandardOutput() + python.readAllStandardError());
    QVERIFY2(python.exitCode() == 0 && output.contains(QLatin1String("datatypes: ok")), qPrintable(output));
}

QTEST_GUILESS_MAIN(TestPython)
#include "tst_python.moc"
