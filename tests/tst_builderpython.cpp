// SPDX-License-Identifier: MIT
// The Builder's Build and Run in Manager for a generated Python project (data/builderpython/
// PyRelay.xml: In and Out ports of several data types, configuration parameters with lists):
// generate → Build (the module loaded into a manager process of its own; `rtctl build` alike) →
// Run in Manager into a live rtmanager → data flows both ways with C++ built-ins and a
// configuration change reaches the bound variables. A module that does not load fails Build at
// its file and line; a project's own IDL is compiled first, and a project with service ports
// (data/pythonidl/PyService.xml) calls and answers C++ built-ins. Every data type the Builder
// offers crosses a pair of Python ports in the manager.
#include "buildcontroller.h"
#include "hostrtctl.h"
#include "pythonscripts.h"
#include "pythonsanitizer.h"
#include "runcontroller.h"
#include "typecatalog.h"

#include <QAction>
#include <QSettings>
#include <QSignalSpy>
#include <QtTest>

using Builder::BuildController;
using Builder::GenerateOutcome;
using Builder::RunController;

namespace {

constexpr int runTimeoutMs = 30 * 1000;
const QString hostName = QStringLiteral("pybuilder");
const QString componentName = QStringLiteral("PyRelay");

/// The user's code in onExecute: relays `in` scaled by `gain` to `out`, with the offsets to
/// `samples` and as a float to `level`; sums `shorts`; prints the configuration when it changes.
const char userCode[] = R"(    def onExecute(self, ec_id):
        while self._inIn.isNew():
            value = self._inIn.read().data
            self._d_out.data = value * self._gain[0]
            self._outOut.write()
            self._d_samples.data = [value + offset for offset in self._offsets[0]]
            self._samplesOut.write()
            self._d_level.data = float(value)
            self._levelOut.write()
        while self._shortsIn.isNew():
            print("shorts %d" % sum(self._shortsIn.read().data))
        config = "gain=%d offsets=%r tags=%r label=%s" % (self._gain[0], self._offsets[0], self._tags[0], self._label[0])
        if config != getattr(self, "_printed", None):
            self._printed = config
            print(config)
        return RTC.RTC_OK
)";

const char generatedExecute[] = "    def onExecute(self, ec_id):\n        return RTC.RTC_OK\n";

/// The user's code in the test component's onExecute: counts up on its OutPort `in` and prints what
/// comes back on its InPort `out`.
const char testCode[] = R"(    def onExecute(self, ec_id):
        self._count = getattr(self, "_count", 0) + 1
        self._d_in.data = self._count
        self._inOut.write()
        while self._outIn.isNew():
            print("test received %d" % self._outIn.read().data)
        return RTC.RTC_OK
)";

} // namespace

class TestBuilderPython : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void generatedProjectBuildsRunsAndIsConfigured();
    void moduleThatDoesNotLoadFailsBuildAtItsLine();
    void ownIdlIsCompiledFirst();
    void serviceProjectBuildsAndCallsReturn();
    void everyBuilderDataTypeCrossesPorts_data();
    void everyBuilderDataTypeCrossesPorts();
    void testComponentExercisesTheComponent();

private:
    /// Generates PyRelay's Python project into a new folder below the test's; empty on failure.
    QString generate(const QString &name, const QStringList &options = {});
    /// Replaces @p from by @p to in the project's module (or in its file @p file).
    static bool edit(const QString &project, const QByteArray &from, const QByteArray &to,
                     const QString &file = componentName + QStringLiteral(".py"));
    static GenerateOutcome buildAndWait(BuildController &build);
    bool connectAndActivate();
    /// Loads data/python/PyAllTypes.py, with m_dataTypes as its list, into the manager; activates it.
    bool loadAllTypes();
    /// The integers the C++ sink received last.
    QList<qint64> sinkValues() const { return LiveTest::integers(m_host.status(m_orb, QStringLiteral("Sink.rtc"), "received_values")); }

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
    LiveTest::HostRtctl m_host{m_live, hostName};
    QProcess *m_manager = nullptr;
    quint16 m_port = 0;
    CORBA::ORB_var m_orb;
    LiveTest::PrintedOutput m_printed;
    QStringList m_dataTypes; ///< the Builder's data types
    bool m_allTypesLoaded = false;
};

void TestBuilderPython::initTestCase()
{
    QVERIFY(m_work.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_work.filePath(QStringLiteral("settings")));
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_builderpython"));
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    // The managers (and the module profiles they and Build start) embed Python.
    LiveTest::startChildrenWithoutLeakChecks();
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_port = LiveTest::freePort();
    m_manager = m_live.startHostManager(RTMANAGER_PATH, m_port, hostName, {}, &error);
    QVERIFY2(m_manager, qPrintable(error));
}

QString TestBuilderPython::generate(const QString &name, const QStringList &options)
{
    const QString project = m_work.filePath(name);
    const RtctlResult generated = runRtctl(
        QStringList{"gen", RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builderpython/PyRelay.xml"), "--lang", "python", "-o", project}
        + options);
    if (generated.code != 0) {
        qWarning().noquote() << generated.out << generated.err;
        return {};
    }
    return project;
}

bool TestBuilderPython::edit(const QString &project, const QByteArray &from, const QByteArray &to, const QString &file)
{
    QFile module(QDir(project).filePath(file));
    if (!module.open(QIODevice::ReadOnly))
        return false;
    QByteArray text = module.readAll();
    module.close();
    if (!text.contains(from) || !module.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    return module.write(text.replace(from, to)) > 0;
}

GenerateOutcome TestBuilderPython::buildAndWait(BuildController &build)
{
    QSignalSpy reported(&build, &BuildController::reported);
    if (!build.build() && reported.isEmpty())
        return {};
    if (reported.isEmpty() && !reported.wait(runTimeoutMs))
        return {};
    return reported.at(0).at(0).value<GenerateOutcome>();
}

bool TestBuilderPython::connectAndActivate()
{
    const QString manager = m_host.managerPath();
    if (!m_host.succeeds({"mgr", manager, "create", "ConsoleIn?instance_name=Feed", "create",
                          "ConsoleOut?instance_name=Sink", "create", "SeqOut?instance_name=Shorts", "create",
                          "SeqIn?instance_name=SeqSink"}))
        return false;
    const QList<QStringList> connections{{"Feed.rtc:out", "PyRelay0.rtc:in"},
                                         {"Shorts.rtc:ShortSeq", "PyRelay0.rtc:shorts"},
                                         {"PyRelay0.rtc:out", "Sink.rtc:in"},
                                         {"PyRelay0.rtc:samples", "SeqSink.rtc:DoubleSeq"},
                                         {"PyRelay0.rtc:level", "SeqSink.rtc:Float"}};
    for (const QStringList &ports : connections) {
        if (!m_host.succeeds(QStringList{"con"} + ports))
            return false;
    }
    for (const char *component : {"Sink.rtc", "SeqSink.rtc", "PyRelay0.rtc", "Feed.rtc", "Shorts.rtc"}) {
        if (!m_host.succeeds({"act", component}))
            return false;
    }
    return true;
}

void TestBuilderPython::generatedProjectBuildsRunsAndIsConfigured()
{
    const QString project = generate(QStringLiteral("relay"));
    QVERIFY(!project.isEmpty());
    QVERIFY(edit(project, generatedExecute, userCode));

    // Build: nothing to compile (standard data types only); the module loads and registers its type.
    BuildController build(nullptr, [&project] { return project; });
    QVERIFY(build.canBuild());
    const GenerateOutcome built = buildAndWait(build);
    QVERIFY2(built.succeeded, qPrintable(built.summary));
    QVERIFY2(built.summary.contains(QLatin1String("registers PyRelay")), qPrintable(built.summary));
    // rtctl build does the same.
    const RtctlResult rtctlBuilt = runRtctl({"build", project});
    QVERIFY2(rtctlBuilt.code == 0, qPrintable(rtctlBuilt.out + rtctlBuilt.err));
    QVERIFY2(rtctlBuilt.out.contains(QLatin1String("registers PyRelay")), qPrintable(rtctlBuilt.out));

    // Run in Manager loads the module itself into the running manager.
    RunController run([&project] { return project; }, [] { return componentName; });
    QCOMPARE(run.modulePath(), QDir(project).filePath(QStringLiteral("PyRelay.py")));
    QVERIFY(run.runAction()->isEnabled());
    QSignalSpy finished(&run, &RunController::runFinished);
    QVERIFY(run.runInManager(QStringLiteral("127.0.0.1:%1").arg(m_port)));
    QVERIFY(finished.wait(run.timeout() + 5000));
    const auto result = finished.at(0).at(0).value<Builder::ModuleRunResult>();
    QVERIFY2(result.ok, qPrintable(result.error));
    QCOMPARE(result.instanceName, QStringLiteral("PyRelay0"));

    QVERIFY(connectAndActivate());
    // C++ → Python → C++ on each port, with the defaults of the configuration.
    QTRY_VERIFY_WITH_TIMEOUT(sinkValues().size() >= 3, runTimeoutMs);
    for (const qint64 value : sinkValues())
        QVERIFY2(value > 0 && value % 2 == 0, qPrintable(QString::number(value)));
    for (const char *count : {"DoubleSeq_count", "Float_count"})
        QTRY_VERIFY2_WITH_TIMEOUT(m_host.status(m_orb, QStringLiteral("SeqSink.rtc"), count).toInt() > 0, count,
                                  runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(m_printed.of(m_manager).contains(QLatin1String("\nshorts ")), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(m_printed.of(m_manager).contains(QLatin1String(
                                 "gain=2 offsets=[0.5, 1.5] tags=['first', 'second'] label=relay\n")),
                             runTimeoutMs);

    // A change of the configuration reaches the bound variables, lists included.
    for (const QStringList &change : {QStringList{"gain", "1000"}, QStringList{"offsets", "3,4.25"},
                                      QStringList{"tags", "x,y,z"}, QStringList{"label", "changed"}})
        QVERIFY(m_host.succeeds(QStringList{"conf", "PyRelay0.rtc", "set"} + change));
    QTRY_VERIFY_WITH_TIMEOUT(m_printed.of(m_manager).contains(QLatin1String(
                                 "gain=1000 offsets=[3.0, 4.25] tags=['x', 'y', 'z'] label=changed\n")),
                             runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!sinkValues().isEmpty() && sinkValues().last() % 1000 == 0, runTimeoutMs);
    for (const char *component : {"Feed.rtc", "Shorts.rtc", "PyRelay0.rtc"})
        QVERIFY(m_host.succeeds({"deact", component}));
}

void TestBuilderPython::moduleThatDoesNotLoadFailsBuildAtItsLine()
{
    const QString project = generate(QStringLiteral("broken"));
    QVERIFY(!project.isEmpty());
    QVERIFY(edit(project, generatedExecute, "    def onExecute(self, ec_id):\n        return RTC.RTC_OK +\n"));
    BuildController build(nullptr, [&project] { return project; });
    const GenerateOutcome outcome = buildAndWait(build);
    QVERIFY(!outcome.succeeded);
    QVERIFY2(outcome.summary.contains(QLatin1String("Checking")), qPrintable(outcome.summary));
    QCOMPARE(outcome.diagnostics.size(), 1);
    const Profile::Diagnostic problem = outcome.diagnostics.first();
    QCOMPARE(problem.file, QDir(project).filePath(QStringLiteral("PyRelay.py")));
    QFile module(problem.file);
    QVERIFY(module.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = module.readAll().split('\n');
    QVERIFY(problem.line > 0 && problem.line <= lines.size());
    QVERIFY2(lines.at(problem.line - 1).contains("return RTC.RTC_OK +"), lines.at(problem.line - 1).constData());
    QVERIFY2(problem.message.contains(QLatin1String("SyntaxError")), qPrintable(problem.message));
}

void TestBuilderPython::ownIdlIsCompiledFirst()
{
    // The project's idlcompile.sh runs before the module is checked (here a stand-in for the
    // IDL compiler, which leaves a mark), and its failure fails the build.
    const QString project = generate(QStringLiteral("withidl"));
    QVERIFY(!project.isEmpty());
    QVERIFY(QDir(project).mkpath(QStringLiteral("idl")));
    QFile idl(QDir(project).filePath(QStringLiteral("idl/Extra.idl")));
    QVERIFY(idl.open(QIODevice::WriteOnly) && idl.write("module Extra { struct Point { double x; }; };\n") > 0);
    idl.close();
    const auto writeScript = [&project](const QByteArray &body) {
        QFile script(QDir(project).filePath(QStringLiteral("idlcompile.sh")));
        return script.open(QIODevice::WriteOnly | QIODevice::Truncate) && script.write("#!/bin/sh\n" + body) > 0;
    };
    QVERIFY(writeScript("cd \"$(dirname \"$0\")\" && echo compiled > compiled.txt\n"));
    BuildController build(nullptr, [&project] { return project; });
    const GenerateOutcome built = buildAndWait(build);
    QVERIFY2(built.succeeded, qPrintable(built.summary));
    QVERIFY(QFileInfo::exists(QDir(project).filePath(QStringLiteral("compiled.txt"))));

    QVERIFY(writeScript("exit 3\n"));
    const GenerateOutcome failed = buildAndWait(build);
    QVERIFY(!failed.succeeded);
    QVERIFY2(failed.summary.contains(QLatin1String("Compiling the IDL")), qPrintable(failed.summary));
}

void TestBuilderPython::serviceProjectBuildsAndCallsReturn()
{
    // A project with a provided and a required SimpleService::MyService and its own IDL: Build
    // compiles the IDL with rtctl idl, and in rtmanager its servant answers the C++ built-in
    // consumer while its consumer calls the C++ built-in provider, all in one process.
    const QString project = m_work.filePath(QStringLiteral("service"));
    const RtctlResult generated = runRtctl(
        {"gen", RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/pythonidl/PyService.xml"), "--lang", "python", "-o", project});
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QVERIFY(edit(project,
                 "        # TODO: implement echo; it returns result\n"
                 "        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)",
                 "        return 'generated says ' + msg", QStringLiteral("SimpleService_idl_example.py")));
    QVERIFY(edit(project, "    def onExecute(self, ec_id):\n        return RTC.RTC_OK",
                 "    def onExecute(self, ec_id):\n"
                 "        remote = self._remote._ptr()\n"
                 "        if remote is not None and not getattr(self, '_called', False):\n"
                 "            self._called = True\n"
                 "            print('generated consumer:', remote.echo('from generated'), flush=True)\n"
                 "        return RTC.RTC_OK",
                 QStringLiteral("PyService.py")));
    BuildController build(nullptr, [&project] { return project; });
    const GenerateOutcome built = buildAndWait(build);
    QVERIFY2(built.succeeded, qPrintable(built.summary));
    QVERIFY(QFileInfo::exists(QDir(project).filePath(QStringLiteral("SimpleService/__init__.py"))));

    const QString manager = m_host.managerPath();
    QVERIFY(m_host.succeeds({"mgr", manager, "load", project + QStringLiteral("/PyService.py"), "create", "PyService"}));
    QVERIFY(m_host.succeeds({"mgr", manager, "create", "MyServiceProvider?instance_name=ServiceProvider", "create",
                             "MyServiceConsumer?instance_name=ServiceConsumer"}));
    QVERIFY(m_host.succeeds({"con", "ServiceConsumer.rtc:MyService", "PyService0.rtc:Provided"}));
    QVERIFY(m_host.succeeds({"con", "PyService0.rtc:Required", "ServiceProvider.rtc:MyService"}));
    for (const char *component : {"ServiceProvider.rtc", "PyService0.rtc", "ServiceConsumer.rtc"})
        QVERIFY(m_host.succeeds({"act", component}));
    QTRY_VERIFY_WITH_TIMEOUT(m_printed.of(m_manager).contains(QLatin1String("generated consumer: from generated")),
                             runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(m_host.status(m_orb, QStringLiteral("ServiceConsumer.rtc"), "echo_count").toInt() >= 1,
                             runTimeoutMs);
    QVERIFY2(m_host.status(m_orb, QStringLiteral("ServiceConsumer.rtc"), "last_reply")
                 .startsWith(QLatin1String("generated says echo ")),
             qPrintable(m_host.status(m_orb, QStringLiteral("ServiceConsumer.rtc"), "last_reply")));
    QVERIFY(m_host.succeeds({"deact", "ServiceConsumer.rtc"}));
}

bool TestBuilderPython::loadAllTypes()
{
    const QString folder = m_work.filePath(QStringLiteral("alltypes"));
    QFile list(folder + QStringLiteral("/types.txt"));
    if (!QDir().mkpath(folder) || !list.open(QIODevice::WriteOnly)
        || list.write((m_dataTypes.join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8()) <= 0)
        return false;
    list.close();
    const QString module = folder + QStringLiteral("/PyAllTypes.py");
    if (!QFile::copy(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/python/PyAllTypes.py"), module))
        return false;
    return m_host.succeeds({"mgr", m_host.managerPath(), "load", module}) && m_host.succeeds({"act", "PyAllTypes0.rtc"});
}

void TestBuilderPython::everyBuilderDataTypeCrossesPorts_data()
{
    // The data types the Builder's port pages offer: every struct of the bundled IDL.
    Builder::TypeCatalog catalog;
    catalog.reload();
    m_dataTypes = catalog.dataTypes();
    QVERIFY2(m_dataTypes.size() > 100, qPrintable(m_dataTypes.join(QLatin1Char(' '))));
    QTest::addColumn<int>("number");
    QTest::addColumn<QString>("type");
    for (int i = 0; i < m_dataTypes.size(); ++i)
        QTest::newRow(qPrintable(m_dataTypes.at(i))) << i << m_dataTypes.at(i);
}

void TestBuilderPython::everyBuilderDataTypeCrossesPorts()
{
    QFETCH(int, number);
    QFETCH(QString, type);
    if (!m_allTypesLoaded) {
        m_allTypesLoaded = true;
        QVERIFY(loadAllTypes());
    }
    // A Python component sends the type's value (as the Builder's projects make it) from its
    // OutPort to its InPort through the runtime, as CDR, and says whether what arrived is equal;
    // its lines may meet other components' output.
    const auto said = [this, &type](const QString &what) {
        const QRegularExpression line(QStringLiteral("(?<![\\w:])%1: %2").arg(QRegularExpression::escape(type), what));
        return line.match(m_printed.of(m_manager)).hasMatch();
    };
    if (!said(QStringLiteral("unsupported"))) {
        QVERIFY(m_host.succeeds({"con", QStringLiteral("PyAllTypes0.rtc:o%1").arg(number),
                                 QStringLiteral("PyAllTypes0.rtc:i%1").arg(number)}));
        QTRY_VERIFY_WITH_TIMEOUT(said(QStringLiteral("(crossed|changed)")), runTimeoutMs);
    }
    QVERIFY2(said(QStringLiteral("crossed the ports")),
             qPrintable(m_printed.of(m_manager).split(QLatin1Char('\n')).filter(type + QLatin1Char(':')).join(QLatin1Char('\n'))));
}

void TestBuilderPython::testComponentExercisesTheComponent()
{
    // The project's test component, in Python as the project is: the user writes its onExecute,
    // runs it beside the component and connects the two, port to mirrored port.
    const QString project = generate(QStringLiteral("withtest"), {"--test-component"});
    QVERIFY(!project.isEmpty());
    QVERIFY(edit(project, generatedExecute, userCode));
    QVERIFY(edit(project, generatedExecute, testCode, QStringLiteral("test/PyRelayTest.py")));
    // Both as programs, under a naming context of their own (the manager holds a PyRelay0 already).
    const QString context = QStringLiteral("pytestcomponent");
    const LiveTest::HostRtctl host(m_live, context);
    const LiveTest::PythonScripts scripts(m_live, host, context, QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE),
                                          RTSTUDIO_PYTHON_PATH, QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD),
                                          m_work.path());
    QProcess *component = scripts.start(QDir(project).filePath(QStringLiteral("PyRelay.py")), {"PyRelay0.rtc"}, runTimeoutMs);
    QVERIFY(component);
    QProcess *test = scripts.start(QDir(project).filePath(QStringLiteral("test/PyRelayTest.py")), {"PyRelayTest0.rtc"},
                                   runTimeoutMs);
    QVERIFY(test);
    QVERIFY(host.succeeds({"con", "PyRelayTest0.rtc:in", "PyRelay0.rtc:in"}));
    QVERIFY(host.succeeds({"con", "PyRelay0.rtc:out", "PyRelayTest0.rtc:out"}));
    QVERIFY(host.succeeds({"act", "PyRelay0.rtc", "PyRelayTest0.rtc"}));
    // What the test component sent comes back scaled by the component's gain (2).
    const QRegularExpression received(QStringLiteral("test received (\\d+)\n"));
    QTRY_VERIFY2_WITH_TIMEOUT(m_printed.of(test).count(received) >= 3, qPrintable(m_printed.of(test).right(2000)),
                              runTimeoutMs);
    for (const QRegularExpressionMatch &match : received.globalMatch(m_printed.of(test))) {
        const qint64 value = match.captured(1).toLongLong();
        QVERIFY2(value > 0 && value % 2 == 0, qPrintable(match.captured(0)));
    }
    QVERIFY(host.succeeds({"deact", "PyRelayTest0.rtc", "PyRelay0.rtc"}));
    m_live.stop(test);
    m_live.stop(component);
}

QTEST_MAIN(TestBuilderPython)
#include "tst_builderpython.moc"
