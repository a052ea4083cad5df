// SPDX-License-Identifier: MIT
// Python components on RT Studio's runtime and OpenRTM-aist 2.x's C++ examples in one name server:
// samples go from OpenRTM-aist's ConsoleIn through a Python component to OpenRTM-aist's ConsoleOut,
// and MyService calls go both ways (OpenRTM-aist's consumer → a Python servant, a Python consumer →
// OpenRTM-aist's provider). Skipped without an OpenRTM-aist prefix.

#include "livesystem.h"
#include "pythonenvironment.h"
#include "rtctlrunner.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString openRtmPrefix = QStringLiteral(RTSTUDIO_OPENRTM_PREFIX);
// OpenRTM-aist's MyService provider takes ten seconds to answer echo().
constexpr int RunTimeoutMs = 30000;

QString dataFile(const QString &name)
{
    for (const char *folder : {"/python/", "/pythonidl/"}) {
        const QString path = RTSTUDIO_TEST_DATA_DIR + QLatin1String(folder) + name;
        if (QFileInfo::exists(path))
            return path;
    }
    return {};
}

} // namespace

class TestInteropPython : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void samplesPassThroughPython();
    void servicesCallBothWays();

private:
    RtctlResult rtctl(const QStringList &arguments) { return runRtctlAt(m_context, arguments); }
    bool rtctlSucceeds(const QStringList &arguments)
    {
        const RtctlResult r = rtctl(arguments);
        if (r.code != 0)
            qWarning().noquote() << "rtctl" << arguments.join(' ') << ":" << r.err;
        return r.code == 0;
    }
    QProcess *startExample(const QString &name, QString *error);
    QProcess *startScript(const QString &script, const QString &instance, QString *error,
                          const QString &extraConf = {});
    /// Waits until @p process has printed @p text, reading what it prints into m_printed.
    bool waitForPrinted(QProcess *process, const QByteArray &text);

    QTemporaryDir m_work;
    LiveTest::LiveSystem m_live;
    QString m_context;
    QString m_stubs;
    QHash<QProcess *, QByteArray> m_printed;
};

QProcess *TestInteropPython::startExample(const QString &name, QString *error)
{
    return m_live.startOpenRtmExample(openRtmPrefix, name, QStringLiteral("interop"), error);
}

QProcess *TestInteropPython::startScript(const QString &script, const QString &instance, QString *error,
                                          const QString &extraConf)
{
    const QString conf = m_work.filePath(QFileInfo(script).baseName() + QStringLiteral(".conf"));
    QFile file(conf);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        *error = conf + QStringLiteral(": ") + file.errorString();
        return nullptr;
    }
    file.write(QStringLiteral("corba.nameservers: %1\nnaming.formats: interop.host_cxt/%n.rtc\nlogger.enable: NO\n%2\n")
                   .arg(m_live.namingServer(), LiveTest::NoMasterLine)
                   .toUtf8()
               + extraConf.toUtf8());
    file.close();
    const QProcessEnvironment environment = LiveTest::pythonEnvironment(
        m_stubs + QLatin1Char(':') + RTSTUDIO_PYTHON_PATH, QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD));
    return m_live.startRegistered(
        QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE), {script, QStringLiteral("-f"), conf},
        [this, &instance] { return rtctl({QStringLiteral("ls")}).out.contains(instance); }, error, RunTimeoutMs,
        environment);
}

bool TestInteropPython::waitForPrinted(QProcess *process, const QByteArray &text)
{
    QByteArray &printed = m_printed[process];
    const bool seen = QTest::qWaitFor(
        [&] {
            printed += process->readAllStandardOutput();
            return printed.contains(text);
        },
        RunTimeoutMs);
    if (!seen)
        qWarning().noquote() << "waited for" << text << "in" << printed;
    return seen;
}

void TestInteropPython::initTestCase()
{
    if (openRtmPrefix.isEmpty())
        QSKIP("skipped: no OpenRTM-aist");
    LiveTest::useOpenRtm(openRtmPrefix);
    QVERIFY(m_work.isValid());
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_context = QStringLiteral("/%1/interop.host_cxt").arg(m_live.namingServer());
    m_stubs = m_work.filePath(QStringLiteral("stubs"));
    const RtctlResult compiled
        = runRtctl({"idl", "--lang", "python", "-o", m_stubs, dataFile(QStringLiteral("SimpleService.idl"))});
    QVERIFY2(compiled.code == 0, qPrintable(compiled.err));
}

void TestInteropPython::cleanupTestCase()
{
    m_live.stopAll();
}

void TestInteropPython::samplesPassThroughPython()
{
    // OpenRTM-aist's ConsoleIn (numbers from its standard input) → PyScaler (×1000) → OpenRTM-aist's
    // ConsoleOut, which prints what it reads.
    QString error;
    QProcess *consoleIn = startExample(QStringLiteral("ConsoleInComp"), &error);
    QVERIFY2(consoleIn, qPrintable(error));
    QProcess *consoleOut = startExample(QStringLiteral("ConsoleOutComp"), &error);
    QVERIFY2(consoleOut, qPrintable(error));
    QProcess *scaler = startScript(dataFile(QStringLiteral("PyScaler.py")), QStringLiteral("PyScaler0.rtc"), &error);
    QVERIFY2(scaler, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"ls"}).out.contains("ConsoleIn0.rtc") && rtctl({"ls"}).out.contains("ConsoleOut0.rtc"),
                             RunTimeoutMs);
    // Every sample, not only the newest of those sent between two executions.
    QVERIFY(rtctlSucceeds({"con", "-p", "dataport.subscription_type=flush", "ConsoleIn0.rtc:out", "PyScaler0.rtc:in"}));
    QVERIFY(rtctlSucceeds({"con", "-p", "dataport.subscription_type=flush", "PyScaler0.rtc:out", "ConsoleOut0.rtc:in"}));
    QVERIFY(rtctlSucceeds({"act", "ConsoleOut0.rtc", "PyScaler0.rtc", "ConsoleIn0.rtc"}));
    consoleIn->write("7\n-3\n");
    QVERIFY2(waitForPrinted(consoleOut, "Received: 7000") && waitForPrinted(consoleOut, "Received: -3000"),
             (consoleIn->readAllStandardOutput() + scaler->readAllStandardOutput()).constData());
    // (ConsoleIn waits in its execution for the next number: it stays active until the process ends.)
    QVERIFY(rtctlSucceeds({"deact", "PyScaler0.rtc", "ConsoleOut0.rtc"}));
}

void TestInteropPython::servicesCallBothWays()
{
    QString error;
    QProcess *provider = startExample(QStringLiteral("MyServiceProviderComp"), &error);
    QVERIFY2(provider, qPrintable(error));
    QProcess *consumer = startExample(QStringLiteral("MyServiceConsumerComp"), &error);
    QVERIFY2(consumer, qPrintable(error));
    QProcess *python = startScript(dataFile(QStringLiteral("PyMyService.py")), QStringLiteral("PyMyService0.rtc"), &error,
                                   QStringLiteral("corba.call_timeout: %1\n").arg(RunTimeoutMs));
    QVERIFY2(python, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"ls"}).out.contains("MyServiceProvider0.rtc")
                                 && rtctl({"ls"}).out.contains("MyServiceConsumer0.rtc"),
                             RunTimeoutMs);
    QVERIFY(rtctlSucceeds({"con", "MyServiceConsumer0.rtc:MyService", "PyMyService0.rtc:Provided"}));
    QVERIFY(rtctlSucceeds({"con", "PyMyService0.rtc:Required", "MyServiceProvider0.rtc:MyService"}));
    // Providers first: their objects answer from their component's activation on.
    QVERIFY(rtctlSucceeds({"act", "MyServiceProvider0.rtc", "PyMyService0.rtc", "MyServiceConsumer0.rtc"}));

    // A Python consumer → OpenRTM-aist's provider: a string, floats and both histories back.
    QVERIFY(waitForPrinted(python, "consumer: echo from python\n"));
    QVERIFY(waitForPrinted(python, "consumer: value 2.5 history [1.25, 2.5]\n"));
    QVERIFY(waitForPrinted(python, "consumer: echoes ['from python']\n"));

    // OpenRTM-aist's consumer (one command per execution from its standard input) → the Python servant.
    consumer->write("echo hello\n");
    QVERIFY(waitForPrinted(python, "servant: echo hello\n"));
    consumer->write("set_value 3.5\n");
    QVERIFY(waitForPrinted(consumer, "Set remote value: 3.5"));
    consumer->write("get_value\n");
    QVERIFY(waitForPrinted(consumer, "Current remote value: 3.5"));
    // The echo's answer is printed with the next command.
    consumer->write("get_value\n");
    QVERIFY(waitForPrinted(consumer, "echo() finished: python says hello"));
    // Its execution waits for the next command; OpenRTM-aist's deactivation waits for the execution
    // (a second at most, then it answers RTC_ERROR): the end of its input lets it return.
    consumer->closeWriteChannel();
    QVERIFY(rtctlSucceeds({"deact", "MyServiceConsumer0.rtc", "PyMyService0.rtc", "MyServiceProvider0.rtc"}));
}

QTEST_GUILESS_MAIN(TestInteropPython)
#include "tst_interoppython.moc"
