// SPDX-License-Identifier: MIT
// OpenRTM-aist-Python's examples beyond SimpleIO and SeqIO, unchanged from the shared conformance
// corpus (each skipped with the reason when it is absent), run with python3 on RT Studio's runtime
// and driven with rtctl:
// - ConfigSample: its configuration sets and bound parameters of every kind, its parameter
//   listener, activating itself through its execution context's object reference;
// - Composite: Sensor, Controller and Motor (Python modules the program's manager preloads) as
//   members of the SDK's PeriodicECSharedComposite, fed and read by rtmanager's built-ins through
//   the composite's exported ports;
// - ExtTrigger: ConsoleIn and ConsoleOut on ExtTrigExecutionContexts, each stepping once per tick
//   the test sends, and driven as the example's Connector.py drives them, through the ORB from
//   Python: the example's Connector.py itself on a simulated host of its own, whose localhost has the
//   default name server it asks, and data/python/PyConnector.py, its calls against the test's;
// - AutoControl: the velocities it answers to range samples, read with rtctl print;
// - Throughput: its own OutPort feeding its InPort, the measurements file it writes per size, its
//   exit() at the end taking the program with it;
// - StaticFsm: Inputbutton's commands driving Microwave's static state machine through event
//   ports;
// - CSPSample and CSPSelectSample: writers and readers on CSP channels, selecting among them;
//   CSPStaticFsmSample failing as it fails on OpenRTM-aist-Python;
// and the same abilities through components of ours (data/python) that need no corpus: a component
// with two configuration sets and every configuration listener; a Python module's component as
// the member of a PeriodicECSharedComposite of rtmanager; a component that ticks its own
// ExtTrigExecutionContext; a Python component created in a slave manager of its own, whose end
// leaves the master serving; wide characters, unions and object references in samples
// (data/python/widechars.py, unions.py, references.py), static FSMs (staticfsm.py), anys and
// NVLists (anys.py), values straight to CDR and back as through the converter (directcdr.py), and
// CSP channels, their selection and event ports (csp.py), and rtc.conf's port settings as the defaults
// of connections (portsettings.py).
#include "hostrtctl.h"
#include "pythonscripts.h"
#include "simulatedhosts.h"

#include <Manager.hh>
#include <OpenRTM.hh>

#include <csignal>

#include <QStandardPaths>
#include <QtTest>

namespace {

constexpr const char *NoPythonCorpus
    = "the OpenRTM-aist-Python examples corpus (shared/conformance/openrtm-python-examples beside the project) "
      "is absent";

constexpr int runTimeoutMs = 30 * 1000;
const QString hostName = QStringLiteral("pyexamples");

} // namespace

class TestPythonExamples : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void configSampleRunsUnchanged();
    void configurationSetsAndListeners();
    void configurationChangesWhileExecuting();
    void compositeRunsUnchanged();
    void pythonMemberOfCompositeInManager();
    void connectorDrivesExtTriggerThroughTheOrb();
    void connectorRunsUnchangedOnAHostOfItsOwn();
    void extTriggerStepsOnlyWhenTicked();
    void componentTicksItsOwnContext();
    void pythonComponentInSlaveOfItsOwn();
    void autoControlRunsUnchanged();
    void throughputRunsUnchanged();
    void staticFsmRunsUnchanged_data();
    void staticFsmRunsUnchanged();
    void serializerExampleRunsUnchanged_data();
    void serializerExampleRunsUnchanged();
    void serializerExampleRunsAsItsRtcConfSays();
    void cspExamplesRunUnchanged_data();
    void cspExamplesRunUnchanged();
    void cspFsmExampleFailsAsOnOpenRtm();
    void dataTypesConvert_data();
    void dataTypesConvert();

private:
    /// The corpus example @p file (`ConfigSample/ConfigSample.py`); empty when the corpus is absent.
    static QString example(const QString &file);
    /// The lines of the example's rtc.conf @p file for the test's name server (see the definition);
    /// its logger's lines too when @p withLogger.
    static QStringList exampleConf(const QString &file, bool withLogger = false);
    /// rtctl with more than its default 3 s per call: the Python components answer slowly under
    /// the sanitizers while other tests run.
    bool rtctlSucceeds(QStringList arguments) const
    {
        arguments.insert(1, QStringLiteral("--timeout"));
        arguments.insert(2, QStringLiteral("15000"));
        return m_host.succeeds(arguments);
    }
    QString printed(QProcess *process) { return m_printed.of(process); }
    /// The process id of the slave manager named @p name (0 when the master has none such).
    qint64 slavePid(const QString &name) const;
    /// Ticks the ExtTrigExecutionContext @p component owns, as OpenRTM's Connector.py does.
    bool tick(const QString &component) const;
    /// `rtctl @p arguments` left running in the host's context (stopped with the test's processes).
    QProcess *startRtctl(const QStringList &arguments);

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
    LiveTest::HostRtctl m_host{m_live, hostName};
    LiveTest::PythonScripts m_scripts{m_live,
                                      m_host,
                                      hostName,
                                      QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE),
                                      RTSTUDIO_PYTHON_PATH,
                                      QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD),
                                      m_work.path()};
    LiveTest::PrintedOutput m_printed;
    QProcess *m_manager = nullptr;
    CORBA::ORB_var m_orb;
};

QString TestPythonExamples::example(const QString &file)
{
    const QString path = LiveTest::pythonCorpusDir() + QLatin1Char('/') + file;
    return QFileInfo::exists(path) ? path : QString();
}

QStringList TestPythonExamples::exampleConf(const QString &file, bool withLogger)
{
    // The example's own lines, but for where names are bound and logged (the test's rtc.conf says);
    // its module folder (`./` beside it) is named in full.
    QFile conf(example(file));
    if (!conf.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    QStringList lines;
    for (const QString &line : QString::fromUtf8(conf.readAll()).split(QLatin1Char('\n'))) {
        if (!line.startsWith(QLatin1String("corba.nameservers")) && !line.startsWith(QLatin1String("naming.formats"))
            && (withLogger || !line.startsWith(QLatin1String("logger."))))
            lines.append(line);
    }
    return lines << QStringLiteral("manager.modules.load_path: ") + QFileInfo(conf).absolutePath();
}

bool TestPythonExamples::tick(const QString &component) const
{
    try {
        const QString name = QStringLiteral("corbaname::%1#%2.host_cxt/%3").arg(m_live.namingServer(), hostName, component);
        CORBA::Object_var object = m_orb->string_to_object(name.toUtf8().constData());
        RTC::RTObject_var rtc = RTC::RTObject::_narrow(object);
        RTC::ExecutionContextList_var contexts = rtc->get_owned_contexts();
        OpenRTM::ExtTrigExecutionContextService_var context =
            OpenRTM::ExtTrigExecutionContextService::_narrow(contexts[0].in());
        if (CORBA::is_nil(context))
            return false;
        context->tick();
        return true;
    } catch (const CORBA::Exception &error) {
        qWarning() << "tick" << component << error._name();
        return false;
    }
}

QProcess *TestPythonExamples::startRtctl(const QStringList &arguments)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("RTCSH_CWD"), QStringLiteral("/%1/%2.host_cxt").arg(m_live.namingServer(), hostName));
    environment.insert(QStringLiteral("RTCTREE_NAMESERVERS"), QString());
    QString error;
    QProcess *process = m_live.startProcess(RTCTL_PATH, arguments, QString(), &error, runTimeoutMs, environment);
    if (!process)
        qWarning().noquote() << error;
    return process;
}

qint64 TestPythonExamples::slavePid(const QString &name) const
{
    RTM::ManagerList_var slaves;
    try {
        const QString path = QStringLiteral("corbaname::%1#%2.host_cxt/manager.mgr").arg(m_live.namingServer(), hostName);
        CORBA::Object_var object = m_orb->string_to_object(path.toUtf8().constData());
        slaves = RTM::Manager::_narrow(object)->get_slave_managers();
    } catch (const CORBA::Exception &error) {
        qWarning() << "slaves of the manager:" << error._name();
        return 0;
    }
    for (CORBA::ULong i = 0; i < slaves->length(); ++i) {
        try {
            RTM::ManagerProfile_var profile = slaves[i]->get_profile();
            QHash<QString, QString> properties;
            for (CORBA::ULong j = 0; j < profile->properties.length(); ++j) {
                const char *text = nullptr;
                if (profile->properties[j].value >>= text)
                    properties.insert(QString::fromUtf8(profile->properties[j].name.in()), QString::fromUtf8(text));
            }
            if (properties.value(QStringLiteral("instance_name")) == name)
                return properties.value(QStringLiteral("pid")).toLongLong();
        } catch (const CORBA::Exception &) {
            // A slave that has just ended, not yet dropped by the master.
        }
    }
    return 0;
}

void TestPythonExamples::initTestCase()
{
    QVERIFY(m_work.isValid());
    QVERIFY2(QFileInfo::exists(RTSTUDIO_PYTHON_PATH + QStringLiteral("/OpenRTM_aist/__init__.py")), "build rtpython first");
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    // The managers (and their slaves) embed Python, which keeps its objects until exit by design.
    LiveTest::startChildrenWithoutLeakChecks();
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    // Our Python modules are in the load path, found by their type names (in slaves too).
    m_manager = m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), hostName,
                                        {QStringLiteral("manager.modules.load_path=") + RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/python")},
                                        &error);
    QVERIFY2(m_manager, qPrintable(error));
}

void TestPythonExamples::configSampleRunsUnchanged()
{
    const QString script = example(QStringLiteral("ConfigSample/ConfigSample.py"));
    if (script.isEmpty())
        QSKIP(NoPythonCorpus);
    // Its own configuration file: sets default, mode0 and mode1, mode1 active.
    QProcess *sample = m_scripts.start(script, {QStringLiteral("ConfigSample0.rtc")}, runTimeoutMs,
        {QStringLiteral("example.ConfigSample.config_file: ") + LiveTest::pythonCorpusDir() + QStringLiteral("/ConfigSample/configsample.conf")});
    QVERIFY(sample);
    // ConfigSample activates itself through get_owned_contexts() and prints its variables each cycle.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sample).contains(QLatin1String("Active Configuration Set:  mode1")),
                              qPrintable(printed(sample).right(2000)), runTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sample).contains(QLatin1String("int_param0:        [-999]")),
                              qPrintable(printed(sample).right(2000)), runTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sample).contains(QLatin1String("vector_param0[ 8 ]:  9.0")),
                              qPrintable(printed(sample).right(2000)), runTimeoutMs);

    QVERIFY(rtctlSucceeds({"conf", "ConfigSample0.rtc", "set", "int_param0", "17"}));
    QVERIFY(rtctlSucceeds({"conf", "ConfigSample0.rtc", "set", "str_param1", "changed"}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sample).contains(QLatin1String("int_param0:        [17]")),
                              qPrintable(printed(sample).right(2000)), runTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sample).contains(QLatin1String("str_param1:        ['changed']")),
                              qPrintable(printed(sample).right(2000)), runTimeoutMs);
    // Its ConfigurationParamListener, told of each parameter that changed.
    QVERIFY2(printed(sample).contains(QLatin1String("Changed config_set_name:  mode1  config_param_name:  int_param0")),
             qPrintable(printed(sample).right(2000)));

    // Switching the set: mode0's values reach the variables.
    QVERIFY(rtctlSucceeds({"conf", "ConfigSample0.rtc", "-s", "mode0", "act"}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sample).contains(QLatin1String("Active Configuration Set:  mode0")),
                              qPrintable(printed(sample).right(2000)), runTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sample).contains(QLatin1String("str_param0:        ['mode0']")),
                              qPrintable(printed(sample).right(2000)), runTimeoutMs);
    QVERIFY2(printed(sample).contains(QLatin1String("int_param0:        [12345]")), qPrintable(printed(sample).right(2000)));
    m_live.stop(sample);
}

void TestPythonExamples::configurationSetsAndListeners()
{
    QProcess *sets = m_scripts.start(LiveTest::pythonTestScript(QStringLiteral("PyConfigSets.py")), {QStringLiteral("PyConfigSets0.rtc")},
                                     runTimeoutMs);
    QVERIFY(sets);
    // PyConfigSets activates itself (self._objref through its own context) and reports its state.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sets).contains(QLatin1String("state ACTIVE_STATE rate 20.0\n")),
                              qPrintable(printed(sets)), runTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sets).contains(QLatin1String("set default gain=[2] names=['a', 'b']\n")),
                              qPrintable(printed(sets)), runTimeoutMs);
    QVERIFY(rtctlSucceeds({"conf", "PyConfigSets0.rtc", "set", "gain", "5"}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sets).contains(QLatin1String("set default gain=[5] names=['a', 'b']\n")),
                              qPrintable(printed(sets)), runTimeoutMs);
    QVERIFY(printed(sets).contains(QLatin1String("param default gain\n")));
    QVERIFY(rtctlSucceeds({"conf", "PyConfigSets0.rtc", "-s", "fast", "act"}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sets).contains(QLatin1String("set fast gain=[40] names=['x']\n")),
                              qPrintable(printed(sets)), runTimeoutMs);
    // The set listeners: the written set with its values, each activation by name.
    QVERIFY2(printed(sets).contains(QLatin1String("activated fast\n")), qPrintable(printed(sets)));
    QVERIFY2(printed(sets).contains(QLatin1String("set changed gain=5\n")), qPrintable(printed(sets)));
    // A removed listener is told nothing more; the others still are.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sets).contains(QLatin1String("param listener removed\n")), qPrintable(printed(sets)),
                              runTimeoutMs);
    QVERIFY(rtctlSucceeds({"conf", "PyConfigSets0.rtc", "-s", "fast", "set", "gain", "41"}));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(sets).contains(QLatin1String("set fast gain=[41] names=['x']\n")),
                              qPrintable(printed(sets)), runTimeoutMs);
    const QString afterRemoval = printed(sets).section(QLatin1String("param listener removed\n"), 1);
    QVERIFY2(!afterRemoval.contains(QLatin1String("param ")), qPrintable(afterRemoval));
    QVERIFY2(afterRemoval.contains(QLatin1String("set changed gain=41\n")), qPrintable(afterRemoval));
    m_live.stop(sets);
}

// A change from outside reaches the configuration listeners (Python, so they need the interpreter)
// while the component's execution context, holding the interpreter, asks the configuration for its
// active set: neither may wait for the other (before, this stopped the component about one time in
// sixty with PyConfigSets, at once with this one).
void TestPythonExamples::configurationChangesWhileExecuting()
{
    QProcess *busy = m_scripts.start(LiveTest::pythonTestScript(QStringLiteral("PyConfigBusy.py")),
                                     {QStringLiteral("PyConfigBusy0.rtc")}, runTimeoutMs);
    QVERIFY(busy);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(busy).contains(QLatin1String("gain [0] sets told 0 params told 0\n")),
                              qPrintable(printed(busy)), runTimeoutMs);
    for (int gain = 1; gain <= 10; ++gain) {
        QVERIFY2(rtctlSucceeds({"conf", "PyConfigBusy0.rtc", "set", "gain", QString::number(gain)}),
                 qPrintable(printed(busy).right(600)));
    }
    QTRY_VERIFY2_WITH_TIMEOUT(printed(busy).contains(QLatin1String("gain [10] sets told 10 params told 10\n")),
                              qPrintable(printed(busy).right(600)), runTimeoutMs);
    m_live.stop(busy);
}

void TestPythonExamples::compositeRunsUnchanged()
{
    const QString script = example(QStringLiteral("Composite/Composite.py"));
    if (script.isEmpty())
        QSKIP(NoPythonCorpus);
    // The example's rtc.conf, with its module folder for "." and its composite.conf by path.
    const QString folder = QFileInfo(script).absolutePath();
    QProcess *server = m_scripts.start(script, {QStringLiteral("PeriodicECSharedComposite0.rtc")}, runTimeoutMs,
        {QStringLiteral("manager.modules.load_path: ") + folder,
         QStringLiteral("manager.modules.preload: Controller, Motor, Sensor"),
         QStringLiteral("manager.components.precreate: Controller, Motor, Sensor, PeriodicECSharedComposite"),
         QStringLiteral("composite.PeriodicECShared.PeriodicECSharedComposite0.config_file: ") + folder
             + QStringLiteral("/composite.conf")});
    QVERIFY(server);
    const RtctlResult cat = m_host.run({"cat", "PeriodicECSharedComposite0.rtc"});
    QVERIFY2(cat.out.contains(QRegularExpression(QStringLiteral("Members +Sensor0, Controller0, Motor0\n"))),
             qPrintable(cat.out));
    QVERIFY(rtctlSucceeds({"con", "Sensor0.rtc:out", "Controller0.rtc:in"}));
    QVERIFY(rtctlSucceeds({"con", "Controller0.rtc:out", "Motor0.rtc:in"}));
    // Through the composite's exported ports (Sensor0.in, Motor0.out), from and to rtmanager's built-ins.
    QVERIFY(rtctlSucceeds({"mgr", m_host.managerPath(), "create", "ConsoleIn?instance_name=CompositeFeed", "create",
                           "ConsoleOut?instance_name=CompositeSink"}));
    QVERIFY(rtctlSucceeds({"con", "CompositeFeed.rtc:out", "PeriodicECSharedComposite0.rtc:in"}));
    QVERIFY(rtctlSucceeds({"con", "PeriodicECSharedComposite0.rtc:out", "CompositeSink.rtc:in"}));
    for (const char *component : {"CompositeSink.rtc", "PeriodicECSharedComposite0.rtc", "CompositeFeed.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    // Activating the composite activated its Python members; on the composite's context each passes
    // the feed's numbers on (Sensor and Controller double them, Motor doubles and truncates).
    // Members are active in the composite's context (`rtctl ls` shows their own one).
    const auto motorActive = [this] { return m_host.run({"cat", "Motor0.rtc"}).out.contains(QLatin1String("Active")); };
    QTRY_VERIFY_WITH_TIMEOUT(motorActive(), runTimeoutMs);
    for (const char *member : {"Sensor Received data: ", "Controller Received data: ", "Motor Received data: "})
        QTRY_VERIFY2_WITH_TIMEOUT(printed(server).contains(QLatin1String(member)), qPrintable(printed(server).right(2000)),
                                  runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(m_host.status(m_orb, QStringLiteral("CompositeSink.rtc"), "received_count").toInt() > 0,
                             runTimeoutMs);
    // Eight times the number fed: what left Motor0.out is a multiple of 8.
    const QList<qint64> values = LiveTest::integers(m_host.status(m_orb, QStringLiteral("CompositeSink.rtc"), "received_values"));
    QVERIFY(!values.isEmpty());
    QVERIFY2(values.first() > 0 && values.first() % 8 == 0, qPrintable(QString::number(values.first())));
    QVERIFY(rtctlSucceeds({"deact", "PeriodicECSharedComposite0.rtc"}));
    QTRY_VERIFY_WITH_TIMEOUT(!motorActive(), runTimeoutMs);
    QVERIFY(rtctlSucceeds({"deact", "CompositeFeed.rtc"}));
    m_live.stop(server);
}

void TestPythonExamples::pythonMemberOfCompositeInManager()
{
    // PyScaler (x1000) in rtmanager, the only member of a composite that exports both its ports.
    QVERIFY(rtctlSucceeds({"mgr", m_host.managerPath(), "load", LiveTest::pythonTestScript(QStringLiteral("PyScaler.py")), "create",
                           "PyScaler?instance_name=ScalerMember", "create",
                           "PeriodicECSharedComposite?instance_name=ScalerComposite&conf.default.members=ScalerMember"
                           "&conf.default.exported_ports=ScalerMember.in,ScalerMember.out",
                           "create", "ConsoleIn?instance_name=MemberFeed", "create",
                           "ConsoleOut?instance_name=MemberSink"}));
    QVERIFY(rtctlSucceeds({"con", "MemberFeed.rtc:out", "ScalerComposite.rtc:in"}));
    QVERIFY(rtctlSucceeds({"con", "ScalerComposite.rtc:out", "MemberSink.rtc:in"}));
    for (const char *component : {"MemberSink.rtc", "ScalerComposite.rtc", "MemberFeed.rtc"})
        QVERIFY(rtctlSucceeds({"act", component}));
    QTRY_VERIFY_WITH_TIMEOUT(m_host.status(m_orb, QStringLiteral("MemberSink.rtc"), "received_count").toInt() > 0,
                             runTimeoutMs);
    const QList<qint64> values = LiveTest::integers(m_host.status(m_orb, QStringLiteral("MemberSink.rtc"), "received_values"));
    QVERIFY(!values.isEmpty());
    QVERIFY2(values.first() > 0 && values.first() % 1000 == 0, qPrintable(QString::number(values.first())));
    for (const char *component : {"MemberFeed.rtc", "ScalerComposite.rtc"})
        QVERIFY(rtctlSucceeds({"deact", component}));
}

void TestPythonExamples::connectorDrivesExtTriggerThroughTheOrb()
{
    const QString in = example(QStringLiteral("ExtTrigger/ConsoleIn.py"));
    if (in.isEmpty())
        QSKIP(NoPythonCorpus);
    const QStringList conf{QStringLiteral("exec_cxt.periodic.type: ExtTrigExecutionContext"),
                           QStringLiteral("exec_cxt.periodic.rate: 1000")};
    QProcess *out = m_scripts.start(example(QStringLiteral("ExtTrigger/ConsoleOut.py")), {QStringLiteral("ConsoleOut0.rtc")},
                                    runTimeoutMs, conf);
    QVERIFY(out);
    QProcess *source = m_scripts.start(in, {QStringLiteral("ConsoleIn0.rtc")}, runTimeoutMs, conf);
    QVERIFY(source);
    source->write("41\n42\n");
    // Names resolved, ports found, disconnected, connected and components activated through their
    // references; contexts narrowed to OpenRTM.ExtTrigExecutionContextService and ticked.
    QString error;
    QProcess *connector = m_live.startProcess(
        QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE),
        {LiveTest::pythonTestScript(QStringLiteral("PyConnector.py")), m_live.namingServer(),
         hostName + QStringLiteral(".host_cxt/"), QStringLiteral("-f"), m_scripts.writeConf(QStringLiteral("connector"), {})},
        QString(), &error, runTimeoutMs, m_scripts.environment());
    QVERIFY2(connector, qPrintable(error));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(connector).contains(QLatin1String("connector: connect RTC_OK connector0 True\n")),
                              qPrintable(printed(connector)), runTimeoutMs);
    QVERIFY2(printed(connector).contains(QLatin1String("connector: ConsoleIn0.rtc activated RTC_OK\n"))
                 && printed(connector).contains(QLatin1String("connector: ConsoleOut0.rtc activated RTC_OK\n")),
             qPrintable(printed(connector)));
    QCOMPARE(m_host.state(QStringLiteral("ConsoleIn0.rtc")), QStringLiteral("Active"));
    // Activating ran one cycle of each; ticking ConsoleIn sends the next number, ticking ConsoleOut
    // takes it.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(source).contains(QLatin1String("Sending to subscriber:  41\n")),
                              qPrintable(printed(source)), runTimeoutMs);
    connector->write("0\n");
    QTRY_VERIFY2_WITH_TIMEOUT(printed(source).contains(QLatin1String("Sending to subscriber:  42\n")),
                              qPrintable(printed(source)), runTimeoutMs);
    connector->write("1\n");
    QTRY_VERIFY2_WITH_TIMEOUT(printed(out).contains(QLatin1String("Received:  42\n")), qPrintable(printed(out)),
                              runTimeoutMs);
    connector->write("q\n");
    QVERIFY(LiveTest::waitForExit(connector, runTimeoutMs));
    // Their names go with them, for the next test's programs of the same names.
    QVERIFY(rtctlSucceeds({"exit", "ConsoleIn0.rtc", "ConsoleOut0.rtc"}));
    m_live.stop(source);
    m_live.stop(out);
}

void TestPythonExamples::connectorRunsUnchangedOnAHostOfItsOwn()
{
    const QString connectorScript = example(QStringLiteral("ExtTrigger/Connector.py"));
    if (connectorScript.isEmpty())
        QSKIP(NoPythonCorpus);
    // Connector.py asks localhost's default name server (port 2809): a host of its own has one.
    LiveTest::SimulatedHosts hosts;
    QString error;
    if (!hosts.create({QStringLiteral("pyexthost")}, &error))
        QSKIP(qPrintable(QStringLiteral("cannot simulate a host: ") + error));
    const QString address = hosts.address(QStringLiteral("pyexthost"));
    LiveTest::LiveSystem host(hosts.liveHost(QStringLiteral("pyexthost")));
    QTemporaryDir names;
    QProcess *nameServer = host.startProcess(
        QStandardPaths::findExecutable(QStringLiteral("omniNames")),
        {QStringLiteral("-start"), QStringLiteral("2809"), QStringLiteral("-datadir"), names.path(), QStringLiteral("-logdir"),
         names.path(), QStringLiteral("-ORBendPoint"), QStringLiteral("giop:tcp:127.0.0.1:2809"),
         QStringLiteral("-ORBendPoint"), QStringLiteral("giop:tcp:%1:2809").arg(address)},
        QString(), &error, runTimeoutMs);
    QVERIFY2(nameServer, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::isListening(address, 2809), runTimeoutMs);
    // The example's rtc.conf: the default name server, names at its root, ExtTrigExecutionContexts.
    QFile conf(m_work.filePath(QStringLiteral("exttrigger.conf")));
    QVERIFY(conf.open(QIODevice::WriteOnly | QIODevice::Text));
    conf.write("corba.nameservers: localhost\nnaming.formats: %n.rtc\nlogger.enable: NO\n"
               "exec_cxt.periodic.type: ExtTrigExecutionContext\nexec_cxt.periodic.rate: 1000\n");
    conf.close();
    const auto startExample = [&](const QString &file) {
        return host.startProcess(QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE), {example(file), QStringLiteral("-f"), conf.fileName()},
                                 QString(), &error, runTimeoutMs, m_scripts.environment());
    };
    QProcess *out = startExample(QStringLiteral("ExtTrigger/ConsoleOut.py"));
    QVERIFY2(out, qPrintable(error));
    QProcess *source = startExample(QStringLiteral("ExtTrigger/ConsoleIn.py"));
    QVERIFY2(source, qPrintable(error));
    source->write("51\n52\n");
    const auto listed = [&] { return runRtctlAt(QStringLiteral("/%1:2809").arg(address), {QStringLiteral("ls")}).out; };
    QTRY_VERIFY2_WITH_TIMEOUT(listed().contains(QLatin1String("ConsoleIn0.rtc")) && listed().contains(QLatin1String("ConsoleOut0.rtc")),
                              qPrintable(listed()), runTimeoutMs);
    QProcess *connector = startExample(QStringLiteral("ExtTrigger/Connector.py"));
    QVERIFY2(connector, qPrintable(error));
    // It activates both (one cycle each) and connects them, then ticks on its commands.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(connector).contains(QLatin1String("cmd? >")), qPrintable(printed(connector)), runTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(source).contains(QLatin1String("Sending to subscriber:  51\n")),
                              qPrintable(printed(source)), runTimeoutMs);
    connector->write("0\n");
    QTRY_VERIFY2_WITH_TIMEOUT(printed(source).contains(QLatin1String("Sending to subscriber:  52\n")),
                              qPrintable(printed(source)), runTimeoutMs);
    // ConsoleIn's first cycle (its activation's) sent 51 before or after the connection was made: when
    // after, ConsoleOut's buffer holds 51 before 52 and its first tick reads 51.
    connector->write("1\n");
    QTRY_VERIFY2_WITH_TIMEOUT(printed(out).contains(QLatin1String("Received:  5")), qPrintable(printed(out)), runTimeoutMs);
    if (!printed(out).contains(QLatin1String("Received:  52\n"))) {
        QVERIFY2(printed(out).contains(QLatin1String("Received:  51\n")), qPrintable(printed(out)));
        connector->write("1\n");
    }
    QTRY_VERIFY2_WITH_TIMEOUT(printed(out).contains(QLatin1String("Received:  52\n")), qPrintable(printed(out)), runTimeoutMs);
    QVERIFY2(!printed(connector).contains(QLatin1String("Exception.")), qPrintable(printed(connector)));
    connector->write("q\n");
    QVERIFY(LiveTest::waitForExit(connector, runTimeoutMs));
    host.stop(source);
    host.stop(out);
}

void TestPythonExamples::extTriggerStepsOnlyWhenTicked()
{
    const QString in = example(QStringLiteral("ExtTrigger/ConsoleIn.py"));
    if (in.isEmpty())
        QSKIP(NoPythonCorpus);
    // The example's rtc.conf: every component on an ExtTrigExecutionContext.
    const QStringList conf{QStringLiteral("exec_cxt.periodic.type: ExtTrigExecutionContext"),
                           QStringLiteral("exec_cxt.periodic.rate: 1000")};
    QProcess *out = m_scripts.start(example(QStringLiteral("ExtTrigger/ConsoleOut.py")), {QStringLiteral("ConsoleOut0.rtc")},
                                    runTimeoutMs, conf);
    QVERIFY(out);
    QProcess *source = m_scripts.start(in, {QStringLiteral("ConsoleIn0.rtc")}, runTimeoutMs, conf);
    QVERIFY(source);
    source->write("11\n22\n33\n");
    QVERIFY(rtctlSucceeds({"con", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in", "-p", "dataport.subscription_type=flush"}));
    const auto sent = [&] { return printed(source).count(QLatin1String("Sending to subscriber:")); };
    const auto received = [&] { return printed(out).count(QLatin1String("Received:")); };
    // As OpenRTM's ExtTrigExecutionContext, activating runs one cycle; after it, one cycle per tick.
    QVERIFY(rtctlSucceeds({"act", "ConsoleIn0.rtc"}));
    QTRY_COMPARE_WITH_TIMEOUT(sent(), 1, runTimeoutMs);
    QVERIFY(tick(QStringLiteral("ConsoleIn0.rtc")));
    QVERIFY(tick(QStringLiteral("ConsoleIn0.rtc")));
    QTRY_COMPARE_WITH_TIMEOUT(sent(), 3, runTimeoutMs);
    QVERIFY2(printed(source).contains(QLatin1String("Sending to subscriber:  33\n")), qPrintable(printed(source)));
    // ConsoleOut, inactive meanwhile, takes one sample per cycle: its activation's, then a tick's.
    QCOMPARE(received(), 0);
    QVERIFY(rtctlSucceeds({"act", "ConsoleOut0.rtc"}));
    QTRY_COMPARE_WITH_TIMEOUT(received(), 1, runTimeoutMs);
    QVERIFY(tick(QStringLiteral("ConsoleOut0.rtc")));
    QTRY_COMPARE_WITH_TIMEOUT(received(), 2, runTimeoutMs);
    QVERIFY2(printed(out).contains(QLatin1String("Received:  11\n")), qPrintable(printed(out)));
    // ConsoleIn, not ticked meanwhile, has not stepped.
    QCOMPARE(sent(), 3);
    QVERIFY(rtctlSucceeds({"deact", "ConsoleIn0.rtc", "ConsoleOut0.rtc"}));
    m_live.stop(source);
    m_live.stop(out);
}

void TestPythonExamples::componentTicksItsOwnContext()
{
    QProcess *ticked = m_scripts.start(LiveTest::pythonTestScript(QStringLiteral("PyTicked.py")), {QStringLiteral("PyTicked0.rtc")},
                                       runTimeoutMs, {QStringLiteral("exec_cxt.periodic.type: ExtTrigExecutionContext")});
    QVERIFY(ticked);
    // Its activation's cycle and its three ticks; then one from here.
    QTRY_VERIFY2_WITH_TIMEOUT(printed(ticked).contains(QLatin1String("cycle 4\n")), qPrintable(printed(ticked)),
                              runTimeoutMs);
    QVERIFY(tick(QStringLiteral("PyTicked0.rtc")));
    QTRY_VERIFY2_WITH_TIMEOUT(printed(ticked).contains(QLatin1String("cycle 5\n")), qPrintable(printed(ticked)),
                              runTimeoutMs);
    QVERIFY2(!printed(ticked).contains(QLatin1String("cycle 6\n")), qPrintable(printed(ticked)));
    m_live.stop(ticked);
}

void TestPythonExamples::pythonComponentInSlaveOfItsOwn()
{
    // PyScaler.py in a slave started for it (manager_name), fed by the master's built-in ConsoleIn.
    const QString manager = m_host.managerPath();
    QVERIFY(rtctlSucceeds({"mgr", manager, "create", "PyScaler?instance_name=SlaveScaler&manager_name=pyslave", "create",
                           "ConsoleIn?instance_name=SlaveFeed", "create", "ConsoleOut?instance_name=SlaveSink"}));
    const qint64 pid = slavePid(QStringLiteral("pyslave"));
    QVERIFY(pid > 0);
    QVERIFY(pid != m_manager->processId());
    QVERIFY(rtctlSucceeds({"con", "SlaveFeed.rtc:out", "SlaveScaler.rtc:in"}));
    QVERIFY(rtctlSucceeds({"con", "SlaveScaler.rtc:out", "SlaveSink.rtc:in"}));
    QVERIFY(rtctlSucceeds({"act", "SlaveSink.rtc", "SlaveScaler.rtc", "SlaveFeed.rtc"}));
    QTRY_VERIFY_WITH_TIMEOUT(m_host.status(m_orb, QStringLiteral("SlaveSink.rtc"), "received_count").toInt() > 0,
                             runTimeoutMs);
    const QList<qint64> values = LiveTest::integers(m_host.status(m_orb, QStringLiteral("SlaveSink.rtc"), "received_values"));
    QVERIFY(!values.isEmpty() && values.first() % 1000 == 0);

    // The slave's end takes its Python component with it; the master serves on.
    QCOMPARE(::kill(pid_t(pid), SIGKILL), 0);
    const auto listed = [&] {
        const RtctlResult list = m_host.run({"mgr", manager, "list"});
        return list.code == 0 ? list.out : QString();
    };
    QTRY_VERIFY_WITH_TIMEOUT(listed().contains(QLatin1String("SlaveFeed")) && !listed().contains(QLatin1String("SlaveScaler")),
                             runTimeoutMs);
    QVERIFY(m_host.run({"cat", "SlaveScaler.rtc"}).code != 0);
    QCOMPARE(m_manager->state(), QProcess::Running);
    QCOMPARE(m_host.state(QStringLiteral("SlaveFeed.rtc")), QStringLiteral("Active"));
    // And makes another slave for the next such request.
    QVERIFY(rtctlSucceeds({"mgr", manager, "create", "PyScaler?instance_name=SlaveScaler2&manager_name=pyslave"}));
    QVERIFY(slavePid(QStringLiteral("pyslave")) > 0);
    QVERIFY(rtctlSucceeds({"deact", "SlaveFeed.rtc"}));
}

void TestPythonExamples::autoControlRunsUnchanged()
{
    const QString script = example(QStringLiteral("AutoControl/AutoControl.py"));
    if (script.isEmpty())
        QSKIP(NoPythonCorpus);
    QProcess *control = m_scripts.start(script, {QStringLiteral("AutoControl0.rtc")}, runTimeoutMs);
    QVERIFY(control);
    QVERIFY(rtctlSucceeds({"act", "AutoControl0.rtc"}));
    QProcess *print = startRtctl({"print", "-n", "4", "AutoControl0.rtc:vel"});
    QVERIFY(print);
    // Range samples until the printer has its four: an obstacle at 20 (within distance_to_env, 40)
    // turns on the spot, one at 50 goes straight at velocity 80.
    const auto printed4 = [&] {
        if (print->state() == QProcess::NotRunning)
            return true;
        m_host.run({"inject", "AutoControl0.rtc:sens", "[10,10,10,20]", "[10,10,10,50]"});
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(printed4(), runTimeoutMs);
    const QString velocities = printed(print);
    QVERIFY2(velocities.contains(QLatin1String("data=[80, -80]")), qPrintable(velocities));
    QVERIFY2(velocities.contains(QLatin1String("data=[80, 80]")), qPrintable(velocities));
    QVERIFY(rtctlSucceeds({"deact", "AutoControl0.rtc"}));
    m_live.stop(control);
}

void TestPythonExamples::throughputRunsUnchanged()
{
    const QString script = example(QStringLiteral("Throughput/Throughput_py.py"));
    if (script.isEmpty())
        QSKIP(NoPythonCorpus);
    // It writes its measurements into the working folder.
    const QString folder = QDir::currentPath();
    QVERIFY(QDir::setCurrent(m_work.path()));
    // The example's rtc.conf connects its OutPort to its InPort (preconnect, in OpenRTM-aist 1.x's form)
    // and activates it; its settings after, with sizes up to 300 floats, five samples each, and little pause.
    // It may run to its end before a name server listing could see it: no name is waited for.
    QProcess *throughput = m_scripts.start(script, {}, runTimeoutMs,
        exampleConf(QStringLiteral("Throughput/rtc.conf"))
            + QStringList{QStringLiteral("example.Throughput_py.conf.default.datatype: float"),
                          QStringLiteral("example.Throughput_py.conf.default.filesuffix: -samecomp"),
                          QStringLiteral("example.Throughput_py.conf.default.maxsize: 300"),
                          QStringLiteral("example.Throughput_py.conf.default.maxsample: 5"),
                          QStringLiteral("example.Throughput_py.conf.default.sleep_time: 0.01"),
                          // OpenRTM-aist's default: the program ends with its last component.
                          QStringLiteral("manager.shutdown_on_nortcs: YES")});
    QVERIFY(QDir::setCurrent(folder));
    QVERIFY(throughput);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(throughput).contains(QLatin1String("Exiting\n")), qPrintable(printed(throughput).right(2000)),
                              runTimeoutMs);
    // The connector's profile that its listener printed (named by its rtc.conf line), and a line per
    // size sent (1, 2, 5, …, 100).
    QVERIFY2(printed(throughput).contains(QLatin1String(
                 "Profile::name:        Throughput_py0.out:Throughput_py0.in(dataflow_type=push&interface_type=corba_cdr)\n")),
             qPrintable(printed(throughput).left(2000)));
    QFile measurements(m_work.filePath(QStringLiteral("float-corba_cdr-samecomp.dat")));
    QTRY_VERIFY_WITH_TIMEOUT(measurements.exists(), runTimeoutMs);
    const auto sizes = [&measurements] {
        QList<int> found;
        if (!measurements.open(QIODevice::ReadOnly | QIODevice::Text))
            return found;
        for (const QByteArray &line : measurements.readAll().split('\n')) {
            const QList<QByteArray> fields = line.split('\t');
            if (fields.size() == 6 && !line.startsWith('#') && fields.first() != "size[byte]")
                found.append(fields.first().toInt());
        }
        measurements.close();
        return found;
    };
    // After the last size (200; 500 is past maxsize) it sends one element, which makes the receiving
    // side write that size's line and exit() the component from a thread of its own: the program ends.
    QVERIFY(LiveTest::waitForExit(throughput, runTimeoutMs));
    QVERIFY(measurements.open(QIODevice::ReadOnly | QIODevice::Text));
    const QByteArray text = measurements.readAll();
    measurements.close();
    QVERIFY2(sizes() == (QList<int>{1, 2, 5, 10, 20, 50, 100, 200}), text.constData());
    // (The connection rtc.conf makes names no data type: OpenRTM-aist's tools add it, a preconnect does not.)
    QVERIFY2(text.contains("# - interface_type: corba_cdr\n") && text.contains("# - dataflow_type: push\n"), text.constData());
}

void TestPythonExamples::staticFsmRunsUnchanged_data()
{
    QTest::addColumn<bool>("asItsRtcConfSays");
    QTest::newRow("two programs connected with rtctl") << false;
    // As the example is meant to run: Inputbutton.py with the example's rtc.conf, which preloads
    // Microwave.py, creates a Microwave, connects each button's OutPort to its event port (named
    // by fsm_event_name) and activates both.
    QTest::newRow("one program, as its rtc.conf says") << true;
}

void TestPythonExamples::staticFsmRunsUnchanged()
{
    QFETCH(bool, asItsRtcConfSays);
    // (Its Microwave_pyfsm.py names a module it does not import, MicrowaveFsm: it cannot run anywhere.)
    const QString script = example(QStringLiteral("StaticFsm/Microwave.py"));
    if (script.isEmpty())
        QSKIP(NoPythonCorpus);
    QProcess *oven = nullptr;
    QProcess *buttons = nullptr;
    if (asItsRtcConfSays) {
        oven = buttons = m_scripts.start(example(QStringLiteral("StaticFsm/Inputbutton.py")),
                                         {QStringLiteral("Inputbutton0.rtc"), QStringLiteral("Microwave0.rtc")},
                                         runTimeoutMs, exampleConf(QStringLiteral("StaticFsm/rtc.conf")));
        QVERIFY(buttons);
    } else {
        oven = m_scripts.start(script, {QStringLiteral("Microwave0.rtc")}, runTimeoutMs);
        QVERIFY(oven);
        buttons = m_scripts.start(example(QStringLiteral("StaticFsm/Inputbutton.py")), {QStringLiteral("Inputbutton0.rtc")},
                                  runTimeoutMs);
        QVERIFY(buttons);
        // The example's rtc.conf by hand: each button's OutPort to the event port, named by fsm_event_name.
        for (const char *event : {"open", "close", "minute", "start", "stop", "tick"})
            QVERIFY(rtctlSucceeds({"con", QStringLiteral("Inputbutton0.rtc:") + event, "Microwave0.rtc:event", "-p",
                                   QStringLiteral("fsm_event_name=") + event}));
        QVERIFY(rtctlSucceeds({"act", "Microwave0.rtc", "Inputbutton0.rtc"}));
    }
    // What the states print as the machine goes through them: the door opened while cooking and
    // closed again goes back to cooking (Operational's deep history).
    const QStringList steps{QStringLiteral("  Microwave ready"), QStringLiteral(" Timer set to  3  minutes"),
                            QStringLiteral("  Heating on"), QStringLiteral("  Clock tick"),
                            QStringLiteral(" Timer set to  2  minutes"), QStringLiteral("  Heating off"),
                            QStringLiteral("  Microwave opened"), QStringLiteral("  Microwave closed"),
                            QStringLiteral("  Heating on"), QStringLiteral("  Clock tick"),
                            QStringLiteral(" Timer set to  1  minutes"), QStringLiteral("  Clock tick"),
                            QStringLiteral("  Finished"), QStringLiteral("  Heating off"),
                            QStringLiteral("  Microwave ready")};
    const auto lines = [&] {
        if (oven == buttons) {
            // One program: the buttons' menu and the machine's lines come from two threads and
            // interleave, so what is compared is the order in which the machine's texts appear.
            QStringList found;
            const QString text = printed(oven);
            for (qsizetype at = 0;;) {
                qsizetype first = -1;
                QString which;
                for (const QString &step : steps) {
                    const QString words = step.section(QLatin1String("  "), 0, 0, QString::SectionSkipEmpty);
                    const qsizetype position = text.indexOf(words, at);
                    if (position >= 0 && (first < 0 || position < first)) {
                        first = position;
                        which = words;
                    }
                }
                if (first < 0)
                    return found;
                found.append(which);
                at = first + which.size();
            }
        }
        QStringList found = printed(oven).split(QLatin1Char('\n'));
        found.removeIf([&steps](const QString &line) { return !steps.contains(line); });
        return found;
    };
    const auto expected = [&](int shown) {
        QStringList texts = steps.mid(0, shown);
        if (oven == buttons) {
            for (QString &text : texts)
                text = text.section(QLatin1String("  "), 0, 0, QString::SectionSkipEmpty);
        }
        return texts;
    };
    // One button at a time, each after the machine has shown what the one before did: the buttons
    // are ports of their own, so events sent at once could arrive in another order.
    const std::pair<const char *, int> presses[] = {{"", 1},       {"minute 3", 2}, {"start", 3}, {"tick", 5},
                                                    {"open", 7},   {"close", 9},    {"tick", 11}, {"tick", 15}};
    for (const auto &[press, shown] : presses) {
        if (*press)
            buttons->write(QByteArray(press) + '\n');
        QTRY_VERIFY2_WITH_TIMEOUT(lines() == expected(shown), qPrintable(printed(oven).right(1500)), runTimeoutMs);
    }
    QVERIFY(rtctlSucceeds({"deact", "Inputbutton0.rtc", "Microwave0.rtc"}));
    m_live.stop(buttons);
    if (oven != buttons)
        m_live.stop(oven);
}

void TestPythonExamples::serializerExampleRunsUnchanged_data()
{
    // The example's serializer modules, preloaded as its rtc_*_serializer.conf files say, into the
    // process of ConsoleInShort (TimedShort OutPort) or of ConsoleOutDouble (TimedDouble InPort); the
    // connection's marshaling types name them. What arrives is a TimedDouble either way.
    QTest::addColumn<QString>("sourceModules");
    QTest::addColumn<QString>("sinkModules");
    QTest::addColumn<QString>("outportMarshaling");
    QTest::addColumn<QString>("inportMarshaling");
    QTest::newRow("InPort's deserializer") << QString() << QStringLiteral("ShortToDoubleDeserializer")
                                           << QStringLiteral("cdr") << QStringLiteral("cdr:RTC/TimedShort:RTC/TimedDouble");
    QTest::newRow("OutPort's serializer") << QStringLiteral("ShortToDoubleSerializer") << QString()
                                          << QStringLiteral("cdr:RTC/TimedDouble:RTC/TimedShort") << QStringLiteral("cdr");
    QTest::newRow("both: short to long to double")
        << QStringLiteral("ShortToLongSerializer") << QStringLiteral("LongToDoubleDeserializer")
        << QStringLiteral("cdr:RTC/TimedLong:RTC/TimedShort") << QStringLiteral("cdr:RTC/TimedLong:RTC/TimedDouble");
    QTest::newRow("one serializer, both sides") << QStringLiteral("TestSerializer") << QStringLiteral("TestSerializer")
                                                << QStringLiteral("test:dummydata") << QStringLiteral("test:dummydata");
}

void TestPythonExamples::serializerExampleRunsUnchanged()
{
    // Here in two programs, the test connecting the ports with the marshaling types of the row.
    QFETCH(QString, sourceModules);
    QFETCH(QString, sinkModules);
    QFETCH(QString, outportMarshaling);
    QFETCH(QString, inportMarshaling);
    const QString in = example(QStringLiteral("Serializer/ConsoleInShort.py"));
    if (in.isEmpty())
        QSKIP(NoPythonCorpus);
    const QString folder = QFileInfo(in).absolutePath();
    auto preload = [&folder](const QString &modules) {
        return modules.isEmpty() ? QStringList()
                                 : QStringList{QStringLiteral("manager.modules.load_path: ") + folder,
                                               QStringLiteral("manager.modules.preload: ") + modules};
    };
    QProcess *sink = m_scripts.start(example(QStringLiteral("Serializer/ConsoleOutDouble.py")), {QStringLiteral("ConsoleOutDouble0.rtc")},
                                     runTimeoutMs, preload(sinkModules));
    QVERIFY(sink);
    QProcess *source = m_scripts.start(in, {QStringLiteral("ConsoleInShort0.rtc")}, runTimeoutMs, preload(sourceModules));
    QVERIFY(source);
    QVERIFY(m_host.connectThroughOrb(m_orb, QStringLiteral("ConsoleInShort0.rtc:out"), QStringLiteral("ConsoleOutDouble0.rtc:in"),
                              {{"dataport.data_type", "IDL:RTC/TimedShort:1.0"},
                               {"dataport.interface_type", "corba_cdr"},
                               {"dataport.dataflow_type", "push"},
                               {"dataport.subscription_type", "flush"},
                               {"dataport.inport.marshaling_type", inportMarshaling},
                               {"dataport.outport.marshaling_type", outportMarshaling}}));
    QVERIFY(rtctlSucceeds({"act", "ConsoleOutDouble0.rtc", "ConsoleInShort0.rtc"}));
    QByteArray numbers;
    for (int i = 1; i <= 200; ++i)
        numbers += QByteArray::number(i * 3 - 300) + '\n';
    source->write(numbers);
    // What arrives is a TimedDouble: its value printed as a float (and the short's value, so negative
    // numbers too), with the time stamp the source set.
    const QRegularExpression received(QStringLiteral("Received:  RTC\\.TimedDouble\\(tm=RTC\\.Time\\(sec=[1-9]\\d*, nsec=\\d+\\), "
                                                     "data=(-?\\d+)\\.0\\)\nReceived:  -?\\d+\\.0\n"));
    QTRY_VERIFY2_WITH_TIMEOUT(received.globalMatch(printed(sink)).hasNext(), qPrintable(printed(sink).right(3000)), runTimeoutMs);
    const int value = received.match(printed(sink)).captured(1).toInt();
    QVERIFY2(value >= -297 && value <= 300 && value % 3 == 0, qPrintable(printed(sink).right(3000)));
    // Its InPort's data listeners are given the converted value too; the source's, the short.
    QVERIFY2(QRegularExpression(QStringLiteral("ON_RECEIVED\n.*\n.*\nData: +-?\\d+\\.0\n")).match(printed(sink)).hasMatch(),
             qPrintable(printed(sink).right(3000)));
    QVERIFY2(QRegularExpression(QStringLiteral("ON_SEND\n.*\n.*\nData: +-?\\d+\n")).match(printed(source)).hasMatch(),
             qPrintable(printed(source).right(2000)));
    QVERIFY(rtctlSucceeds({"deact", "ConsoleInShort0.rtc", "ConsoleOutDouble0.rtc"}));
    // A source that has read every number (a slow test) waits in onExecute for the next one, and
    // neither its deactivation nor its exit can end that wait: one more line lets it return.
    source->write("0\n");
    // Their exits take their names out of the name server (the next row's programs register them
    // again), which killed programs would leave there.
    QVERIFY(rtctlSucceeds({"exit", "ConsoleInShort0.rtc"}));
    QVERIFY(rtctlSucceeds({"exit", "ConsoleOutDouble0.rtc"}));
    const auto registered = [this] {
        const QString listed = m_host.run({QStringLiteral("ls")}).out;
        return listed.contains(QLatin1String("ConsoleInShort0")) || listed.contains(QLatin1String("ConsoleOutDouble0"));
    };
    QTRY_VERIFY_WITH_TIMEOUT(!registered(), runTimeoutMs);
    m_live.stop(source);
    m_live.stop(sink);
}

void TestPythonExamples::serializerExampleRunsAsItsRtcConfSays()
{
    // `python3 ConsoleInShort.py -f rtc.conf` in the example's folder: its rtc.conf preloads the
    // consumer and the deserializer, creates a ConsoleOutDouble, connects its InPort to the
    // ConsoleInShort's OutPort with the connector properties written there and activates both.
    const QString in = example(QStringLiteral("Serializer/ConsoleInShort.py"));
    if (in.isEmpty())
        QSKIP(NoPythonCorpus);
    QProcess *program = m_scripts.start(in, {QStringLiteral("ConsoleInShort0.rtc"), QStringLiteral("ConsoleOutDouble0.rtc")},
                                        runTimeoutMs, exampleConf(QStringLiteral("Serializer/rtc.conf")));
    QVERIFY(program);
    QByteArray numbers;
    for (int i = 1; i <= 200; ++i)
        numbers += QByteArray::number(i * 3 - 300) + '\n';
    program->write(numbers);
    const QRegularExpression received(
        QStringLiteral("Received:  RTC\\.TimedDouble\\(tm=RTC\\.Time\\(sec=[1-9]\\d*, nsec=\\d+\\), data=(-?\\d+)\\.0\\)"));
    QTRY_VERIFY2_WITH_TIMEOUT(received.match(printed(program)).hasMatch(), qPrintable(printed(program).right(3000)),
                              runTimeoutMs);
    const int value = received.match(printed(program)).captured(1).toInt();
    QVERIFY2(value >= -297 && value <= 300 && value % 3 == 0, qPrintable(printed(program).right(3000)));
    // The connector is named by its line of rtc.conf.
    QVERIFY2(printed(program).contains(QLatin1String(
                 "Profile::name:   ConsoleOutDouble0.in?port=ConsoleInShort0.out&inport.marshaling_type=cdr:RTC/TimedShort:"
                 "RTC/TimedDouble&outport.marshaling_type=cdr\n")),
             qPrintable(printed(program).left(3000)));
    m_live.stop(program);
}

void TestPythonExamples::cspExamplesRunUnchanged_data()
{
    // Each program runs as its .bat file starts it: one process whose rtc.conf creates the other
    // components, connects them by CSP channels and activates them. What their log prints (at ERROR
    // level, on standard output) is counted: the `expected` lines each appear several times, and no
    // more than the channels let through (the slow readers bound the fast writers).
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("conf");
    QTest::addColumn<QStringList>("instances");
    QTest::addColumn<QStringList>("expected");
    QTest::addColumn<QString>("fast");
    QTest::addColumn<QString>("slow");
    // DataOut2 writes at 1000 Hz into DataIn2's rendezvous channel (buffer.length 0), read once a second.
    QTest::newRow("CSPSample") << "CSPSample/DataOut2.py"
                               << "CSPSample/rtc_samplecsp.conf" << QStringList{"DataOut20.rtc", "DataIn20.rtc"}
                               << QStringList{"writedata", "dataread: RTC.TimedLong(tm=RTC.Time(sec=0, nsec=0), data=1)"}
                               << QString() << QString();
    // One writer selects among three rendezvous readers reading 10, 2 and 1 times a second.
    QTest::newRow("CSPSelectSample out1in3")
        << "CSPSelectSample/DataOut_port3.py"
        << "CSPSelectSample/rtc_out1in3.conf"
        << QStringList{"DataOut_port30.rtc", "DataIn0.rtc", "DataIn1.rtc", "DataIn2.rtc"}
        << QStringList{"datawrite: out1", "datawrite: out2", "datawrite: out3"} << "datawrite: out1"
        << "datawrite: out3";
    // Three writers (5, 2 and 1 times a second) into one reader's buffered ports.
    QTest::newRow("CSPSelectSample out3in1")
        << "CSPSelectSample/DataIn_port3.py"
        << "CSPSelectSample/rtc_out3in1.conf"
        << QStringList{"DataIn_port30.rtc", "DataOut0.rtc", "DataOut1.rtc", "DataOut2.rtc"}
        << QStringList{"dataread: in1", "dataread: in2", "dataread: in3"} << "dataread: in1"
        << "dataread: in3";
    // One component selecting among three InPorts and three OutPorts.
    QTest::newRow("CSPSelectSample out3in3")
        << "CSPSelectSample/DataInOut.py"
        << "CSPSelectSample/rtc_out3in3.conf"
        << QStringList{"DataInOut0.rtc", "DataIn0.rtc", "DataOut2.rtc"}
        << QStringList{"dataread: in1", "dataread: in3", "datawrite: out1", "datawrite: out3"} << "datawrite: out1"
        << "datawrite: out3";
}

void TestPythonExamples::cspExamplesRunUnchanged()
{
    QFETCH(QString, program);
    QFETCH(QString, conf);
    QFETCH(QStringList, instances);
    QFETCH(QStringList, expected);
    QFETCH(QString, fast);
    QFETCH(QString, slow);
    const QString script = example(program);
    if (script.isEmpty())
        QSKIP(NoPythonCorpus);
    QProcess *process = m_scripts.start(script, instances, runTimeoutMs, exampleConf(conf, true));
    QVERIFY(process);
    const auto times = [&](const QString &line) { return printed(process).count(line); };
    const auto enough = [&] {
        return std::all_of(expected.begin(), expected.end(), [&](const QString &line) { return times(line) >= 3; });
    };
    QTRY_VERIFY2_WITH_TIMEOUT(enough(), qPrintable(printed(process).right(3000)), runTimeoutMs);
    const QString log = printed(process);
    m_live.stop(process);
    QVERIFY2(!log.contains(QLatin1String("Traceback")), qPrintable(log.left(3000)));
    if (!fast.isEmpty())
        QVERIFY2(log.count(fast) > log.count(slow), qPrintable(log.right(3000)));
    // A channel passes a sample only when its reader takes one: at 1000 Hz without that, the
    // fastest writer would have printed thousands of lines by now.
    const qsizetype lines = log.count(QLatin1Char('\n'));
    QVERIFY2(lines < 400, qPrintable(QStringLiteral("%1 lines:\n").arg(lines) + log.right(3000)));
    if (program == QLatin1String("CSPSample/DataOut2.py")) {
        // Each write ends when the reader takes its sample.
        const qsizetype writes = log.count(QLatin1String("writedata"));
        const qsizetype reads = log.count(QLatin1String("dataread"));
        QVERIFY2(qAbs(writes - reads) <= 2, qPrintable(QStringLiteral("%1 writes, %2 reads").arg(writes).arg(reads)));
    }
}

void TestPythonExamples::cspFsmExampleFailsAsOnOpenRtm()
{
    // CSPStaticFsmSample's Microwave makes its CSPMachine with two arguments where the class takes
    // three (OpenRTM-aist-Python 2.1 too): the component fails to initialize with Python's message,
    // and the program goes on without it, as on OpenRTM-aist-Python.
    const QString script = example(QStringLiteral("CSPStaticFsmSample/Inputbutton.py"));
    if (script.isEmpty())
        QSKIP(NoPythonCorpus);
    m_live.setErrorsRead(true);
    QProcess *process = m_scripts.start(script, {QStringLiteral("Inputbutton0.rtc")}, runTimeoutMs,
                                        exampleConf(QStringLiteral("CSPStaticFsmSample/rtc.conf")));
    m_live.setErrorsRead(false);
    QVERIFY(process);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(process).contains(QLatin1String(
                                  "CSPMachine.__init__() missing 1 required positional argument: 'cspmgr'")),
                              qPrintable(printed(process).right(3000)), runTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(printed(process).contains(QLatin1String("Microwave0 failed to initialize")),
                              qPrintable(printed(process).right(3000)), runTimeoutMs);
    m_live.stop(process);
}

void TestPythonExamples::dataTypesConvert_data()
{
    QTest::addColumn<QString>("script");
    QTest::newRow("wide characters") << QStringLiteral("widechars");
    QTest::newRow("unions") << QStringLiteral("unions");
    QTest::newRow("object references") << QStringLiteral("references");
    QTest::newRow("ring buffer") << QStringLiteral("ringbuffer");
    QTest::newRow("static FSM") << QStringLiteral("staticfsm");
    QTest::newRow("anys and NVLists") << QStringLiteral("anys");
    QTest::newRow("straight to CDR") << QStringLiteral("directcdr");
    QTest::newRow("serializers") << QStringLiteral("serializers");
    QTest::newRow("CSP channels") << QStringLiteral("csp");
    QTest::newRow("port settings") << QStringLiteral("portsettings");
    QTest::newRow("shutdown") << QStringLiteral("shutdown");
}

void TestPythonExamples::dataTypesConvert()
{
    // Each script checks its values and prints "<script>: ok".
    QFETCH(QString, script);
    QProcess python;
    python.setProcessEnvironment(m_scripts.environment());
    python.start(QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE), {LiveTest::pythonTestScript(script + QStringLiteral(".py"))});
    QVERIFY(python.waitForFinished(runTimeoutMs));
    const QString output = QString::fromLocal8Bit(python.readAllStandardOutput() + python.readAllStandardError());
    QVERIFY2(python.exitStatus() == QProcess::NormalExit && python.exitCode() == 0, qPrintable(output));
    QVERIFY2(output.contains(script + QStringLiteral(": ok")), qPrintable(output));
}

QTEST_GUILESS_MAIN(TestPythonExamples)
#include "tst_pythonexamples.moc"
