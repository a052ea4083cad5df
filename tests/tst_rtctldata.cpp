// SPDX-License-Identifier: MIT
// rtctl print and inject (rtshell's rtprint / rtinject) against a live rtmanager: samples as
// text and JSON, values written through a component and read back on its output, and the tools'
// own connectors removed again after a count, Ctrl-C and bad input.

#include "componentproxy.h"
#include "livesystem.h"
#include "namingbrowser.h"
#include "rtctlrunner.h"
#include "rtpath.h"

#include <QDateTime>
#include <QDeadlineTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

class TestRtctlData : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanup();
    void printsSamplesAsTextAndJson();
    void injectedValuesPassThroughAComponent();
    void injectReadsWhatPrintWrote();
    void interruptRemovesTheConnector();
    void logRecordsAndPlaysBack();
    void badInputWritesNothing_data();
    void badInputWritesNothing();

private:
    RtctlResult rtctl(const QStringList &arguments)
    {
        return runRtctlAt(m_context, arguments);
    }
    /// The number of connectors on a port of a component under the test's host context.
    int connectors(const QString &component, const QString &port);
    /// Waits (bounded) until the port has `count` connectors.
    bool waitForConnectors(const QString &component, const QString &port, int count);
    QProcess *startPrint(const QStringList &arguments);

    LiveTest::LiveSystem m_live;
    QString m_context;
    std::vector<std::unique_ptr<QProcess>> m_prints;
};

void TestRtctlData::initTestCase()
{
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    QVERIFY2(m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(),
                                     QStringLiteral("data"),
                                     {"manager.components.precreate=SeqOut,Sensor"}, &error),
             qPrintable(error));
    m_context = QStringLiteral("/%1/data.host_cxt").arg(m_live.namingServer());
    QCOMPARE(rtctl({"act", "SeqOut0.rtc", "Sensor0.rtc"}).code, 0);
}

void TestRtctlData::cleanup()
{
    // A print a failed test left running is interrupted, so that it removes its connector.
    for (const auto &print : m_prints) {
        if (print->state() != QProcess::NotRunning) {
            ::kill(pid_t(print->processId()), SIGINT);
            if (!print->waitForFinished(10000))
                print->kill();
        }
    }
    m_prints.clear();
}

int TestRtctlData::connectors(const QString &component, const QString &port)
{
    QString error;
    const auto path = Corba::RtPath::parse(m_context + QLatin1Char('/') + component, QStringLiteral("/"), &error);
    if (!path)
        return -1;
    const Corba::NamingNode node = Corba::NamingBrowser::node(*path);
    return int(Corba::ComponentProxy(node.ior, node.path).port(port).connectors.size());
}

bool TestRtctlData::waitForConnectors(const QString &component, const QString &port, int count)
{
    const QDeadlineTimer deadline(10000);
    while (!deadline.hasExpired()) {
        if (connectors(component, port) == count)
            return true;
        QTest::qWait(20);
    }
    return false;
}

QProcess *TestRtctlData::startPrint(const QStringList &arguments)
{
    auto process = std::make_unique<QProcess>();
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("RTCSH_CWD"), m_context);
    process->setProcessEnvironment(environment);
    process->start(RTCTL_PATH, QStringList {"print"} + arguments);
    m_prints.push_back(std::move(process));
    return m_prints.back().get();
}

void TestRtctlData::printsSamplesAsTextAndJson()
{
    const RtctlResult text = rtctl({"print", "-n", "3", "SeqOut0.rtc:Long"});
    QCOMPARE(text.code, 0);
    const QStringList lines = text.lines();
    QCOMPARE(lines.size(), 3);
    static const QRegularExpression sample(QStringLiteral("^\\[\\d+\\.\\d{9}\\] data=(\\d+)$"));
    qint64 previous = -1;
    for (const QString &line : lines) {
        const QRegularExpressionMatch match = sample.match(line);
        QVERIFY2(match.hasMatch(), qPrintable(line));
        QVERIFY(match.captured(1).toLongLong() > previous); // SeqOut counts up
        previous = match.captured(1).toLongLong();
    }

    const RtctlResult json = rtctl({"print", "-n", "2", "--json", "SeqOut0.rtc:DoubleSeq"});
    QCOMPARE(json.code, 0);
    QCOMPARE(json.lines().size(), 2);
    for (const QString &line : json.lines()) {
        const QJsonObject object = QJsonDocument::fromJson(line.toUtf8()).object();
        QCOMPARE(object.keys(), QStringList({"data", "tm"}));
        QCOMPARE(object["data"].toArray().size(), 10);
    }
    QVERIFY(json.lines().first().startsWith(R"({"tm":{"sec":)")); // declaration order
    QCOMPARE(connectors("SeqOut0.rtc", "Long"), 0);
    QCOMPARE(connectors("SeqOut0.rtc", "DoubleSeq"), 0);
}

void TestRtctlData::injectedValuesPassThroughAComponent()
{
    // Sensor turns each TimedLong on "in" into a TimedFloat on "out" with the same timestamp.
    // It may write all three in one step, which the default subscription ("new") would thin out.
    QProcess *print = startPrint({"-n", "3", "--json", "-p", "dataport.subscription_type=flush", "Sensor0.rtc:out"});
    QVERIFY(waitForConnectors("Sensor0.rtc", "out", 1));
    const RtctlResult injected
        = rtctl({"inject", "Sensor0.rtc:in", R"({"tm":{"sec":5,"nsec":7},"data":1})", "2", "-3"});
    QVERIFY2(injected.code == 0, qPrintable(injected.err));
    QVERIFY(LiveTest::waitForExit(print, 10000));
    QCOMPARE(print->exitCode(), 0);
    const QStringList lines = QString::fromUtf8(print->readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines[0], QString(R"({"tm":{"sec":5,"nsec":7},"data":1})"));
    QVERIFY2(lines[1].endsWith(R"("data":2})"), qPrintable(lines[1]));
    QVERIFY2(lines[2].endsWith(R"("data":-3})"), qPrintable(lines[2]));
    const qint64 sec = QJsonDocument::fromJson(lines[1].toUtf8())["tm"]["sec"].toInteger();
    QVERIFY(qAbs(sec - QDateTime::currentSecsSinceEpoch()) < 60); // stamped when sent
    QCOMPARE(connectors("Sensor0.rtc", "in"), 0);
    QCOMPARE(connectors("Sensor0.rtc", "out"), 0);
}

void TestRtctlData::injectReadsWhatPrintWrote()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath("samples.jsonl");
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write("# recorded by hand\n{\"tm\":{\"sec\":1,\"nsec\":0},\"data\":10}\n\n"
              "{\"tm\":{\"sec\":2,\"nsec\":0},\"data\":20}\n");
    out.close();
    // Every sample: the default subscription type (new) may skip one written 5 ms after another.
    QProcess *print = startPrint({"-n", "4", "-p", "dataport.subscription_type=flush", "Sensor0.rtc:out"});
    QVERIFY(waitForConnectors("Sensor0.rtc", "out", 1));
    QCOMPARE(rtctl({"inject", "--from", file, "-n", "2", "-r", "200", "Sensor0.rtc:in"}).code, 0);
    QVERIFY(LiveTest::waitForExit(print, 10000));
    QCOMPARE(QString::fromUtf8(print->readAllStandardOutput()).split('\n', Qt::SkipEmptyParts),
             QStringList({"[1.000000000] data=10", "[2.000000000] data=20", "[1.000000000] data=10",
                          "[2.000000000] data=20"}));
}

void TestRtctlData::interruptRemovesTheConnector()
{
    QProcess *print = startPrint({"SeqOut0.rtc:Short"});
    QVERIFY(waitForConnectors("SeqOut0.rtc", "Short", 1));
    QVERIFY(print->waitForReadyRead(10000)); // samples are flowing
    ::kill(pid_t(print->processId()), SIGINT);
    QVERIFY(LiveTest::waitForExit(print, 10000));
    QCOMPARE(print->exitStatus(), QProcess::NormalExit);
    QCOMPARE(print->exitCode(), 0);
    QCOMPARE(connectors("SeqOut0.rtc", "Short"), 0);
}

void TestRtctlData::logRecordsAndPlaysBack()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString both = dir.filePath("both.jsonl");
    // Half a second of both ports (a count could be reached before the second port's first sample).
    const RtctlResult recorded = rtctl({"log", "-o", both, "-d", "0.5", "SeqOut0.rtc:Long", "SeqOut0.rtc:Double"});
    QVERIFY2(recorded.code == 0, qPrintable(recorded.err));
    QFile file(both);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QSet<QString> types;
    int lines = 0;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.isEmpty())
            continue;
        ++lines;
        const QJsonObject object = QJsonDocument::fromJson(line).object();
        QVERIFY(object["t"].toInteger() > 0);
        QVERIFY(object["port"].toString().endsWith("SeqOut0.rtc:Long") || object["port"].toString().endsWith("SeqOut0.rtc:Double"));
        QVERIFY(object["value"]["data"].isDouble());
        types.insert(object["type"].toString());
    }
    QVERIFY(lines > 2);
    QCOMPARE(types, QSet<QString>({"RTC::TimedLong", "RTC::TimedDouble"}));
    QCOMPARE(connectors("SeqOut0.rtc", "Long"), 0);
    QCOMPARE(connectors("SeqOut0.rtc", "Double"), 0);

    // Played into Sensor, the recorded values come out again.
    const QString longs = dir.filePath("long.jsonl");
    QCOMPARE(rtctl({"log", "-o", longs, "-n", "4", "SeqOut0.rtc:Long"}).code, 0);
    QStringList expected;
    QFile longFile(longs);
    QVERIFY(longFile.open(QIODevice::ReadOnly));
    for (const QByteArray &line : longFile.readAll().split('\n')) {
        if (!line.isEmpty())
            expected.append(QString::number(QJsonDocument::fromJson(line)["value"]["data"].toInteger()));
    }
    QCOMPARE(expected.size(), 4);
    QProcess *print = startPrint({"-n", "4", "--json", "-p", "dataport.subscription_type=flush", "Sensor0.rtc:out"});
    QVERIFY(waitForConnectors("Sensor0.rtc", "out", 1));
    const RtctlResult played = rtctl({"log", "--play", longs, "Sensor0.rtc:in"});
    QVERIFY2(played.code == 0, qPrintable(played.err));
    QVERIFY(LiveTest::waitForExit(print, 10000));
    QStringList seen;
    for (const QString &line : QString::fromUtf8(print->readAllStandardOutput()).split('\n', Qt::SkipEmptyParts))
        seen.append(QString::number(QJsonDocument::fromJson(line.toUtf8())["data"].toInteger()));
    QCOMPARE(seen, expected);

    const RtctlResult wrongCount = rtctl({"log", "--play", longs, "Sensor0.rtc:in", "Sensor0.rtc:in"});
    QCOMPARE(wrongCount.code, 1);
    QVERIFY2(wrongCount.err.contains("holds 1 port(s)"), qPrintable(wrongCount.err));
    const RtctlResult wrongType = rtctl({"log", "--play", both, "Sensor0.rtc:in", "Sensor0.rtc:in"});
    QCOMPARE(wrongType.code, 1);
    QVERIFY2(wrongType.err.contains("was recorded with RTC::TimedDouble"), qPrintable(wrongType.err));
    QCOMPARE(connectors("Sensor0.rtc", "in"), 0);
}

void TestRtctlData::badInputWritesNothing_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("message");
    QTest::newRow("not a number") << QStringList {"inject", "Sensor0.rtc:in", "1", "two"} << 1
                                  << "Sensor0.rtc:in: value 2 for RTC::TimedLong: 'two' is not a value";
    QTest::newRow("unknown member") << QStringList {"inject", "Sensor0.rtc:in", R"({"value":1})"} << 1
                                    << "RTC::TimedLong has no member 'value'";
    QTest::newRow("out of range") << QStringList {"inject", "Sensor0.rtc:in", "4294967296"} << 1
                                  << ".data: 4.29497e+09 is not a whole number";
    QTest::newRow("print an InPort") << QStringList {"print", "Sensor0.rtc:in"} << 1 << "not an OutPort";
    QTest::newRow("inject an OutPort") << QStringList {"inject", "Sensor0.rtc:out", "1"} << 1 << "not an InPort";
    QTest::newRow("no port") << QStringList {"print", "Sensor0.rtc"} << 1 << "no :PORT given";
    QTest::newRow("no such port") << QStringList {"print", "Sensor0.rtc:nope"} << 1 << "nope";
    QTest::newRow("no value") << QStringList {"inject", "Sensor0.rtc:in"} << 2 << "at least one VALUE";
    QTest::newRow("missing file") << QStringList {"inject", "--from", "/nonexistent/x.jsonl", "Sensor0.rtc:in"}
                                  << 1 << "/nonexistent/x.jsonl";
}

void TestRtctlData::badInputWritesNothing()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QString, message);
    const RtctlResult r = rtctl(arguments);
    QCOMPARE(r.code, code);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(connectors("Sensor0.rtc", "in"), 0);
    QCOMPARE(connectors("Sensor0.rtc", "out"), 0);
}

QTEST_GUILESS_MAIN(TestRtctlData)
#include "tst_rtctldata.moc"
