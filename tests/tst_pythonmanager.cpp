// SPDX-License-Identifier: MIT
// Python component modules inside rtmanager (the interpreter embedded on the first .py module,
// python/embed): loaded by `rtctl mgr load` or by creating their type, and listed among the
// loadable modules; exchanging data both ways with C++ built-ins of the same manager; a callback's
// exception taking its component to Error with the traceback in the manager's log while the
// manager serves on; broken modules refused with file and line; OpenRTM-aist-Python's
// ConsoleOut.py unchanged from the shared corpus (skipped with the reason when it is absent); and
// a manager without the Python plugin.
#include "hostrtctl.h"
#include "nvlist.h"
#include "pythonsanitizer.h"

#include <Manager.hh>

#include <QtTest>

namespace {

constexpr int runTimeoutMs = 30 * 1000;
const QString hostName = QStringLiteral("pymgr");

QString testModule(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/python/")) + name;
}

/// The 1-based number of the first line of @p file containing @p marker; 0 when none does.
int lineOf(const QString &file, const QString &marker)
{
    QFile source(file);
    if (!source.open(QIODevice::ReadOnly | QIODevice::Text))
        return 0;
    const QStringList lines = QString::fromUtf8(source.readAll()).split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size(); ++i) {
        if (lines.at(i).contains(marker))
            return i + 1;
    }
    return 0;
}

} // namespace

class TestPythonManager : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void loadableModulesListPythonModules();
    void moduleExchangesDataWithBuiltins();
    void creatingATypeLoadsItsModule();
    void callbackExceptionMovesComponentToError();
    void brokenModulesAreRefused();
    void managerWithoutPythonRefusesClearly();
    void corpusConsoleOutLoadsUnchanged();

private:
    QString logged() const;
    /// What the manager printed on standard output so far.
    QString printed() { return m_printed.of(m_manager); }
    /// Loads module @p file into the manager with rtctl: its exit code and output.
    RtctlResult load(const QString &file) const;

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
    LiveTest::HostRtctl m_host{m_live, hostName};
    QProcess *m_manager = nullptr;
    CORBA::ORB_var m_orb;
    LiveTest::PrintedOutput m_printed;
};

QString TestPythonManager::logged() const
{
    QFile file(m_work.filePath(QStringLiteral("manager.log")));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

RtctlResult TestPythonManager::load(const QString &file) const
{
    return m_host.run({QStringLiteral("mgr"), m_host.managerPath(), QStringLiteral("load"), file});
}

void TestPythonManager::initTestCase()
{
    QVERIFY(m_work.isValid());
    QVERIFY2(QFileInfo::exists(RTSTUDIO_PYTHON_PLUGIN), "build rtpymodules first");
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    // The managers (and the module profiles they and Build start) embed Python.
    LiveTest::startChildrenWithoutLeakChecks();
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    // The modules of the test data are in the manager's load path, found by their file names.
    m_manager = m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), hostName,
                                        {QStringLiteral("manager.modules.load_path=") + RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/python"),
                                         QStringLiteral("logger.enable=YES"),
                                         QStringLiteral("logger.file_name=") + m_work.filePath(QStringLiteral("manager.log"))},
                                        &error);
    QVERIFY2(m_manager, qPrintable(error));
}

void TestPythonManager::loadableModulesListPythonModules()
{
    // Each .py module is profiled as a .so one is (in a process of its own): one entry per type.
    CORBA::Object_var object = m_orb->string_to_object(
        qPrintable(QStringLiteral("corbaname::%1#%2.host_cxt/manager.mgr").arg(m_live.namingServer(), hostName)));
    RTM::Manager_var manager = RTM::Manager::_narrow(object);
    QVERIFY(!CORBA::is_nil(manager));
    RTM::ModuleProfileList_var modules = manager->get_loadable_modules();
    QMap<QString, QString> languages;
    for (CORBA::ULong i = 0; i < modules->length(); ++i) {
        const SDOPackage::NVList &module = modules[i].properties;
        languages.insert(nv(module, "module_file_name") + QLatin1Char(':') + nv(module, "implementation_id"),
                         nv(module, "language"));
    }
    QCOMPARE(languages.value(QStringLiteral("PyScaler.py:PyScaler")), QStringLiteral("Python"));
    QCOMPARE(languages.value(QStringLiteral("PyFaulty.py:PyFaulty")), QStringLiteral("Python"));
    // A module that does not load holds no component type it could list.
    for (const QString &key : languages.keys())
        QVERIFY2(!key.startsWith(QLatin1String("PyBadSyntax.py")), qPrintable(key));
}

void TestPythonManager::moduleExchangesDataWithBuiltins()
{
    const RtctlResult loaded = load(QStringLiteral("PyScaler.py"));
    QVERIFY2(loaded.code == 0, qPrintable(loaded.out + loaded.err));
    // PyScalerInit created its component in this manager, named and registered by it.
    QTRY_COMPARE_WITH_TIMEOUT(m_host.state(QStringLiteral("PyScaler0.rtc")), QStringLiteral("Inactive"), runTimeoutMs);
    QVERIFY(m_host.succeeds({"mgr", m_host.managerPath(), "create", "ConsoleIn?instance_name=Feed", "create",
                             "ConsoleOut?instance_name=Sink"}));
    QVERIFY(m_host.succeeds({"con", "Feed.rtc:out", "PyScaler0.rtc:in"}));
    QVERIFY(m_host.succeeds({"con", "PyScaler0.rtc:out", "Sink.rtc:in"}));
    for (const char *component : {"Sink.rtc", "PyScaler0.rtc", "Feed.rtc"})
        QVERIFY(m_host.succeeds({"act", component}));

    // C++ → Python → C++: the C++ sink gets the C++ source's counts times 1000.
    QTRY_VERIFY_WITH_TIMEOUT(m_host.status(m_orb, QStringLiteral("Sink.rtc"), "received_count").toInt() >= 3,
                             runTimeoutMs);
    const QList<qint64> values = LiveTest::integers(m_host.status(m_orb, QStringLiteral("Sink.rtc"), "received_values"));
    QVERIFY(!values.isEmpty());
    for (const qint64 value : values)
        QVERIFY2(value > 0 && value % 1000 == 0, qPrintable(QString::number(value)));
    // What the component printed is the manager's output.
    QTRY_VERIFY_WITH_TIMEOUT(printed().contains(QStringLiteral("scaled %1\n").arg(values.last() / 1000)), runTimeoutMs);
    const RtctlResult list = m_host.run({"mgr", m_host.managerPath(), "list"});
    QVERIFY2(list.out.contains(testModule(QStringLiteral("PyScaler.py"))), qPrintable(list.out));
}

void TestPythonManager::creatingATypeLoadsItsModule()
{
    // As for `<Type>.so`: the type nobody registered is looked for as `<Type>.py` in the load path.
    const RtctlResult created = m_host.run({"mgr", m_host.managerPath(), "create", "PyRegistered?instance_name=ByTypeName"});
    QVERIFY2(created.code == 0, qPrintable(created.out + created.err));
    // Python interleaves the writes of a print() (its text, then its end) with other threads' writes:
    // PyScaler prints on, so the line's end is not looked for.
    QTRY_VERIFY2_WITH_TIMEOUT(printed().contains(QLatin1String("PyRegistered initialized as ByTypeName")),
                              qPrintable(created.out + created.err + printed().right(600)), runTimeoutMs);
    const RtctlResult list = m_host.run({"mgr", m_host.managerPath(), "list"});
    QVERIFY2(list.out.contains(testModule(QStringLiteral("PyRegistered.py"))), qPrintable(list.out));
}

void TestPythonManager::callbackExceptionMovesComponentToError()
{
    const RtctlResult loaded = load(QStringLiteral("PyFaulty.py"));
    QVERIFY2(loaded.code == 0, qPrintable(loaded.out + loaded.err));
    QTRY_COMPARE_WITH_TIMEOUT(m_host.state(QStringLiteral("PyFaulty0.rtc")), QStringLiteral("Inactive"), runTimeoutMs);
    QVERIFY(m_host.succeeds({"act", "PyFaulty0.rtc"}));
    QTRY_COMPARE_WITH_TIMEOUT(m_host.state(QStringLiteral("PyFaulty0.rtc")), QStringLiteral("Error"), runTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(logged().contains(QLatin1String("RuntimeError: faulty on purpose")), runTimeoutMs);
    QVERIFY2(logged().contains(QLatin1String("PyFaulty0: onExecute() raised an exception")), qPrintable(logged()));
    QVERIFY2(logged().contains(QLatin1String("Traceback (most recent call last)")), qPrintable(logged()));
    // The manager serves on: the other components run, new ones are made, the faulty one recovers.
    QCOMPARE(m_manager->state(), QProcess::Running);
    const int before = m_host.status(m_orb, QStringLiteral("Sink.rtc"), "received_count").toInt();
    QTRY_VERIFY_WITH_TIMEOUT(m_host.status(m_orb, QStringLiteral("Sink.rtc"), "received_count").toInt() > before,
                             runTimeoutMs);
    QVERIFY(m_host.succeeds({"mgr", m_host.managerPath(), "create", "ConsoleOut?instance_name=AfterFault"}));
    QVERIFY(m_host.succeeds({"reset", "PyFaulty0.rtc"}));
    QTRY_VERIFY_WITH_TIMEOUT(printed().contains(QLatin1String("PyFaulty reset")), runTimeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(m_host.state(QStringLiteral("PyFaulty0.rtc")), QStringLiteral("Inactive"), runTimeoutMs);
}

void TestPythonManager::brokenModulesAreRefused()
{
    const struct
    {
        const char *module;
        const char *error;
    } broken[] = {{"PyBadSyntax.py", "SyntaxError"},
                  {"PyRaisesOnLoad.py", "RuntimeError: module fails on purpose"},
                  {"PyInitRaises.py", "RuntimeError: init fails on purpose"}};
    for (const auto &module : broken) {
        const QString file = testModule(QString::fromLatin1(module.module));
        const int line = lineOf(file, QStringLiteral("refused here"));
        QVERIFY(line > 0);
        const RtctlResult refused = load(QString::fromLatin1(module.module));
        QVERIFY2(refused.code != 0, qPrintable(refused.out));
        const QString where = QStringLiteral("%1:%2: %3").arg(file).arg(line).arg(QString::fromLatin1(module.error));
        QVERIFY2(refused.err.contains(where), qPrintable(where + QStringLiteral(" in: ") + refused.err));
    }
    const RtctlResult list = m_host.run({"mgr", m_host.managerPath(), "list"});
    // Nothing of them is loaded, not even the type the raising init function registered.
    QVERIFY2(list.code == 0 && !list.out.contains(QLatin1String("PyBadSyntax")), qPrintable(list.out + list.err));
    QVERIFY2(!list.out.contains(QLatin1String("PyInitRaises")), qPrintable(list.out));
    QCOMPARE(m_manager->state(), QProcess::Running);
}

void TestPythonManager::managerWithoutPythonRefusesClearly()
{
    // As on a machine without python3: the plugin cannot be opened, the manager starts and serves,
    // and a Python module is refused with the reason.
    QString error;
    const QString host = QStringLiteral("nopython");
    QProcess *manager = m_live.startHostManager(
        RTMANAGER_PATH, LiveTest::freePort(), host,
        {QStringLiteral("manager.modules.Python.plugin=") + m_work.filePath(QStringLiteral("absent.so"))}, &error);
    QVERIFY2(manager, qPrintable(error));
    const LiveTest::HostRtctl rtctl(m_live, host);
    const RtctlResult refused = rtctl.run({"mgr", rtctl.managerPath(), "load", testModule(QStringLiteral("PyScaler.py"))});
    QVERIFY(refused.code != 0);
    QVERIFY2(refused.err.contains(QLatin1String("Python modules need the Python support")), qPrintable(refused.err));
    QVERIFY(rtctl.succeeds({"mgr", rtctl.managerPath(), "create", "ConsoleIn?instance_name=StillServing"}));
    m_live.stop(manager);
}

void TestPythonManager::corpusConsoleOutLoadsUnchanged()
{
    const QString module = RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-python-examples/SimpleIO/ConsoleOut.py");
    if (!QFileInfo::exists(module))
        QSKIP("the OpenRTM-aist-Python examples corpus (shared/conformance/openrtm-python-examples beside the "
              "project) is absent");
    // ConsoleOutInit registers the type; it takes the place of the built-in of the same name.
    const RtctlResult loaded = load(module);
    QVERIFY2(loaded.code == 0, qPrintable(loaded.out + loaded.err));
    QVERIFY(m_host.succeeds({"mgr", m_host.managerPath(), "create", "ConsoleOut?instance_name=PyConsoleOut"}));
    QVERIFY(m_host.succeeds({"con", "Feed.rtc:out", "PyConsoleOut.rtc:in"}));
    QVERIFY(m_host.succeeds({"act", "PyConsoleOut.rtc"}));
    // The example prints what it receives from the C++ source ("Received: " only when it read a
    // sample; the number is a print() argument of its own, which other threads' writes may separate).
    QTRY_VERIFY2_WITH_TIMEOUT(printed().contains(QLatin1String("Received: ")), qPrintable(printed().right(600)),
                              runTimeoutMs);
    // The name of the listener's kind: the example prints it as one of several arguments, which
    // Python may interleave with what its other threads print.
    QVERIFY2(printed().contains(QLatin1String("ON_CONNECT")), qPrintable(printed().right(600)));
}

QTEST_GUILESS_MAIN(TestPythonManager)
#include "tst_pythonmanager.moc"
