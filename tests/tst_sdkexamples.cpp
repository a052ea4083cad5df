// SPDX-License-Identifier: MIT
// OpenRTM-aist's own C++ examples, unchanged (the shared conformance corpus), built against the
// component SDK and run on our runtime. Every example folder that is a standalone
// find_package(OpenRTM) project is configured and built as it is, against the build tree's prefix
// and against an installed copy; the examples that build only inside OpenRTM-aist's tree are built
// from their unchanged sources by a small project of ours (data/openrtm/examplesources). Then the
// data-port, service-port and configuration examples run as modules in rtmanager and as <Name>Comp
// programs, exchanging data and calls with rtmanager's built-in components.
// Runs when the corpus is beside the project; skipped with the reason otherwise.
#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkproject.h"

#include <QtTest>

namespace {

constexpr int runTimeoutMs = 30 * 1000;
const QString hostName = QStringLiteral("exhost");

QString corpusDir()
{
    return RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-examples");
}

/// The example folders that are standalone projects: their CMakeLists.txt finds the OpenRTM package.
QStringList standaloneProjects()
{
    QStringList names;
    const QDir corpus(corpusDir());
    for (const QString &name : corpus.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        QFile lists(corpus.filePath(name + QStringLiteral("/CMakeLists.txt")));
        if (lists.open(QIODevice::ReadOnly) && lists.readAll().contains("find_package(OpenRTM"))
            names << name;
    }
    return names;
}

} // namespace

class TestSdkExamples : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void standaloneProjectBuilds_data();
    void standaloneProjectBuilds();
    void treeOnlyExampleBuilds_data();
    void treeOnlyExampleBuilds();
    void dataPortExamplesRunInRtmanager();
    void consoleInProgramFeedsBuiltinSink();
    void seqProgramsExchangeData();
    void serviceExamplesCallBuiltins();
    void configSampleTakesConfiguration();
    void serviceAndConfigurationModulesRunInRtmanager();
    void compositeExampleRuns();

private:
    RtctlResult rtctl(const QStringList &arguments) const;
    QString path(const QString &name) const;
    QString built(const QString &project, const QString &file) const;
    QString status(const QString &component, const char *name) const;
    /// Writes an rtc.conf for a <Name>Comp program registering in the test's name server.
    QString writeConf(const QString &name, const QStringList &extraLines = {});
    /// Starts a <Name>Comp program with @p conf; waits until @p instance is in the name server.
    QProcess *startProgram(const QString &program, const QString &conf, const QString &instance);
    /// What @p process printed so far (kept across calls).
    QString printed(QProcess *process);

    // No "-" in the name: OpenRTP's templates split the SDK's paths at "-I", "-L" and "-l", and a random
    // suffix starting with one of those letters would break every installed-prefix build.
    QTemporaryDir m_work{QDir::tempPath() + QStringLiteral("/rtsdkexamplesXXXXXX")};
    QString m_installPrefix;
    LiveTest::LiveSystem m_live;
    QProcess *m_manager = nullptr;
    CORBA::ORB_var m_orb;
    LiveTest::PrintedOutput m_printed;
};

RtctlResult TestSdkExamples::rtctl(const QStringList &arguments) const
{
    // The examples built with the sanitizers answer slowly while other tests build theirs: each
    // call gets more than rtctl's default 3 s.
    QStringList withTimeout = arguments;
    withTimeout.insert(1, QStringLiteral("--timeout"));
    withTimeout.insert(2, QStringLiteral("15000"));
    return runRtctlAt(QStringLiteral("/%1/%2.host_cxt").arg(m_live.namingServer(), hostName), withTimeout);
}

QString TestSdkExamples::path(const QString &name) const
{
    return QStringLiteral("/%1/%2.host_cxt/%3").arg(m_live.namingServer(), hostName, name);
}

QString TestSdkExamples::built(const QString &project, const QString &file) const
{
    return m_work.filePath(QStringLiteral("build/%1/build/%2").arg(project, file));
}

QString TestSdkExamples::status(const QString &component, const char *name) const
{
    return LiveTest::componentStatus(
        m_orb, QStringLiteral("corbaname::%1#%2.host_cxt/%3").arg(m_live.namingServer(), hostName, component), name);
}

void TestSdkExamples::initTestCase()
{
    if (!QFileInfo::exists(corpusDir() + QStringLiteral("/COPYRIGHT")))
        QSKIP("the OpenRTM-aist examples corpus (shared/conformance/openrtm-examples beside the project) is absent");
    QVERIFY(m_work.isValid());
    QVERIFY2(QFileInfo::exists(RTSTUDIO_BUILD_DIR + QStringLiteral("/lib/librtstudio_rtm.so")), "build rtsdk and rtsdk_stage first");
    QString log;
    // Inside the work folder, so that ccache finds the projects built against it in the next run.
    m_installPrefix = m_work.filePath(QStringLiteral("prefix"));
    QVERIFY2(SdkTest::runTool(QStringLiteral(CMAKE_COMMAND),
                              {"--install", RTSTUDIO_BUILD_DIR, "--prefix", m_installPrefix, "--component", "sdk"},
                              m_work.path(), runTimeoutMs * 4, &log),
             qPrintable(log));

    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_manager = m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), hostName, {}, &error);
    QVERIFY2(m_manager, qPrintable(error));
}

void TestSdkExamples::standaloneProjectBuilds_data()
{
    QTest::addColumn<QString>("project");
    QTest::addColumn<bool>("installed");
    const QStringList projects = standaloneProjects();
    // OpenRTM-aist 2.1.0 has nine; fewer means the corpus or the discovery broke.
    QVERIFY2(projects.size() >= 9, qPrintable(projects.join(' ')));
    for (const QString &project : projects) {
        QTest::newRow(qPrintable(project + QStringLiteral(", build tree"))) << project << false;
        QTest::newRow(qPrintable(project + QStringLiteral(", installed"))) << project << true;
    }
}

void TestSdkExamples::standaloneProjectBuilds()
{
    QFETCH(QString, project);
    QFETCH(bool, installed);
    const QString dir = m_work.filePath((installed ? QStringLiteral("installed/") : QStringLiteral("build/")) + project);
    // A copy: the corpus stays as it is whatever a build writes.
    QVERIFY(SdkTest::copyTree(corpusDir() + QLatin1Char('/') + project, dir));
    QString log;
    QVERIFY2(SdkTest::buildProject(dir, installed ? m_installPrefix : RTSTUDIO_BUILD_DIR, &log),
             qPrintable(project + QStringLiteral(":\n") + log.right(8000)));
    QVERIFY2(QFileInfo::exists(dir + QStringLiteral("/build/src/%1Comp").arg(project)), qPrintable(project));
    QVERIFY2(QFileInfo::exists(dir + QStringLiteral("/build/src/%1.so").arg(project)), qPrintable(project));
}

void TestSdkExamples::treeOnlyExampleBuilds_data()
{
    QTest::addColumn<QString>("example");
    QTest::addColumn<QString>("components");
    QTest::addColumn<QString>("programs");
    QTest::newRow("ConfigSample") << "ConfigSample" << "ConfigSample" << "";
    QTest::newRow("ExtTrigger") << "ExtTrigger" << "ConsoleIn;ConsoleOut" << "ConnectorComp";
    QTest::newRow("Composite") << "Composite" << "" << "Composite";
}

void TestSdkExamples::treeOnlyExampleBuilds()
{
    QFETCH(QString, example);
    QFETCH(QString, components);
    QFETCH(QString, programs);
    const QString dir = m_work.filePath(QStringLiteral("build/") + example);
    QVERIFY(SdkTest::copyTree(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/openrtm/examplesources"), dir));
    QString log;
    QVERIFY2(SdkTest::buildProject(dir, RTSTUDIO_BUILD_DIR, &log,
                                   {"-DEXAMPLE_DIR=" + corpusDir() + '/' + example, "-DCOMPONENTS=" + components,
                                    "-DPROGRAMS=" + programs}),
             qPrintable(log.right(8000)));
    for (const QString &name : components.split(';', Qt::SkipEmptyParts))
        QVERIFY2(QFileInfo::exists(built(example, name + QStringLiteral("Comp"))), qPrintable(name));
    for (const QString &name : programs.split(';', Qt::SkipEmptyParts))
        QVERIFY2(QFileInfo::exists(built(example, name)), qPrintable(name));
}

QString TestSdkExamples::writeConf(const QString &name, const QStringList &extraLines)
{
    const QString file = m_work.filePath(name + QStringLiteral(".conf"));
    QFile conf(file);
    if (!conf.open(QIODevice::WriteOnly | QIODevice::Text))
        return {};
    const QStringList lines = QStringList{QStringLiteral("corba.nameservers: ") + m_live.namingServer(),
                                          QStringLiteral("naming.formats: %1.host_cxt/%n.rtc").arg(hostName),
                                          QStringLiteral("logger.enable: NO"), LiveTest::NoMasterLine}
                              + extraLines;
    conf.write((lines.join('\n') + '\n').toUtf8());
    return file;
}

QProcess *TestSdkExamples::startProgram(const QString &program, const QString &conf, const QString &instance)
{
    QString error;
    QProcess *process = m_live.startRegistered(program, {QStringLiteral("-f"), conf},
        [this, &instance] { return rtctl({QStringLiteral("ls")}).out.contains(instance); }, &error,
        runTimeoutMs);
    if (!process)
        qWarning().noquote() << error;
    return process;
}

QString TestSdkExamples::printed(QProcess *process)
{
    return m_printed.of(process);
}

void TestSdkExamples::dataPortExamplesRunInRtmanager()
{
    // Built-in instances first: the examples' modules register types of the same names.
    const QString manager = path(QStringLiteral("manager.mgr"));
    RtctlResult r = rtctl({"mgr", manager, "create", "ConsoleIn?instance_name=BuiltinIn", "create",
                           "SeqIn?instance_name=BuiltinSeqIn"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"mgr", manager, "load", built("ConsoleOut", "src/ConsoleOut.so"), "create",
               "ConsoleOut?instance_name=ExampleOut", "load", built("SeqOut", "src/SeqOut.so"), "create",
               "SeqOut?instance_name=ExampleSeqOut"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    for (const QStringList &link : {QStringList{"BuiltinIn.rtc:out", "ExampleOut.rtc:in"},
                                    QStringList{"ExampleSeqOut.rtc:Long", "BuiltinSeqIn.rtc:Long"}}) {
        r = rtctl(QStringList{"con"} + link);
        QVERIFY2(r.code == 0, qPrintable(link.join(' ') + ": " + r.out + r.err));
    }
    for (const QString component : {"BuiltinIn.rtc", "ExampleOut.rtc", "ExampleSeqOut.rtc", "BuiltinSeqIn.rtc"}) {
        r = rtctl({"act", component});
        QVERIFY2(r.code == 0, qPrintable(component + ": " + r.out + r.err));
    }
    // OpenRTM's ConsoleOut prints what it receives on the manager's standard output.
    QTRY_VERIFY_WITH_TIMEOUT(printed(m_manager).contains(QLatin1String("Received: ")), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(status(QStringLiteral("BuiltinSeqIn.rtc"), "Long_count").toInt() > 0, runTimeoutMs);
    for (const QString component : {"BuiltinIn.rtc", "ExampleOut.rtc", "ExampleSeqOut.rtc", "BuiltinSeqIn.rtc"})
        QVERIFY(rtctl({"deact", component}).code == 0);
}

void TestSdkExamples::consoleInProgramFeedsBuiltinSink()
{
    const QString manager = path(QStringLiteral("manager.mgr"));
    RtctlResult r = rtctl({"mgr", manager, "create", "ConsoleOut?instance_name=ProgramSink"});
    // After the example's module was loaded, ConsoleOut may be its type; either prints or counts.
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QProcess *in = startProgram(built("ConsoleIn", "src/ConsoleInComp"), writeConf(QStringLiteral("consolein")),
                                QStringLiteral("ConsoleIn0.rtc"));
    QVERIFY(in);
    // OpenRTM's ConsoleIn reads one number from standard input each cycle.
    QByteArray numbers;
    for (int i = 1; i <= 500; ++i)
        numbers += QByteArray::number(i) + '\n';
    in->write(numbers);
    r = rtctl({"con", "ConsoleIn0.rtc:out", "ProgramSink.rtc:in"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err + printed(in)));
    QVERIFY(rtctl({"act", "ProgramSink.rtc"}).code == 0);
    QVERIFY(rtctl({"act", "ConsoleIn0.rtc"}).code == 0);
    QTRY_VERIFY_WITH_TIMEOUT(printed(in).contains(QLatin1String("Please input number")), runTimeoutMs);
    const QString sinkPrinted = QStringLiteral("Received: 3");
    QTRY_VERIFY_WITH_TIMEOUT(status(QStringLiteral("ProgramSink.rtc"), "received_count").toInt() >= 3
                                 || printed(m_manager).contains(sinkPrinted),
                             runTimeoutMs);
    QVERIFY(rtctl({"deact", "ConsoleIn0.rtc"}).code == 0);
    m_live.stop(in);
}

void TestSdkExamples::seqProgramsExchangeData()
{
    // Slow enough that the counters stay small: SeqOut counts, its doubles end in .345.
    const QStringList slow{QStringLiteral("exec_cxt.periodic.rate: 20")};
    QProcess *out = startProgram(built("SeqOut", "src/SeqOutComp"), writeConf(QStringLiteral("seqout"), slow),
                                 QStringLiteral("SeqOut0.rtc"));
    QVERIFY(out);
    QProcess *in = startProgram(built("SeqIn", "src/SeqInComp"), writeConf(QStringLiteral("seqin"), slow),
                                QStringLiteral("SeqIn0.rtc"));
    QVERIFY(in);
    for (const QString port : {"Octet", "Short", "Long", "Float", "Double", "OctetSeq", "ShortSeq", "LongSeq",
                               "FloatSeq", "DoubleSeq"}) {
        const RtctlResult r = rtctl({"con", "SeqOut0.rtc:" + port, "SeqIn0.rtc:" + port});
        QVERIFY2(r.code == 0, qPrintable(port + ": " + r.out + r.err));
    }
    QVERIFY(rtctl({"act", "SeqIn0.rtc"}).code == 0);
    QVERIFY(rtctl({"act", "SeqOut0.rtc"}).code == 0);
    // SeqOut prints each sample it sends ("-: 3.345 3.12 3 3 3[...]"); SeqIn draws a table of
    // what it received, where only received doubles end in .345.
    const QRegularExpression sent(QStringLiteral("-: (\\d+)\\.345 "));
    QTRY_VERIFY_WITH_TIMEOUT(sent.match(printed(out)).hasMatch(), runTimeoutMs);
    const QRegularExpression received(QStringLiteral("\\b\\d+\\.345\\b"));
    QTRY_VERIFY_WITH_TIMEOUT(received.match(printed(in)).hasMatch(), runTimeoutMs);
    m_live.stop(in);
    m_live.stop(out);
}

void TestSdkExamples::serviceExamplesCallBuiltins()
{
    const QString manager = path(QStringLiteral("manager.mgr"));
    RtctlResult r = rtctl({"mgr", manager, "create", "MyServiceProvider?instance_name=BuiltinProvider", "create",
                           "MyServiceConsumer?instance_name=BuiltinConsumer"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QProcess *provider = startProgram(built("MyServiceProvider", "src/MyServiceProviderComp"),
                                      writeConf(QStringLiteral("provider")), QStringLiteral("MyServiceProvider0.rtc"));
    QVERIFY(provider);
    QProcess *consumer = startProgram(built("MyServiceConsumer", "src/MyServiceConsumerComp"),
                                      writeConf(QStringLiteral("consumer")), QStringLiteral("MyServiceConsumer0.rtc"));
    QVERIFY(consumer);
    for (const QStringList &link : {QStringList{"BuiltinConsumer.rtc:MyService", "MyServiceProvider0.rtc:MyService"},
                                    QStringList{"MyServiceConsumer0.rtc:MyService", "BuiltinProvider.rtc:MyService"}}) {
        r = rtctl(QStringList{"con"} + link);
        QVERIFY2(r.code == 0, qPrintable(link.join(' ') + ": " + r.out + r.err));
    }
    for (const QString component : {"MyServiceProvider0.rtc", "MyServiceConsumer0.rtc", "BuiltinProvider.rtc",
                                     "BuiltinConsumer.rtc"})
        QVERIFY2(rtctl({"act", component}).code == 0, qPrintable(component));
    // The built-in consumer calls the example's provider, whose echo() prints the message once a
    // second for ten seconds before it returns.
    QTRY_VERIFY_WITH_TIMEOUT(printed(provider).contains(QLatin1String("MyService::echo() was called.")), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(printed(provider).contains(QLatin1String("Message: echo 1")), runTimeoutMs);
    // The example's consumer takes commands on standard input and calls the built-in provider.
    // set_value() runs in a thread of the consumer's own: ask for the value until it is there.
    consumer->write("set_value 4.5\n");
    QTRY_VERIFY_WITH_TIMEOUT(printed(consumer).contains(QLatin1String("Set remote value: 4.5")), runTimeoutMs);
    const bool valueSet = QTest::qWaitFor(
        [&] {
            const int answers = printed(consumer).count(QLatin1String("Current remote value: "));
            consumer->write("get_value\n");
            const bool answered = QTest::qWaitFor(
                [&] { return printed(consumer).count(QLatin1String("Current remote value: ")) > answers; }, runTimeoutMs);
            return answered && printed(consumer).contains(QLatin1String("Current remote value: 4.5"));
        },
        runTimeoutMs);
    QVERIFY2(valueSet, qPrintable(printed(consumer).right(1000)));
    m_live.stop(consumer);
    m_live.stop(provider);
}

void TestSdkExamples::configSampleTakesConfiguration()
{
    QProcess *sample = startProgram(built("ConfigSample", "ConfigSampleComp"),
                                    writeConf(QStringLiteral("configsample")), QStringLiteral("ConfigSample0.rtc"));
    QVERIFY(sample);
    // ConfigSampleComp activates its component itself and prints the bound variables each cycle.
    QTRY_VERIFY_WITH_TIMEOUT(printed(sample).contains(QLatin1String("int_param0:       0")), runTimeoutMs);
    RtctlResult r = rtctl({"conf", "ConfigSample0.rtc", "set", "int_param0", "17"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"conf", "ConfigSample0.rtc", "set", "str_param1", "changed"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(printed(sample).contains(QLatin1String("int_param0:       17")), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(printed(sample).contains(QLatin1String("str_param1:       changed")), runTimeoutMs);
    m_live.stop(sample);
}

void TestSdkExamples::serviceAndConfigurationModulesRunInRtmanager()
{
    // The same examples as modules of rtmanager: the provider called by the built-in consumer,
    // ConfigSample taking a configuration change; both print on the manager's output.
    const QString manager = path(QStringLiteral("manager.mgr"));
    RtctlResult r = rtctl({"mgr", manager, "create", "MyServiceConsumer?instance_name=ModuleCaller", "load",
                           built("MyServiceProvider", "src/MyServiceProvider.so"), "create",
                           "MyServiceProvider?instance_name=ModuleProvider", "load",
                           built("ConfigSample", "ConfigSample.so"), "create", "ConfigSample?instance_name=ModuleConfig"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = rtctl({"con", "ModuleCaller.rtc:MyService", "ModuleProvider.rtc:MyService"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    for (const QString component : {"ModuleProvider.rtc", "ModuleCaller.rtc", "ModuleConfig.rtc"})
        QVERIFY2(rtctl({"act", component}).code == 0, qPrintable(component));
    QTRY_VERIFY_WITH_TIMEOUT(printed(m_manager).contains(QLatin1String("Message: echo 1")), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(printed(m_manager).contains(QLatin1String("int_param1:       1")), runTimeoutMs);
    r = rtctl({"conf", "ModuleConfig.rtc", "set", "int_param1", "23"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(printed(m_manager).contains(QLatin1String("int_param1:       23")), runTimeoutMs);
    for (const QString component : {"ModuleCaller.rtc", "ModuleConfig.rtc"})
        QVERIFY(rtctl({"deact", component}).code == 0);
}

void TestSdkExamples::compositeExampleRuns()
{
    // OpenRTM's Composite server with its rtc.composite.linux.conf, pointed at the examples built
    // above and at the test's name server: it preloads Controller, Motor and Sensor and composes
    // them in a PeriodicECSharedComposite that exports Sensor0.in and Motor0.out.
    QStringList modules;
    for (const QString &member : {QStringLiteral("Controller"), QStringLiteral("Motor"), QStringLiteral("Sensor")})
        modules << QFileInfo(built(member, QStringLiteral("src/%1.so").arg(member))).absolutePath();
    const QString conf = writeConf(
        QStringLiteral("composite"),
        {QStringLiteral("manager.modules.load_path: ") + modules.join(QStringLiteral(", ")),
         QStringLiteral("manager.modules.preload: Controller.so, Motor.so, Sensor.so"),
         QStringLiteral("manager.components.precreate: Controller, Motor, Sensor, PeriodicECSharedComposite"),
         QStringLiteral("composite.PeriodicECShared.PeriodicECSharedComposite0.config_file: ") + corpusDir()
             + QStringLiteral("/Composite/composite.conf")});
    QProcess *server = startProgram(built("Composite", "Composite"), conf, QStringLiteral("PeriodicECSharedComposite0.rtc"));
    QVERIFY(server);
    const RtctlResult cat = rtctl({"cat", "PeriodicECSharedComposite0.rtc"});
    QVERIFY2(cat.out.contains(QRegularExpression(QStringLiteral("Members +Sensor0, Controller0, Motor0\n"))),
             qPrintable(cat.out));
    for (const QStringList &link : {QStringList{"Sensor0.rtc:out", "Controller0.rtc:in"},
                                    QStringList{"Controller0.rtc:out", "Motor0.rtc:in"}}) {
        const RtctlResult r = rtctl(QStringList{"con"} + link);
        QVERIFY2(r.code == 0, qPrintable(link.join(' ') + ": " + r.out + r.err));
    }
    // Through the composite's exported ports, from and to rtmanager's built-ins.
    const QString manager = path(QStringLiteral("manager.mgr"));
    RtctlResult r = rtctl({"mgr", manager, "create", "ConsoleIn?instance_name=CompositeFeed", "create",
                           "ConsoleOut?instance_name=CompositeSink"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    for (const QStringList &link : {QStringList{"CompositeFeed.rtc:out", "PeriodicECSharedComposite0.rtc:in"},
                                    QStringList{"PeriodicECSharedComposite0.rtc:out", "CompositeSink.rtc:in"}}) {
        r = rtctl(QStringList{"con"} + link);
        QVERIFY2(r.code == 0, qPrintable(link.join(' ') + ": " + r.out + r.err));
    }
    // The sink is OpenRTM's ConsoleOut by now (its module replaced the built-in type): it prints
    // what it receives on the manager's standard output.
    const int receivedBefore = printed(m_manager).count(QLatin1String("Received: "));
    for (const QString component : {"CompositeSink.rtc", "PeriodicECSharedComposite0.rtc", "CompositeFeed.rtc"})
        QVERIFY2(rtctl({"act", component}).code == 0, qPrintable(component));
    // Activating the composite activated its members; the feed's numbers pass Sensor, Controller
    // and Motor on the composite's context and leave through its exported port.
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "Motor0.rtc"}).out.contains(QLatin1String("Active")), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(printed(server).contains(QLatin1String("Motor Received data: ")), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(printed(m_manager).count(QLatin1String("Received: ")) > receivedBefore, runTimeoutMs);
    QVERIFY(rtctl({"deact", "PeriodicECSharedComposite0.rtc"}).code == 0);
    QTRY_VERIFY_WITH_TIMEOUT(!rtctl({"cat", "Motor0.rtc"}).out.contains(QLatin1String("Active")), runTimeoutMs);
    m_live.stop(server);
}

QTEST_GUILESS_MAIN(TestSdkExamples)
#include "tst_sdkexamples.moc"
