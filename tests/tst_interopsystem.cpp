// SPDX-License-Identifier: MIT
// One name server shared by OpenRTM-aist 2.x — its example components as their own programs and
// an rtcd2 master that creates more in a slave — and rtmanager with its built-in twins of the same
// examples. rtctl drives all of them: every command it has against OpenRTM-aist's side, data of
// every basic type from each SeqOut to the other side's SeqIn (and over every data flow: push with
// flush, new and periodic, and pull), configuration sets written and activated, service calls in
// both directions and a mixed system saved, torn down and restored.
//
// Needs the prefix of an OpenRTM-aist installation (CMake cache variable RTSTUDIO_OPENRTM_PREFIX,
// ctest label "interop"); without one the test is skipped.
#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace {

const QString openRtmPrefix = QStringLiteral(RTSTUDIO_OPENRTM_PREFIX);

/**
 * Where each rtctl command is exercised against OpenRTM-aist. `test` names the test function
 * that runs it (and must see it succeed at least once); nullptr marks a command that works on
 * files or on RT Studio's own runtime only, with the reason in `check`.
 */
struct CommandCoverage
{
    const char *command;
    const char *test;
    const char *check;
};

const CommandCoverage commandTable[] = {
    {"profile", nullptr, "offline: checks and converts profile files"},
    {"gen", nullptr, "offline: writes a project (built against OpenRTM-aist by tst_interopbuild)"},
    {"build", nullptr,
     "offline: builds a generated project (against OpenRTM-aist in tst_interopbuild)"},
    {"local", nullptr, "RT Studio's own name server and manager on fixed ports; no peer involved"},
    {"idl", nullptr, "offline: Python modules of IDL for RT Studio's Python runtime"},
    {"package", nullptr, "offline: a Debian package of a built project"},
    {"repo", nullptr, "offline: a Debian repository of component packages"},
    {"node", nullptr, "RT Studio's install service on rtmanager; OpenRTM-aist's managers have none"},
    {"deploy", nullptr, "installs through RT Studio's install service, which OpenRTM-aist's managers lack"},
    {"undeploy", nullptr, "the same"},
    {"plan", nullptr, "offline: places components on nodes from their facts"},
    {"tls", nullptr, "certificates that OpenRTM-aist's SSLTransport accepts: tst_interoptls"},
    {"ls", "everyRtctlCommand",
     "-l: states and port counts of OpenRTM's components; rtcd2's manager"},
    {"cat", "everyRtctlCommand", "SeqIn0's ten InPorts; rtcd2's manager profile"},
    {"find", "everyRtctlCommand", "by name pattern and by type (rtcd2's manager)"},
    {"pwd", "everyRtctlCommand", "prints the directory cd gave"},
    {"cd", "everyRtctlCommand", "into OpenRTM's context and rtcd2's manager; refuses a component"},
    {"act", "everyRtctlCommand", "OpenRTM's SeqIn0 and SeqOut0 read back Active"},
    {"deact", "everyRtctlCommand", "the same read back Inactive"},
    {"reset", "everyRtctlCommand", "OpenRTM's ConsoleIn0 from Error (input 666) to Inactive"},
    {"exit", "everyRtctlCommand",
     "a component rtcd2 created is gone from the manager and the names"},
    {"con", "everyRtctlCommand", "the connector is listed on both OpenRTM ports"},
    {"dis", "everyRtctlCommand", "the connector is gone from both"},
    {"print", "everyRtctlCommand", "samples of OpenRTM's SeqOut0"},
    {"inject", "everyRtctlCommand", "a value OpenRTM's SeqIn0 then shows"},
    {"log", "everyRtctlCommand", "records OpenRTM's SeqOut0, plays into OpenRTM's SeqIn0"},
    {"conf", "configuration", "set, get and act on OpenRTM's ConfigSample0; it prints the values"},
    {"mgr", "everyRtctlCommand",
     "rtcd2: create in a slave and several in the master, list, load, unload"},
    {"cryo", "mixedSystemRoundTrip", "saves OpenRTM's and rtmanager's components with connectors"},
    {"teardown", "mixedSystemRoundTrip", "the saved connectors are gone"},
    {"stop", "mixedSystemRoundTrip", "every saved component reads back Inactive"},
    {"resurrect", "mixedSystemRoundTrip", "the connectors are back"},
    {"start", "mixedSystemRoundTrip", "every saved component reads back Active"},
    {"diff", "mixedSystemRoundTrip", "differences after teardown, none after the restore"},
};

/// The ten data ports of the SeqOut / SeqIn examples, OpenRTM-aist's and rtmanager's alike.
const QStringList seqPorts {"Octet",    "Short",    "Long",    "Float",    "Double",
                            "OctetSeq", "ShortSeq", "LongSeq", "FloatSeq", "DoubleSeq"};

/**
 * One table OpenRTM-aist's SeqIn prints each cycle: a header naming the basic types, the latest
 * value read on each basic-type port and, one row per element, the latest sequences (NaN where a
 * sequence has ended).
 */
struct SeqInTable
{
    QStringList columns;
    QList<double> basic;
    QList<QList<double>> rows;
};

double cell(const QString &text)
{
    return text == QLatin1String("-") ? std::nan("") : text.toDouble();
}

/// The tables in @p output that are complete (the next one has begun).
QList<SeqInTable> seqInTables(QByteArray output)
{
    // The program moves the cursor up to redraw in place; only the lines matter here.
    output.replace("\x1b[A", "").replace('\r', "");
    static const QRegularExpression header(
        QStringLiteral("^\\s*((?:[A-Z][a-z]+\\s+){4}[A-Z][a-z]+)\\s*$"));
    static const QRegularExpression basicRow(
        QStringLiteral("^\\s*(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(-?\\d+)\\["));
    static const QRegularExpression sequenceRow(
        QStringLiteral("^\\s*\\d+:\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(-|-?\\d+)"));
    QList<SeqInTable> tables;
    std::optional<SeqInTable> current;
    for (const QByteArray &line : output.split('\n')) {
        const QString text = QString::fromLatin1(line);
        if (const auto m = header.match(text); m.hasMatch()) {
            if (current)
                tables.append(*current);
            current
                = SeqInTable {m.captured(1).split(QLatin1Char(' '), Qt::SkipEmptyParts), {}, {}};
        } else if (const auto b = basicRow.match(text);
                   current && current->basic.isEmpty() && b.hasMatch()) {
            for (int i = 1; i <= 5; ++i)
                current->basic.append(cell(b.captured(i)));
        } else if (const auto s = sequenceRow.match(text); current && s.hasMatch()) {
            QList<double> row;
            for (int i = 1; i <= 5; ++i)
                row.append(cell(s.captured(i)));
            current->rows.append(row);
        }
    }
    return tables;
}

/// Whether column @p column of @p table holds what rtmanager's SeqOut writes: a counter in the
/// basic port, ten consecutive values (wrapping with the type) in the sequence.
bool holdsCounter(const SeqInTable &table, int column)
{
    if (table.basic.size() != 5 || table.rows.size() < 10 || table.basic[column] == 0)
        return false;
    const QString type = table.columns.value(column);
    const double wrap = type == QLatin1String("Octet") ? 256
        : type == QLatin1String("Short")               ? 65536
                                                       : 0;
    for (int i = 0; i < 10; ++i) {
        const double step = table.rows[i][column] - table.rows[0][column];
        if (std::isnan(step) || (wrap ? std::fmod(step + wrap, wrap) : step) != i)
            return false;
    }
    return true;
}

} // namespace

class TestInteropSystem : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void everyRtctlCommand();
    void dataBothWays();
    void everyDataFlow_data();
    void everyDataFlow();
    void configuration();
    void serviceCalls();
    void mixedSystemRoundTrip();
    void commandTableMatchesHelp();

private:
    void treeCommands();
    void dataCommands();
    void resetCommand();
    void managerCommands();
    RtctlResult rtctl(const QStringList &arguments, const QString &cwd = QString());
    QString openRtm(const QString &name) const { return "openrtm.host_cxt/" + name; }
    QString ours(const QString &name) const { return "ours.host_cxt/" + name; }
    QString ourStatus(const QString &component, const QString &name) const;
    /// rtctl's exit code of @p command (act, deact) on both sides' SeqOut0 and SeqIn0.
    int onSeqComponents(const QString &command);
    QProcess *startExample(const QString &name, QString *error);
    bool startMaster(QString *error);
    QString state(const QString &path);
    QByteArray newOutput(QProcess *process);
    bool waitForOutput(QProcess *process, const QRegularExpression &pattern, int timeoutMs,
                       const QByteArray &poke = QByteArray());
    bool waitForSeqInTable(const std::function<bool(const SeqInTable &)> &wanted, int timeoutMs);
    void checkConfiguration(
        const QString &component,
        const std::function<bool(const QString &, const QString &, const QString &)> &inEffect);

    LiveTest::LiveSystem m_live;
    QTemporaryDir m_work;
    CORBA::ORB_var m_orb;
    QString m_server;
    quint16 m_masterPort = 0;
    QProcess *m_master = nullptr;
    QHash<QString, QProcess *> m_examples; // OpenRTM-aist's programs by component name
    QSet<QString> m_succeeded; // rtctl commands that exited 0 at least once
};

RtctlResult TestInteropSystem::rtctl(const QStringList &arguments, const QString &cwd)
{
    const QString directory = cwd.isEmpty() ? "/" + m_server : cwd;
    const RtctlResult result = runRtctlAt(directory, arguments);
    // Counted for the command table when OpenRTM-aist's side took part: its contexts, the
    // master's endpoint or a saved mixed system.
    const QString all = arguments.join(QLatin1Char(' ')) + QLatin1Char(' ') + directory;
    const bool openRtmInvolved = all.contains(QLatin1String("openrtm.host_cxt"))
        || all.contains(QLatin1String("rtcd.host_cxt"))
        || all.contains(QStringLiteral(":%1").arg(m_masterPort))
        || all.contains(QLatin1String(".rtsys"));
    if (result.code == 0 && !arguments.isEmpty() && openRtmInvolved)
        m_succeeded.insert(arguments.first());
    return result;
}

int TestInteropSystem::onSeqComponents(const QString &command)
{
    return rtctl({command, openRtm("SeqOut0.rtc"), openRtm("SeqIn0.rtc"), ours("SeqOut0.rtc"),
                  ours("SeqIn0.rtc")})
        .code;
}

QString TestInteropSystem::ourStatus(const QString &component, const QString &name) const
{
    const QString name_
        = QStringLiteral("corbaname::%1#ours.host_cxt/%2.rtc").arg(m_server, component);
    return LiveTest::componentStatus(m_orb, name_, name.toUtf8().constData());
}

QProcess *TestInteropSystem::startExample(const QString &name, QString *error)
{
    // Twenty cycles a second keep the examples' console output small.
    QStringList options {QStringLiteral("exec_cxt.periodic.rate:20")};
    // ConfigSample's sets other than the default come from the example's configuration file.
    if (name == QLatin1String("ConfigSample"))
        options << "example.ConfigSample.config_file:" + openRtmPrefix
                + "/share/openrtm-2.1/components/c++/examples/configsample.conf";
    QProcess *process = m_live.startOpenRtmExample(openRtmPrefix, name + "Comp", QStringLiteral("openrtm"), error, options);
    m_examples.insert(name, process);
    return process;
}

bool TestInteropSystem::startMaster(QString *error)
{
    m_masterPort = LiveTest::freePort();
    const QString examples = openRtmPrefix + "/share/openrtm-2.1/components/c++/examples/rtc";
    m_master = m_live.startRtcdMaster(openRtmPrefix, m_work.filePath("master.conf"), m_masterPort, "rtcd",
                                      {"manager.modules.load_path: " + examples,
                                       "manager.modules.preload: ConsoleOut.so"},
                                      error);
    return m_master != nullptr;
}

QString TestInteropSystem::state(const QString &path)
{
    const QJsonArray entries = rtctl({"ls", "-l", "--json", path}).json().array();
    return entries.isEmpty() ? QString() : entries.first()["state"].toString();
}

QByteArray TestInteropSystem::newOutput(QProcess *process)
{
    return process->readAllStandardOutput();
}

bool TestInteropSystem::waitForOutput(QProcess *process, const QRegularExpression &pattern,
                                      int timeoutMs, const QByteArray &poke)
{
    QByteArray output;
    const QDeadlineTimer deadline(timeoutMs);
    while (!pattern.match(QString::fromLatin1(output)).hasMatch()) {
        if (deadline.hasExpired()) {
            // The examples redraw with cursor movements; shown as they are they would hide the
            // text.
            output.replace("\x1b[A", "").replace('\r', "");
            qWarning("no %s in: %s", qPrintable(pattern.pattern()), output.right(1500).constData());
            return false;
        }
        if (!poke.isEmpty())
            process->write(poke);
        process->waitForReadyRead(200);
        output += process->readAllStandardOutput();
    }
    return true;
}

bool TestInteropSystem::waitForSeqInTable(const std::function<bool(const SeqInTable &)> &wanted,
                                          int timeoutMs)
{
    QProcess *seqIn = m_examples.value("SeqIn");
    QByteArray output;
    const QDeadlineTimer deadline(timeoutMs);
    while (!deadline.hasExpired()) {
        seqIn->waitForReadyRead(200);
        output += seqIn->readAllStandardOutput();
        const QList<SeqInTable> tables = seqInTables(output);
        if (std::any_of(tables.begin(), tables.end(), wanted))
            return true;
        // Keep the tail: a table is a few hundred bytes.
        if (output.size() > 65536)
            output = output.right(8192);
    }
    return false;
}

void TestInteropSystem::initTestCase()
{
    if (openRtmPrefix.isEmpty() || !QFile::exists(openRtmPrefix + "/bin/rtcd2"))
        QSKIP("skipped: no OpenRTM-aist (RTSTUDIO_OPENRTM_PREFIX unset or without bin/rtcd2)");
    LiveTest::useOpenRtm(openRtmPrefix);
    QVERIFY(m_work.isValid());
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_server = m_live.namingServer();
    for (const char *name :
         {"SeqOut", "SeqIn", "ConfigSample", "MyServiceProvider", "MyServiceConsumer", "ConsoleIn"})
        QVERIFY2(startExample(name, &error), qPrintable(error));
    QVERIFY2(startMaster(&error), qPrintable(error));
    // rtmanager's service consumer waits for OpenRTM's provider, which takes ten seconds to echo.
    QVERIFY2(m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), "ours",
                                     {"manager.components.precreate=SeqOut,SeqIn,ConfigSample,"
                                      "MyServiceProvider,MyServiceConsumer",
                                      "corba.call_timeout=20000"},
                                     &error),
             qPrintable(error));
    for (const char *name :
         {"SeqOut", "SeqIn", "ConfigSample", "MyServiceProvider", "MyServiceConsumer", "ConsoleIn"})
        QTRY_VERIFY2_WITH_TIMEOUT(rtctl({"cat", openRtm(name + QStringLiteral("0.rtc"))}).code == 0,
                                  name, 30000);
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "rtcd.host_cxt/manager.mgr"}).code == 0, 30000);
    QCOMPARE(rtctl({"ls", "ours.host_cxt"}).lines().size(), 6);
    m_succeeded.clear();
}

void TestInteropSystem::cleanupTestCase()
{
    m_master = nullptr;
    m_live.stopAll();
    // Its threads must not outlive the test's objects at exit.
    if (!CORBA::is_nil(m_orb))
        m_orb->destroy();
}

// Each command of the table above that names this function succeeds here at least once, and its
// effect is read back.
void TestInteropSystem::everyRtctlCommand()
{
    for (void (TestInteropSystem::*part)() :
         {&TestInteropSystem::treeCommands, &TestInteropSystem::dataCommands,
          &TestInteropSystem::resetCommand, &TestInteropSystem::managerCommands}) {
        (this->*part)();
        if (QTest::currentTestFailed())
            return;
    }
}

// ls, cat, find, cd, pwd: OpenRTM's programs, the master and our manager side by side.
void TestInteropSystem::treeCommands()
{
    const RtctlResult ls = rtctl({"ls", "-l", "openrtm.host_cxt"});
    QCOMPARE(ls.code, 0);
    QVERIFY2(
        ls.out.contains(QRegularExpression("Inactive\\s+10/0\\s+10/0\\s+0/0\\s+0/0\\s+SeqIn0.rtc")),
        qPrintable(ls.out));
    QVERIFY2(ls.out.contains(QRegularExpression(
                 "Inactive\\s+1/0\\s+0/0\\s+0/0\\s+1/0\\s+MyServiceProvider0.rtc")),
             qPrintable(ls.out));
    QCOMPARE(rtctl({"ls", "rtcd.host_cxt"}).lines(), QStringList {"manager.mgr"});

    const RtctlResult cat = rtctl({"cat", openRtm("SeqIn0.rtc")});
    QCOMPARE(cat.code, 0);
    for (const QString &port : seqPorts)
        QVERIFY2(cat.lines().contains("  DataInPort: " + port), qPrintable(port));
    QVERIFY(cat.lines().contains("  Type name      SeqIn"));
    const QJsonObject master
        = rtctl({"cat", "--json", "rtcd.host_cxt/manager.mgr"}).json().object();
    QCOMPARE(master["profile"]["instance_name"].toString(), QString("manager"));

    const RtctlResult found = rtctl({"find", "/" + m_server, "-n", "Seq*.rtc"});
    QCOMPARE(found.code, 0);
    for (const QString &path :
         {openRtm("SeqIn0.rtc"), openRtm("SeqOut0.rtc"), ours("SeqIn0.rtc"), ours("SeqOut0.rtc")})
        QVERIFY2(found.lines().contains("/" + m_server + "/" + path), qPrintable(found.out));
    const RtctlResult managers = rtctl({"find", "/" + m_server + "/rtcd.host_cxt", "-t", "m"});
    QVERIFY2(managers.lines().contains("/" + m_server + "/rtcd.host_cxt/manager.mgr"),
             qPrintable(managers.out));

    const RtctlResult cd = rtctl({"cd", "openrtm.host_cxt"});
    QCOMPARE(cd.code, 0);
    const QString context = "/" + m_server + "/openrtm.host_cxt";
    QCOMPARE(cd.out, "export RTCSH_CWD='" + context + "'\n");
    QCOMPARE(rtctl({"pwd"}, context).out, context + "\n");
    QCOMPARE(rtctl({"cd", "rtcd.host_cxt/manager.mgr"}).code, 0);
    QCOMPARE(rtctl({"cd", "SeqIn0.rtc"}, context).code, 1);
}

// act, print, inject, log, con, dis, deact on OpenRTM's SeqOut and SeqIn.
void TestInteropSystem::dataCommands()
{
    // States, read back through ls.
    QCOMPARE(rtctl({"act", openRtm("SeqIn0.rtc"), openRtm("SeqOut0.rtc")}).code, 0);
    QTRY_COMPARE(state(openRtm("SeqIn0.rtc")), QString("Active"));
    QTRY_COMPARE(state(openRtm("SeqOut0.rtc")), QString("Active"));

    // Data: OpenRTM's SeqOut printed, OpenRTM's SeqIn shows what is injected and played.
    const RtctlResult printed = rtctl({"print", "-n", "2", openRtm("SeqOut0.rtc:Short")});
    QCOMPARE(printed.code, 0);
    QCOMPARE(printed.lines().size(), 2);
    QVERIFY2(
        printed.lines().first().contains(QRegularExpression("^\\[\\d+\\.\\d{9}\\] data=-?\\d+$")),
        qPrintable(printed.out));
    QCOMPARE(rtctl({"inject", openRtm("SeqIn0.rtc:Short"), "4242"}).code, 0);
    QVERIFY(waitForSeqInTable([](const SeqInTable &t) { return t.basic.value(3) == 4242; }, 10000));

    const QString recording = m_work.filePath("seqout.jsonl");
    QCOMPARE(rtctl({"log", "-o", recording, "-n", "3", openRtm("SeqOut0.rtc:Long")}).code, 0);
    QFile file(recording);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> samples = file.readAll().split('\n');
    QCOMPARE(samples.size(), 4); // three lines and the empty rest
    const QJsonObject last = QJsonDocument::fromJson(samples[2]).object();
    QVERIFY2(last["type"].toString().contains("TimedLong"), samples[2].constData());
    const double value = last["value"]["data"].toDouble();
    QCOMPARE(rtctl({"log", "--play", recording, "-r", "50", openRtm("SeqIn0.rtc:Long")}).code, 0);
    QVERIFY(waitForSeqInTable([value](const SeqInTable &t) { return t.basic.value(2) == value; },
                              10000));

    // A connector between two of OpenRTM's ports, seen from both and gone again.
    const RtctlResult con = rtctl(
        {"con", "-n", "interop", openRtm("SeqOut0.rtc:Double"), openRtm("SeqIn0.rtc:Double")});
    QCOMPARE(con.code, 0);
    const QString id = con.out.trimmed();
    for (const QString &port : {openRtm("SeqOut0.rtc:Double"), openRtm("SeqIn0.rtc:Double")}) {
        const QJsonArray connectors = rtctl({"cat", "--json", port}).json()["connectors"].toArray();
        QCOMPARE(connectors.size(), 1);
        QCOMPARE(connectors[0]["id"].toString(), id);
        QCOMPARE(connectors[0]["name"].toString(), QString("interop"));
    }
    // OpenRTM's ports refuse a second connection between them unless the connector allows it
    // (rtmanager's ports do the same: tst_managerruntime), and rtctl names the reason.
    const RtctlResult again
        = rtctl({"con", openRtm("SeqOut0.rtc:Double"), openRtm("SeqIn0.rtc:Double")});
    QCOMPARE(again.code, 1);
    QVERIFY2(again.err.contains(
                 "PRECONDITION_NOT_MET: SeqOut0.Double is already connected to SeqIn0.Double"),
             qPrintable(again.err));
    const RtctlResult allowed
        = rtctl({"con", "-p", "dataport.allow_dup_connection=YES", openRtm("SeqOut0.rtc:Double"),
                 openRtm("SeqIn0.rtc:Double")});
    QCOMPARE(allowed.code, 0);
    QCOMPARE(rtctl({"dis", "-i", allowed.out.trimmed(), openRtm("SeqOut0.rtc:Double")}).code, 0);
    QCOMPARE(rtctl({"dis", openRtm("SeqOut0.rtc:Double"), openRtm("SeqIn0.rtc:Double")}).code, 0);
    for (const QString &port : {openRtm("SeqOut0.rtc:Double"), openRtm("SeqIn0.rtc:Double")})
        QVERIFY(rtctl({"cat", "--json", port}).json()["connectors"].toArray().isEmpty());

    QCOMPARE(rtctl({"deact", openRtm("SeqIn0.rtc"), openRtm("SeqOut0.rtc")}).code, 0);
    QTRY_COMPARE(state(openRtm("SeqIn0.rtc")), QString("Inactive"));
    QTRY_COMPARE(state(openRtm("SeqOut0.rtc")), QString("Inactive"));
}

// reset: OpenRTM's ConsoleIn goes to Error on 666.
void TestInteropSystem::resetCommand()
{
    QCOMPARE(rtctl({"act", openRtm("ConsoleIn0.rtc")}).code, 0);
    m_examples.value("ConsoleIn")->write("666\n");
    QTRY_COMPARE_WITH_TIMEOUT(state(openRtm("ConsoleIn0.rtc")), QString("Error"), 10000);
    QCOMPARE(rtctl({"reset", openRtm("ConsoleIn0.rtc")}).code, 0);
    QTRY_COMPARE_WITH_TIMEOUT(state(openRtm("ConsoleIn0.rtc")), QString("Inactive"), 10000);
}

// mgr and exit: rtcd2 creates in a slave and in the master, loads and unloads; exit removes what it
// created.
void TestInteropSystem::managerCommands()
{
    const QString direct = QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_masterPort);
    const RtctlResult created
        // rtcd2 starts the slave as a new process that profiles every module: slow on a loaded machine.
        = rtctl({"mgr", "--timeout", "20000", direct, "create",
                 "ConsoleOut?instance_name=Made0&manager_name=interopslave", "list"});
    QVERIFY2(created.code == 0, qPrintable(created.err));
    QCOMPARE(created.lines().value(0), QString("Made0"));
    QVERIFY2(created.lines().contains("  Made0  ConsoleOut"), qPrintable(created.out));
    QTRY_VERIFY(rtctl({"ls", "rtcd.host_cxt"}).lines().contains("Made0.rtc"));
    const RtctlResult loaded
        = rtctl({"mgr", "--json", "rtcd.host_cxt/manager.mgr", "load", "ConfigSample.so", "list"});
    QVERIFY2(loaded.code == 0, qPrintable(loaded.err));
    QVERIFY2(loaded.json()["factories"].toArray().contains(QJsonValue("ConfigSample")),
             qPrintable(loaded.out));
    // OpenRTM's manager unloads a module by the path it lists, not by the name it was loaded with.
    QString module;
    for (const QJsonValue &entry : loaded.json()["loadedModules"].toArray()) {
        if (entry["file_path"].toString().endsWith("/ConfigSample.so"))
            module = entry["file_path"].toString();
    }
    QVERIFY2(!module.isEmpty(), qPrintable(loaded.out));
    const RtctlResult unloaded = rtctl({"mgr", direct, "unload", module, "list"});
    QVERIFY2(unloaded.code == 0, qPrintable(unloaded.err));
    QVERIFY2(!unloaded.out.contains("ConfigSample.so"), qPrintable(unloaded.out));

    // A manager's profile holds its configuration's manager.* keys without the prefix, on both
    // sides.
    for (const QString &manager :
         {QStringLiteral("rtcd.host_cxt/manager.mgr"), ours("manager.mgr")}) {
        const QJsonObject profile = rtctl({"cat", "--json", manager}).json()["profile"].toObject();
        for (const char *key :
             {"instance_name", "name", "pid", "is_master", "naming_formats", "modules.load_path"})
            QVERIFY2(profile.contains(key), qPrintable(manager + ": " + key));
        QVERIFY2(!profile.contains("manager.naming_formats"), qPrintable(manager));
    }

    // Several creates the master hosts itself: OpenRTM's manager has no create_components, so
    // rtctl makes them one by one.
    const RtctlResult two = rtctl({"mgr", direct, "create", "ConsoleOut?instance_name=Made1",
                                   "create", "ConsoleOut?instance_name=Made2"});
    QVERIFY2(two.code == 0, qPrintable(two.err));
    QCOMPARE(two.lines(), QStringList({"Made1", "Made2"}));
    QVERIFY(rtctl({"mgr", direct, "list"}).lines().contains("  Made2  ConsoleOut"));
    QCOMPARE(rtctl({"exit", "rtcd.host_cxt/Made1.rtc", "rtcd.host_cxt/Made2.rtc"}).code, 0);
    QCOMPARE(rtctl({"exit", "rtcd.host_cxt/Made0.rtc"}).code, 0);
    QTRY_VERIFY(!rtctl({"ls", "rtcd.host_cxt"}).lines().contains("Made0.rtc"));
    QTRY_VERIFY(!rtctl({"mgr", direct, "list"}).out.contains("Made0"));
}

void TestInteropSystem::dataBothWays()
{
    for (const QString &port : seqPorts) {
        const RtctlResult in
            = rtctl({"con", openRtm("SeqOut0.rtc:") + port, ours("SeqIn0.rtc:") + port});
        QVERIFY2(in.code == 0, qPrintable(port + ": " + in.err));
        const RtctlResult out
            = rtctl({"con", ours("SeqOut0.rtc:") + port, openRtm("SeqIn0.rtc:") + port});
        QVERIFY2(out.code == 0, qPrintable(port + ": " + out.err));
    }
    QCOMPARE(onSeqComponents("act"), 0);

    // OpenRTM → ours: our SeqIn counts the samples of each port.
    QStringList silent = seqPorts;
    const QDeadlineTimer deadline(15000);
    while (!silent.isEmpty() && !deadline.hasExpired()) {
        silent.removeIf([this](const QString &port) {
            return ourStatus("SeqIn0", port + "_count").toLong() > 0;
        });
        QTest::qWait(50);
    }
    QVERIFY2(silent.isEmpty(),
             qPrintable("nothing arrived from OpenRTM's SeqOut on " + silent.join(", ")));

    // Ours → OpenRTM: each column of its table holds our counter, every sequence complete.
    QSet<QString> arrived;
    waitForSeqInTable(
        [&arrived](const SeqInTable &table) {
            for (int column = 0; column < table.columns.size(); ++column) {
                if (holdsCounter(table, column))
                    arrived.insert(table.columns[column]);
            }
            return arrived.size() == 5;
        },
        15000);
    for (const char *type : {"Double", "Float", "Long", "Short", "Octet"})
        QVERIFY2(
            arrived.contains(type),
            qPrintable(QStringLiteral("OpenRTM's SeqIn did not get our %1 and %1Seq").arg(type)));

    QCOMPARE(onSeqComponents("deact"), 0);
    QCOMPARE(rtctl({"dis", openRtm("SeqOut0.rtc")}).code, 0);
    QCOMPARE(rtctl({"dis", ours("SeqOut0.rtc")}).code, 0);
    QVERIFY(rtctl({"ls", "-l", ours("SeqIn0.rtc")}).out.simplified().startsWith("Inactive 10/0"));
}

void TestInteropSystem::everyDataFlow_data()
{
    QTest::addColumn<QStringList>("properties");
    QTest::newRow("push, flush") << QStringList {"dataport.subscription_type=flush"};
    QTest::newRow("push, new") << QStringList {"dataport.subscription_type=new"};
    QTest::newRow("push, periodic")
        << QStringList {"dataport.subscription_type=periodic", "dataport.publisher.push_rate=50"};
    // OpenRTM-aist 2.x's other names for flush and new.
    QTest::newRow("push, block") << QStringList {"dataport.subscription_type=block"};
    QTest::newRow("push, nonblock") << QStringList {"dataport.subscription_type=nonblock"};
    QTest::newRow("pull") << QStringList {"dataport.dataflow_type=pull"};
}

// Each data flow OpenRTM-aist offers, both ways: OpenRTM's SeqOut into our SeqIn on Short, our
// SeqOut into OpenRTM's SeqIn on Long (a pull connector has the reading side ask the writing
// side's OutPortCdr each cycle).
void TestInteropSystem::everyDataFlow()
{
    QFETCH(QStringList, properties);
    QStringList options;
    for (const QString &property : properties)
        options << "-p" << property;
    const RtctlResult in
        = rtctl(QStringList {"con"} + options
                + QStringList {openRtm("SeqOut0.rtc:Short"), ours("SeqIn0.rtc:Short")});
    QVERIFY2(in.code == 0, qPrintable(in.err));
    const RtctlResult out
        = rtctl(QStringList {"con"} + options
                + QStringList {ours("SeqOut0.rtc:Long"), openRtm("SeqIn0.rtc:Long")});
    QVERIFY2(out.code == 0, qPrintable(out.err));
    QCOMPARE(onSeqComponents("act"), 0);

    const long before = ourStatus("SeqIn0", "Short_count").toLong();
    QTRY_VERIFY_WITH_TIMEOUT(ourStatus("SeqIn0", "Short_count").toLong() > before + 10, 15000);
    // OpenRTM's SeqIn shows our counter in its Long column, growing from table to table.
    double seen = 0;
    const bool growing = waitForSeqInTable(
        [&seen](const SeqInTable &table) {
            const int column = int(table.columns.indexOf(QStringLiteral("Long")));
            if (column < 0 || table.basic.size() != 5 || table.basic[column] <= 0)
                return false;
            const bool grew = seen > 0 && table.basic[column] > seen;
            seen = table.basic[column];
            return grew;
        },
        15000);
    QVERIFY2(growing, "OpenRTM's SeqIn did not show our SeqOut's Long counter growing");

    QCOMPARE(onSeqComponents("deact"), 0);
    QCOMPARE(rtctl({"dis", openRtm("SeqOut0.rtc")}).code, 0);
    QCOMPARE(rtctl({"dis", ours("SeqOut0.rtc")}).code, 0);
}

void TestInteropSystem::configuration()
{
    QProcess *sample = m_examples.value("ConfigSample");
    // OpenRTM's ConfigSample runs from the start and prints its active set every cycle; its
    // configuration file makes mode1 the active set.
    const QString theirs = openRtm("ConfigSample0.rtc");
    const RtctlResult list = rtctl({"conf", theirs});
    QCOMPARE(list.code, 0);
    QVERIFY2(list.lines().contains("  default") && list.lines().contains("  mode0")
                 && list.lines().contains("* mode1"),
             qPrintable(list.out));
    checkConfiguration(
        theirs, [this, sample](const QString &set, const QString &parameter, const QString &value) {
            newOutput(sample);
            return waitForOutput(
                sample,
                QRegularExpression(
                    QStringLiteral("Active Configuration Set: %1\\s[^A]*%2:\\s+%3\\s")
                        .arg(set, parameter, QRegularExpression::escape(value))),
                10000);
        });
    QCOMPARE(rtctl({"conf", "-s", "mode1", theirs, "act"}).code, 0);

    // The same against rtmanager's ConfigSample, which mirrors its bound values in its status.
    // Like OpenRTM-aist's, it takes new values into its variables while it runs.
    const QString mine = ours("ConfigSample0.rtc");
    QCOMPARE(rtctl({"act", mine}).code, 0);
    QCOMPARE(rtctl({"conf", "--json", mine}).json()["active"].toString(), QString("default"));
    checkConfiguration(
        mine, [this](const QString &, const QString &parameter, const QString &value) {
            const QDeadlineTimer deadline(10000);
            while (ourStatus("ConfigSample0", parameter) != value && !deadline.hasExpired())
                QTest::qWait(50);
            return ourStatus("ConfigSample0", parameter) == value;
        });
    QCOMPARE(rtctl({"conf", "-s", "default", mine, "act"}).code, 0);
    QCOMPARE(rtctl({"deact", mine}).code, 0);
}

// Writes the active set and mode0, activates mode0 and reads back; `inEffect(set, parameter,
// value)` tells whether the component itself runs with that value.
void TestInteropSystem::checkConfiguration(
    const QString &component,
    const std::function<bool(const QString &, const QString &, const QString &)> &inEffect)
{
    const QString active = rtctl({"conf", "--json", component}).json()["active"].toString();
    QVERIFY(!active.isEmpty());
    QCOMPARE(rtctl({"conf", component, "set", "int_param0", "77"}).code, 0);
    QCOMPARE(rtctl({"conf", component, "get", "int_param0"}).out, QString("77\n"));
    QVERIFY2(inEffect(active, "int_param0", "77"), qPrintable(component));

    QCOMPARE(rtctl({"conf", "-s", "mode0", component, "set", "str_param1", "interop"}).code, 0);
    QCOMPARE(rtctl({"conf", "-s", "mode0", component, "act"}).code, 0);
    QCOMPARE(rtctl({"conf", "--json", component}).json()["active"].toString(), QString("mode0"));
    QCOMPARE(rtctl({"conf", component, "get", "str_param1"}).out, QString("interop\n"));
    QCOMPARE(rtctl({"conf", component, "get", "int_param0"}).out, QString("12345\n"));
    QVERIFY2(inEffect("mode0", "str_param1", "interop"), qPrintable(component));
    QVERIFY2(inEffect("mode0", "int_param0", "12345"), qPrintable(component));
}

void TestInteropSystem::serviceCalls()
{
    // OpenRTM's consumer calls our provider: it reads its commands from the console and prints
    // the reply of an echo at the next command.
    QProcess *consumer = m_examples.value("MyServiceConsumer");
    const QString provided = ours("MyServiceProvider0.rtc");
    QCOMPARE(
        rtctl({"con", openRtm("MyServiceConsumer0.rtc:MyService"), provided + ":MyService"}).code,
        0);
    QCOMPARE(rtctl({"act", openRtm("MyServiceConsumer0.rtc")}).code, 0);
    // Service providers exist only while their component is Active, ours as OpenRTM-aist's; the
    // consumer says so when a call fails.
    newOutput(consumer);
    consumer->write("get_value\n");
    // A failed call leaves the line as "Current remote value: No service connected.".
    const QRegularExpression answer("No service connected\\.|Current remote value: [-+0-9.eE]+\\n");
    QByteArray got;
    QTRY_VERIFY_WITH_TIMEOUT(
        (got += consumer->readAllStandardOutput(), answer.match(got).hasMatch()), 10000);
    QCOMPARE(answer.match(got).captured(0), QString("No service connected."));

    QCOMPARE(rtctl({"act", provided}).code, 0);
    consumer->write("echo interop-hello\n");
    QVERIFY(waitForOutput(consumer, QRegularExpression("echo\\(\\) finished: interop-hello"), 10000,
                          "\n"));
    newOutput(consumer);
    consumer->write("get_echo_history\n");
    QVERIFY(waitForOutput(consumer, QRegularExpression("\\n> 0: interop-hello\\n"), 10000));
    QCOMPARE(rtctl({"dis", openRtm("MyServiceConsumer0.rtc:MyService")}).code, 0);
    QCOMPARE(rtctl({"deact", provided}).code, 0);

    // Our consumer calls OpenRTM's provider: until that is Active every call fails.
    QProcess *provider = m_examples.value("MyServiceProvider");
    QCOMPARE(rtctl({"con", ours("MyServiceConsumer0.rtc:MyService"),
                    openRtm("MyServiceProvider0.rtc:MyService")})
                 .code,
             0);
    QCOMPARE(rtctl({"act", ours("MyServiceConsumer0.rtc")}).code, 0);
    QTRY_COMPARE_WITH_TIMEOUT(ourStatus("MyServiceConsumer0", "last_error"),
                              QString("provider unreachable"), 10000);
    QCOMPARE(ourStatus("MyServiceConsumer0", "echo_count"), QString());
    // The provider prints each call and answers ten seconds later.
    QCOMPARE(rtctl({"act", openRtm("MyServiceProvider0.rtc")}).code, 0);
    QTRY_VERIFY_WITH_TIMEOUT(!ourStatus("MyServiceConsumer0", "last_reply").isEmpty(), 30000);
    // What came back is what the provider was called with.
    const QString reply = ourStatus("MyServiceConsumer0", "last_reply");
    QVERIFY2(reply.startsWith("echo "), qPrintable(reply));
    QCOMPARE(ourStatus("MyServiceConsumer0", "echo_count"), reply.mid(5));
    QVERIFY(waitForOutput(provider,
                          QRegularExpression("MyService::echo\\(\\) was called\\.\\s+Message: "
                                             + QRegularExpression::escape(reply) + "\\s"),
                          5000));
    // The next call is under way and would hold our consumer ten seconds: the provider goes.
    QCOMPARE(rtctl({"dis", ours("MyServiceConsumer0.rtc:MyService")}).code, 0);
    m_live.stop(provider);
    QCOMPARE(rtctl({"deact", ours("MyServiceConsumer0.rtc")}).code, 0);
}

void TestInteropSystem::mixedSystemRoundTrip()
{
    // An RTS profile tells components apart by instance name: cryo refuses to save two SeqIn0s
    // silently as one, and the system below gives ours names of their own.
    const RtctlResult twins = rtctl(
        {"cryo", "-o", m_work.filePath("twins.rtsys"), openRtm("SeqIn0.rtc"), ours("SeqIn0.rtc")});
    QCOMPARE(twins.code, 1);
    QVERIFY2(twins.err.contains("another component is named SeqIn0 too"), qPrintable(twins.err));
    const RtctlResult made
        = rtctl({"mgr", ours("manager.mgr"), "create", "SeqOut?instance_name=MixOut0", "create",
                 "SeqIn?instance_name=MixIn0"});
    QVERIFY2(made.code == 0, qPrintable(made.err));
    const QStringList components {openRtm("SeqOut0.rtc"), openRtm("SeqIn0.rtc"),
                                  openRtm("ConfigSample0.rtc"), ours("MixOut0.rtc"),
                                  ours("MixIn0.rtc")};
    QCOMPARE(rtctl({"con", openRtm("SeqOut0.rtc:Long"), ours("MixIn0.rtc:Long")}).code, 0);
    QCOMPARE(rtctl({"con", ours("MixOut0.rtc:Double"), openRtm("SeqIn0.rtc:Double")}).code, 0);
    QCOMPARE(rtctl({"act", openRtm("SeqOut0.rtc"), openRtm("SeqIn0.rtc"), ours("MixOut0.rtc"),
                    ours("MixIn0.rtc")})
                 .code,
             0);
    QTRY_VERIFY(ourStatus("MixIn0", "Long_count").toLong() > 0);

    const QString file = m_work.filePath("mixed.rtsys");
    const RtctlResult cryo = rtctl(QStringList {"cryo", "-n", "Mixed", "-o", file} + components);
    QVERIFY2(cryo.code == 0, qPrintable(cryo.err));
    QFile saved(file);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    const QByteArray xml = saved.readAll();
    QCOMPARE(xml.count("<rts:Components "), 5);
    QCOMPARE(xml.count("<rts:DataPortConnectors "), 2);
    const RtctlResult same = rtctl({"diff", file});
    QVERIFY2(same.code == 0, qPrintable(same.out + same.err));

    QCOMPARE(rtctl({"teardown", file}).code, 0);
    QVERIFY(
        rtctl({"cat", "--json", ours("MixIn0.rtc:Long")}).json()["connectors"].toArray().isEmpty());
    QVERIFY(rtctl({"cat", "--json", openRtm("SeqIn0.rtc:Double")})
                .json()["connectors"]
                .toArray()
                .isEmpty());
    const RtctlResult stopped = rtctl({"stop", file});
    QVERIFY2(stopped.code == 0, qPrintable(stopped.out + stopped.err));
    for (const QString &component : components)
        QTRY_COMPARE(state(component), QString("Inactive"));
    const RtctlResult differs = rtctl({"diff", file});
    QCOMPARE(differs.code, 1);
    QVERIFY2(differs.out.contains("Long") && differs.out.contains("Double"),
             qPrintable(differs.out));

    const long before = ourStatus("MixIn0", "Long_count").toLong();
    const RtctlResult resurrected = rtctl({"resurrect", file});
    QVERIFY2(resurrected.code == 0, qPrintable(resurrected.out + resurrected.err));
    QCOMPARE(
        rtctl({"cat", "--json", ours("MixIn0.rtc:Long")}).json()["connectors"].toArray().size(), 1);
    QCOMPARE(rtctl({"cat", "--json", openRtm("SeqIn0.rtc:Double")})
                 .json()["connectors"]
                 .toArray()
                 .size(),
             1);
    const RtctlResult started = rtctl({"start", file});
    QVERIFY2(started.code == 0, qPrintable(started.out + started.err));
    for (const QString &component : components)
        QTRY_COMPARE(state(component), QString("Active"));
    const RtctlResult restored = rtctl({"diff", file});
    QVERIFY2(restored.code == 0, qPrintable(restored.out + restored.err));

    // Data flows again both ways.
    QTRY_VERIFY_WITH_TIMEOUT(ourStatus("MixIn0", "Long_count").toLong() > before, 10000);
    QVERIFY(waitForSeqInTable([](const SeqInTable &t) { return t.basic.value(0) > 0; }, 10000));

    QCOMPARE(rtctl({"stop", file}).code, 0);
    QCOMPARE(rtctl({"teardown", file}).code, 0);
}

void TestInteropSystem::commandTableMatchesHelp()
{
    const RtctlResult help = rtctl({"--help"});
    QCOMPARE(help.code, 0);
    const QString commands
        = help.out.section(QStringLiteral("Commands:\n"), 1).section(QStringLiteral("\n\n"), 0, 0);
    QStringList listed;
    for (const QString &line : commands.split('\n', Qt::SkipEmptyParts))
        listed.append(line.simplified().section(' ', 0, 0));
    QVERIFY(listed.size() > 20);
    QStringList inTable;
    for (const CommandCoverage &entry : commandTable) {
        inTable.append(entry.command);
        if (!entry.test)
            continue;
        QVERIFY2(metaObject()->indexOfSlot(QByteArray(entry.test) + "()") >= 0, entry.test);
        QVERIFY2(m_succeeded.contains(entry.command),
                 qPrintable(QStringLiteral("rtctl %1 never succeeded against OpenRTM-aist (%2)")
                                .arg(entry.command, entry.test)));
    }
    std::sort(listed.begin(), listed.end());
    std::sort(inTable.begin(), inTable.end());
    QCOMPARE(inTable, listed);
}

QTEST_GUILESS_MAIN(TestInteropSystem)
#include "tst_interopsystem.moc"
