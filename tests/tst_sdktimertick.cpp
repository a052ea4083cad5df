// SPDX-License-Identifier: MIT
// The SDK manager's `timer.tick` (the period of the thread that runs addTask() and invoke() work):
// unreadable, negative or not-a-number values fall back to OpenRTM-aist's 0.1 s, and values too large
// for a clock's duration (1e300, inf) are bounded, so the timer neither overflows nor keeps the
// manager from ending. The manager is one per process, so each value runs in a child process: this
// program started again with `--child TICK WAIT_MS`.
#include "sdkinprocess.h"

#include <QCoreApplication>
#include <QProcess>
#include <QTest>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// Starts the manager with @p tick, asks for a delayed call and says whether it ran within @p waitMs;
// then ends the manager. Exit status 0 when the manager started and ended.
int runChild(const char *tick, int waitMs)
{
    RTC::Manager *manager = SdkTest::startInProcessManager("tst_sdktimertick",
                                                           {QByteArray("timer.tick:") + tick});
    if (manager == nullptr)
        return 2;
    std::atomic<int> delayed{0};
    manager->invoke([&delayed] { ++delayed; });
    const bool ran = QTest::qWaitFor([&delayed] { return delayed.load() > 0; }, waitMs);
    std::printf("delayed call ran: %s\n", ran ? "yes" : "no");
    std::fflush(stdout);
    return SdkTest::stopInProcessManager(manager) ? 0 : 3;
}

} // namespace

class TestSdkTimerTick : public QObject
{
    Q_OBJECT

private slots:
    void tick_data();
    void tick();
};

void TestSdkTimerTick::tick_data()
{
    QTest::addColumn<QString>("value");
    QTest::addColumn<int>("waitMs");
    QTest::addColumn<bool>("runs");
    QTest::newRow("10 ms") << "0.01" << 5000 << true;
    QTest::newRow("not a number") << "junk" << 5000 << true;
    QTest::newRow("negative") << "-1" << 5000 << true;
    QTest::newRow("nan") << "nan" << 5000 << true;
    QTest::newRow("1e300 s") << "1e300" << 300 << false;
    QTest::newRow("infinite") << "inf" << 300 << false;
}

void TestSdkTimerTick::tick()
{
    QFETCH(QString, value);
    QFETCH(int, waitMs);
    QFETCH(bool, runs);
    QProcess child;
    child.setProcessChannelMode(QProcess::MergedChannels);
    child.start(QCoreApplication::applicationFilePath(), {"--child", value, QString::number(waitMs)});
    QVERIFY2(child.waitForStarted(10000), qPrintable(child.errorString()));
    // An unbounded tick would keep the timer thread (and so the manager's end) waiting for ever.
    const bool ended = child.waitForFinished(60000);
    if (!ended) {
        child.kill();
        child.waitForFinished(5000);
    }
    const QString output = QString::fromUtf8(child.readAll());
    QVERIFY2(ended, qPrintable("the manager did not end; output:\n" + output.right(600)));
    QVERIFY2(child.exitStatus() == QProcess::NormalExit && child.exitCode() == 0,
             qPrintable(QString("exit code %1; output:\n%2").arg(child.exitCode()).arg(output.right(600))));
    const QString expected = runs ? "delayed call ran: yes" : "delayed call ran: no";
    QVERIFY2(output.contains(expected), qPrintable("expected \"" + expected + "\"; output:\n" + output.right(600)));
}

int main(int argc, char **argv)
{
    QCoreApplication application(argc, argv);
    if (argc == 4 && std::strcmp(argv[1], "--child") == 0)
        return runChild(argv[2], std::atoi(argv[3]));
    TestSdkTimerTick test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_sdktimertick.moc"
