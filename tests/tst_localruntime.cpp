// SPDX-License-Identifier: MIT
// rtctl local start|stop|status: a name server and an rtmanager master that outlive rtctl, found
// and reused by the next call, restarted when half of it died, moved to the next free ports when
// the usual ones are taken, and stopped for good.

#include "livesystem.h"
#include "rtctlrunner.h"

#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <csignal>

namespace {

/// The local addresses (hex, as the kernel lists them) of the sockets listening on TCP @p port.
QStringList listeningAddresses(int port)
{
    QStringList addresses;
    for (const char *table : {"/proc/net/tcp", "/proc/net/tcp6"}) {
        QFile file {QString::fromLatin1(table)};
        if (!file.open(QIODevice::ReadOnly))
            continue;
        for (const QByteArray &line : file.readAll().split('\n').mid(1)) {
            const QList<QByteArray> fields = line.simplified().split(' ');
            if (fields.size() < 4 || fields.at(3) != "0A") // LISTEN
                continue;
            const QList<QByteArray> local = fields.at(1).split(':');
            if (local.size() == 2 && local.at(1).toInt(nullptr, 16) == port)
                addresses << QString::fromLatin1(local.at(0));
        }
    }
    return addresses;
}

} // namespace

class TestLocalRuntime : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void startsReusesAndStops();
    void restartsWhenHalfOfItDied();
    void takenPortsAreSkipped();
    void deploymentShowsProgressOnATerminal();

private:
    RtctlResult local(const QString &action)
    {
        return runRtctl({"local", action, "--json"}, {{"XDG_RUNTIME_DIR", m_runtime.path()}});
    }
    QJsonObject state(const QString &action)
    {
        const RtctlResult r = local(action);
        return r.json().object();
    }

    QTemporaryDir m_runtime;
};

void TestLocalRuntime::initTestCase()
{
    QVERIFY(m_runtime.isValid());
    QFile::setPermissions(m_runtime.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
}

void TestLocalRuntime::cleanupTestCase()
{
    local("stop"); // whatever a failed test left running
}

void TestLocalRuntime::startsReusesAndStops()
{
    const RtctlResult before = local("status");
    QCOMPARE(before.code, 1);
    QCOMPARE(before.json()["running"].toBool(), false);

    const QJsonObject started = state("start");
    QVERIFY2(started["running"].toBool(), qPrintable(local("status").err));
    const int namingPort = started["nameServer"]["port"].toInt();
    const int managerPort = started["manager"]["port"].toInt();
    QVERIFY(namingPort >= 2809 && managerPort >= 2810 && namingPort != managerPort);
    // Both serve this machine only.
    for (const int port : {namingPort, managerPort}) {
        const QStringList addresses = listeningAddresses(port);
        QVERIFY2(addresses == QStringList {QStringLiteral("0100007F")}, qPrintable(addresses.join(' ')));
    }

    // The manager is registered in the name server and creates components.
    const QString server = QStringLiteral("/127.0.0.1:%1").arg(namingPort);
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"ls", "-R", server}).out.contains("manager.mgr"), 10000);
    const RtctlResult created
        = runRtctl({"mgr", QStringLiteral("corbaloc::127.0.0.1:%1").arg(managerPort), "create", "ConsoleIn"});
    QVERIFY2(created.code == 0, qPrintable(created.err));
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"ls", "-R", server}).out.contains("ConsoleIn0.rtc"), 10000);

    // A second start finds the same processes.
    const QJsonObject again = state("start");
    QCOMPARE(again["nameServer"]["pid"].toInteger(), started["nameServer"]["pid"].toInteger());
    QCOMPARE(again["manager"]["pid"].toInteger(), started["manager"]["pid"].toInteger());

    QCOMPARE(local("stop").code, 0);
    // Both processes are gone (the detached processes are reaped by init).
    for (const char *process : {"manager", "nameServer"}) {
        const auto pid = pid_t(started[process]["pid"].toInteger());
        QTRY_VERIFY_WITH_TIMEOUT(::kill(pid, 0) != 0, 10000);
    }
    QCOMPARE(local("status").code, 1);
}

void TestLocalRuntime::restartsWhenHalfOfItDied()
{
    const QJsonObject started = state("start");
    QVERIFY(started["running"].toBool());
    const qint64 manager = started["manager"]["pid"].toInteger();
    ::kill(pid_t(manager), SIGKILL);
    QTRY_COMPARE_WITH_TIMEOUT(local("status").code, 1, 10000);
    const QJsonObject status = local("status").json().object();
    QVERIFY(status["nameServer"]["running"].toBool());
    QVERIFY(!status["manager"]["running"].toBool());

    const QJsonObject restarted = state("start");
    QVERIFY(restarted["running"].toBool());
    QVERIFY(restarted["manager"]["pid"].toInteger() != manager);
    QCOMPARE(local("stop").code, 0);
}

void TestLocalRuntime::takenPortsAreSkipped()
{
    // Whatever holds 2809 and 2810 (this socket, or a runtime of the machine's user), ours moves on.
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_port = htons(2809);
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    const bool holding = ::bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0
        && ::listen(fd, 1) == 0;
    const QJsonObject started = state("start");
    ::close(fd);
    QVERIFY(started["running"].toBool());
    if (holding)
        QVERIFY(started["nameServer"]["port"].toInt() > 2809);
    QVERIFY(started["manager"]["port"].toInt() != started["nameServer"]["port"].toInt());
    QCOMPARE(local("stop").code, 0);
}

void TestLocalRuntime::deploymentShowsProgressOnATerminal()
{
    const QString script = QStandardPaths::findExecutable("script");
    if (script.isEmpty())
        QSKIP("skipped: no script(1) to give rtctl a terminal (Debian's util-linux)");
    const QJsonObject started = state("start");
    QVERIFY(started["running"].toBool());
    const QStringList arguments {"resurrect", "--create", "-s",
                                 QStringLiteral("127.0.0.1:%1").arg(started["nameServer"]["port"].toInt()), "-m",
                                 QStringLiteral("corbaloc::127.0.0.1:%1").arg(started["manager"]["port"].toInt()),
                                 RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml")};
    // On a terminal (script's pseudo-terminal) each step under way stands on the line until it is done.
    QProcess terminal;
    terminal.start(script, {"-qec", (RTCTL_PATH + QStringLiteral(" ")) + arguments.join(' '), "/dev/null"});
    QVERIFY(terminal.waitForFinished(60000));
    const QString shown = QString::fromUtf8(terminal.readAllStandardOutput());
    QVERIFY2(shown.contains("\r\033[K… create ConsoleIn0\r\033[Kdone create ConsoleIn0"), qPrintable(shown));
    // Into a pipe, only the finished steps.
    const RtctlResult piped = runRtctl(QStringList {"teardown"} + arguments.mid(2, 4) + arguments.mid(6));
    QVERIFY2(piped.code == 0, qPrintable(piped.err));
    QVERIFY(!piped.out.contains("\033[K") && !piped.out.contains("…"));
    QCOMPARE(local("stop").code, 0);
}

QTEST_GUILESS_MAIN(TestLocalRuntime)
#include "tst_localruntime.moc"
