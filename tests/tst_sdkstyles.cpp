// SPDX-License-Identifier: MIT
// Components and test drivers in the styles OpenRTM-aist users write that OpenRTM's own examples do
// not cover (data/sdkstyles, written against OpenRTM-aist 2.1's API only), built against the SDK
// and run: PortCallback functors on both port kinds and the ports' connection callbacks, connector
// listeners reading properties with NVUtil and CORBA_SeqUtil, coil::Timer and coil::Task in
// components, the RTC_* logging macros, a <Name>Comp program, a driver using CorbaNaming and
// CORBA_RTCUtil, and a driver ticking an ExtTrigExecutionContext. Each is checked against what
// rtmanager's built-in components received or against what the program printed.
#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkproject.h"

#include <QtTest>

namespace {

constexpr int runTimeoutMs = 30 * 1000;
const QString hostName = QStringLiteral("stylehost");

/// The values in a built-in ConsoleOut's received_values status.
QList<long> values(const QString &text)
{
    QList<long> numbers;
    for (const QString &item : text.split(',', Qt::SkipEmptyParts))
        numbers << item.toLong();
    return numbers;
}

} // namespace

class TestSdkStyles : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void portCallbacksOnWrite();
    void portCallbacksOnReadAndConnection();
    void connectorListenersUseNvUtil();
    void timerAndTaskInComponents();
    void rtcUtilDriverActsOnComponents();
    void componentProgramLogsAndTicks();

private:
    RtctlResult rtctl(const QStringList &arguments) const;
    QString status(const QString &component, const char *name) const;
    QString built(const QString &file) const { return m_dir + QStringLiteral("/build/") + file; }
    /// Loads the style module @p type into the manager and creates it as @p instance.
    bool create(const QString &type, const QString &instance, const QString &parameters = QString());
    /// What the manager printed so far.
    QString managerOutput();
    QString run(const QString &program, const QStringList &arguments, int *exitCode);

    QTemporaryDir m_work;
    QString m_dir;
    LiveTest::LiveSystem m_live;
    QProcess *m_manager = nullptr;
    QString m_managerOutput;
    QSet<QString> m_loaded;
    CORBA::ORB_var m_orb;
};

RtctlResult TestSdkStyles::rtctl(const QStringList &arguments) const
{
    return runRtctlAt(QStringLiteral("/%1/%2.host_cxt").arg(m_live.namingServer(), hostName), arguments);
}

QString TestSdkStyles::status(const QString &component, const char *name) const
{
    return LiveTest::componentStatus(
        m_orb, QStringLiteral("corbaname::%1#%2.host_cxt/%3").arg(m_live.namingServer(), hostName, component), name);
}

QString TestSdkStyles::managerOutput()
{
    m_managerOutput += QString::fromLocal8Bit(m_manager->readAllStandardOutput());
    return m_managerOutput;
}

bool TestSdkStyles::create(const QString &type, const QString &instance, const QString &parameters)
{
    const QString manager = QStringLiteral("/%1/%2.host_cxt/manager.mgr").arg(m_live.namingServer(), hostName);
    // A module loads once; later components of its type are only created.
    QStringList arguments{"mgr", manager};
    if (!m_loaded.contains(type))
        arguments << "load" << built(type + ".so");
    arguments << "create" << type + "?instance_name=" + instance + parameters;
    const RtctlResult r = rtctl(arguments);
    if (r.code == 0)
        m_loaded.insert(type);
    if (r.code != 0)
        qWarning().noquote() << r.out << r.err;
    return r.code == 0;
}

QString TestSdkStyles::run(const QString &program, const QStringList &arguments, int *exitCode)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    if (!process.waitForFinished(runTimeoutMs)) {
        process.kill();
        process.waitForFinished();
        *exitCode = -1;
    } else {
        *exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    }
    return QString::fromLocal8Bit(process.readAll());
}

void TestSdkStyles::initTestCase()
{
    QVERIFY(m_work.isValid());
    m_dir = m_work.filePath(QStringLiteral("sdkstyles"));
    QDir().mkpath(m_dir);
    const QDir source(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdkstyles"));
    for (const QString &file : source.entryList(QDir::Files))
        QVERIFY(QFile::copy(source.filePath(file), m_dir + '/' + file));
    QString log;
    QVERIFY2(SdkTest::buildProject(m_dir, RTSTUDIO_BUILD_DIR, &log), qPrintable(log.right(8000)));

    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_manager = m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), hostName, {}, &error);
    QVERIFY2(m_manager, qPrintable(error));
}

void TestSdkStyles::portCallbacksOnWrite()
{
    // What OnWriteConvert returns is what is sent: ten times the count.
    QVERIFY(create(QStringLiteral("CallbackSource"), QStringLiteral("Source"), QStringLiteral("&exec_cxt.periodic.rate=50")));
    QVERIFY(rtctl({"mgr", QStringLiteral("/%1/%2.host_cxt/manager.mgr").arg(m_live.namingServer(), hostName), "create",
                   "ConsoleOut?instance_name=TenfoldSink"})
                .code
            == 0);
    QVERIFY(rtctl({"con", "Source.rtc:out", "TenfoldSink.rtc:in"}).code == 0);
    QVERIFY(rtctl({"act", "TenfoldSink.rtc"}).code == 0);
    QVERIFY(rtctl({"act", "Source.rtc"}).code == 0);
    QTRY_VERIFY_WITH_TIMEOUT(values(status(QStringLiteral("TenfoldSink.rtc"), "received_values")).size() >= 3,
                             runTimeoutMs);
    for (long value : values(status(QStringLiteral("TenfoldSink.rtc"), "received_values"))) {
        QVERIFY2(value > 0 && value % 10 == 0, qPrintable(QString::number(value)));
    }
    // OnWrite sees the value before the conversion.
    QTRY_VERIFY_WITH_TIMEOUT(managerOutput().contains(QLatin1String("CallbackSource OnWrite 2\n")), runTimeoutMs);
    QVERIFY(!managerOutput().contains(QLatin1String("CallbackSource OnWrite 20\n")));
    QVERIFY(rtctl({"deact", "Source.rtc"}).code == 0);
}

void TestSdkStyles::portCallbacksOnReadAndConnection()
{
    QVERIFY(create(QStringLiteral("CallbackSink"), QStringLiteral("Sink")));
    QVERIFY(rtctl({"mgr", QStringLiteral("/%1/%2.host_cxt/manager.mgr").arg(m_live.namingServer(), hostName), "create",
                   "ConsoleIn?instance_name=Counter&exec_cxt.periodic.rate=50"})
                .code
            == 0);
    QVERIFY(rtctl({"con", "-n", "countlink", "Counter.rtc:out", "Sink.rtc:in"}).code == 0);
    QTRY_VERIFY_WITH_TIMEOUT(managerOutput().contains(QLatin1String("CallbackSink connected countlink")), runTimeoutMs);
    QVERIFY(rtctl({"act", "Sink.rtc"}).code == 0);
    QVERIFY(rtctl({"act", "Counter.rtc"}).code == 0);
    // OnReadConvert adds 1000 to what arrives (the counter starts at 1); OnRead counted the read.
    const QRegularExpression read(QStringLiteral("CallbackSink read (\\d+) after (\\d+) reads"));
    QTRY_VERIFY_WITH_TIMEOUT(read.globalMatch(managerOutput()).hasNext(), runTimeoutMs);
    const QRegularExpressionMatch first = read.match(managerOutput());
    QVERIFY2(first.captured(1).toLong() > 1000, qPrintable(first.captured(0)));
    QVERIFY2(first.captured(2).toLong() >= 1, qPrintable(first.captured(0)));
    QVERIFY(rtctl({"deact", "Counter.rtc"}).code == 0);
    QVERIFY(rtctl({"dis", "Counter.rtc:out", "Sink.rtc:in"}).code == 0);
    QTRY_VERIFY_WITH_TIMEOUT(managerOutput().contains(QLatin1String("CallbackSink disconnected countlink")),
                             runTimeoutMs);
}

void TestSdkStyles::connectorListenersUseNvUtil()
{
    QVERIFY(create(QStringLiteral("ConnectorWatcher"), QStringLiteral("Watcher")));
    QVERIFY(rtctl({"con", "-n", "watched", "-p", "dataport.subscription_type=new", "Counter.rtc:out",
                   "Watcher.rtc:in"})
                .code
            == 0);
    const QRegularExpression connect(
        QStringLiteral("ConnectorWatcher connect watched subscription new at found of (\\d+)"));
    QTRY_VERIFY2_WITH_TIMEOUT(connect.match(managerOutput()).hasMatch(), qPrintable(managerOutput().right(2000)),
                              runTimeoutMs);
    QVERIFY(connect.match(managerOutput()).captured(1).toInt() >= 4);
    QVERIFY(rtctl({"act", "Watcher.rtc"}).code == 0);
    QVERIFY(rtctl({"act", "Counter.rtc"}).code == 0);
    QTRY_VERIFY_WITH_TIMEOUT(managerOutput().contains(QLatin1String("ConnectorWatcher received ")), runTimeoutMs);
    QVERIFY(rtctl({"deact", "Counter.rtc"}).code == 0);
}

void TestSdkStyles::timerAndTaskInComponents()
{
    QVERIFY(create(QStringLiteral("TimerCounter"), QStringLiteral("Timed"), QStringLiteral("&exec_cxt.periodic.rate=100")));
    QVERIFY(create(QStringLiteral("TaskProducer"), QStringLiteral("Producer")));
    const QString manager = QStringLiteral("/%1/%2.host_cxt/manager.mgr").arg(m_live.namingServer(), hostName);
    QVERIFY(rtctl({"mgr", manager, "create", "ConsoleOut?instance_name=TimerSink", "create",
                   "ConsoleOut?instance_name=TaskSink"})
                .code
            == 0);
    QVERIFY(rtctl({"con", "Timed.rtc:out", "TimerSink.rtc:in"}).code == 0);
    QVERIFY(rtctl({"con", "Producer.rtc:out", "TaskSink.rtc:in"}).code == 0);
    for (const QString component : {"TimerSink.rtc", "TaskSink.rtc", "Timed.rtc", "Producer.rtc"})
        QVERIFY(rtctl({"act", component}).code == 0);
    // Ticked 10 ms a cycle: the 20 ms function ran about every second cycle, the 100 ms one once
    // after ten cycles and never again.
    QTRY_VERIFY_WITH_TIMEOUT(!values(status(QStringLiteral("TimerSink.rtc"), "last_value")).isEmpty()
                                 && values(status(QStringLiteral("TimerSink.rtc"), "last_value")).first() >= 20001,
                             runTimeoutMs);
    const long timed = values(status(QStringLiteral("TimerSink.rtc"), "last_value")).first();
    QCOMPARE(timed % 1000, 1L);
    // The task's numbers, in order, are multiples of seven. A late cycle writes a burst that may
    // overflow the sink's buffer (overwrite policy), so a number may be skipped, never reordered.
    QTRY_VERIFY_WITH_TIMEOUT(values(status(QStringLiteral("TaskSink.rtc"), "received_values")).size() >= 5,
                             runTimeoutMs);
    const QList<long> produced = values(status(QStringLiteral("TaskSink.rtc"), "received_values"));
    for (int i = 0; i < produced.size(); ++i) {
        QVERIFY2(produced.at(i) % 7 == 0, qPrintable(QString::number(produced.at(i))));
        if (i > 0)
            QVERIFY2(produced.at(i) > produced.at(i - 1), qPrintable(QString::number(produced.at(i))));
    }
    for (const QString component : {"Timed.rtc", "Producer.rtc"})
        QVERIFY(rtctl({"deact", component}).code == 0);
}

void TestSdkStyles::rtcUtilDriverActsOnComponents()
{
    QVERIFY(create(QStringLiteral("CallbackSource"), QStringLiteral("DrivenSource")));
    QVERIFY(create(QStringLiteral("CallbackSink"), QStringLiteral("DrivenSink")));
    int code = 0;
    const QString output = run(built(QStringLiteral("RtcUtilDriver")),
                               {m_live.namingServer(), hostName + ".host_cxt/DrivenSource.rtc",
                                hostName + ".host_cxt/DrivenSink.rtc"},
                               &code);
    QVERIFY2(code == 0, qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver outport DrivenSource.out")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver inport DrivenSink.in")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver connect 0\n")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver connector driven\n")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver rate 50\n")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver activate 0\n")), qPrintable(output));
    // ACTIVE_STATE (2) after activation, INACTIVE_STATE (1) after deactivation.
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver state source 2 active 1\n")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver state source 1 active 0\n")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver config default\n")), qPrintable(output));
    QVERIFY2(output.contains(QLatin1String("RtcUtilDriver disconnect 0\n")), qPrintable(output));
    QTRY_VERIFY2_WITH_TIMEOUT(managerOutput().contains(QLatin1String("CallbackSink connected driven")),
                              qPrintable(managerOutput().right(2000)), runTimeoutMs);
    QVERIFY(!rtctl({"cat", "-l", "DrivenSource.rtc"}).out.contains(QLatin1String("driven")));
}

void TestSdkStyles::componentProgramLogsAndTicks()
{
    // A <Name>Comp program whose contexts are ExtTrigExecutionContexts, logging to a file.
    const QString logFile = m_work.filePath(QStringLiteral("styles.log"));
    const QString conf = m_work.filePath(QStringLiteral("styles.conf"));
    QFile file(conf);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Text));
    file.write(QStringLiteral("corba.nameservers: %1\n"
                              "naming.formats: %2.host_cxt/%n.rtc\n"
                              "exec_cxt.periodic.type: ExtTrigExecutionContext\n"
                              "logger.enable: YES\n"
                              "logger.log_level: PARANOID\n"
                              "logger.file_name: %3\n%4\n")
                   .arg(m_live.namingServer(), hostName, logFile, LiveTest::NoMasterLine)
                   .toUtf8());
    file.close();
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("STYLES_CREATE"), QStringLiteral("TickCounter,LoggingComp"));
    QString error;
    QProcess *program = m_live.startProcess(built(QStringLiteral("StylesComp")), {"-f", conf},
                                            QStringLiteral("StylesComp created LoggingComp0"), &error, runTimeoutMs,
                                            environment);
    QVERIFY2(program, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"ls"}).out.contains(QLatin1String("LoggingComp0.rtc")), runTimeoutMs);

    int code = 0;
    QString output = run(built(QStringLiteral("ExtTrigDriver")),
                         {m_live.namingServer(), hostName + ".host_cxt/TickCounter0.rtc", "5"}, &code);
    QVERIFY2(code == 0, qPrintable(output));
    QString printed;
    QTRY_VERIFY_WITH_TIMEOUT((printed += QString::fromLocal8Bit(program->readAllStandardOutput()))
                                 .contains(QLatin1String("TickCounter0 cycle 6\n")),
                             runTimeoutMs);
    // The activation's cycle, then exactly one per tick: no cycle runs without one.
    QVERIFY(!printed.contains(QLatin1String("TickCounter0 cycle 7")));
    output = run(built(QStringLiteral("ExtTrigDriver")),
                 {m_live.namingServer(), hostName + ".host_cxt/LoggingComp0.rtc", "3"}, &code);
    QVERIFY2(code == 0, qPrintable(output));

    // The macros wrote at their levels into the configured file.
    auto logged = [&logFile]() {
        QFile log(logFile);
        return log.open(QIODevice::ReadOnly) ? QString::fromUtf8(log.readAll()) : QString();
    };
    QTRY_VERIFY_WITH_TIMEOUT(logged().contains(QLatin1String("LoggingComp cycle 3 reached")), runTimeoutMs);
    const QString text = logged();
    QVERIFY2(text.contains(QLatin1String("LoggingComp initialized with 0 ports")), qPrintable(text.right(2000)));
    QVERIFY2(text.contains(QLatin1String("LoggingComp activated")), qPrintable(text.right(2000)));
    QVERIFY2(text.contains(QLatin1String("ERROR")), qPrintable(text.right(2000)));
    QVERIFY2(text.contains(QLatin1String("LoggingComp cycle 1")), qPrintable(text.right(2000)));
    m_live.stop(program);
}

QTEST_GUILESS_MAIN(TestSdkStyles)
#include "tst_sdkstyles.moc"
