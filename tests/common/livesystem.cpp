// SPDX-License-Identifier: MIT
#include "livesystem.h"

#include "tlsarguments.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QTest>
#include <QThread>

#include <arpa/inet.h>
#include <csignal>
#include <netinet/in.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

namespace LiveTest {

namespace {

sockaddr_in loopback(quint16 port)
{
    sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return address;
}

bool accepts(const sockaddr_in &address)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0)
        return false;
    const bool connected
        = ::connect(fd, reinterpret_cast<const sockaddr *>(&address), sizeof(address)) == 0;
    ::close(fd);
    return connected;
}

// A test killed by its time limit or a crash never reaches stopAll(); the kernel then ends the
// servers it started (even SIGSTOPped ones) instead of leaving them behind.
void prepareChild(QProcess &process, const std::function<void()> &enterChild)
{
    process.setChildProcessModifier([enterChild] {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (enterChild)
            enterChild();
    });
}

} // namespace

quint16 freePort()
{
    // Below the kernel's range for the local ports of outgoing connections: a port the kernel
    // handed out for binding to port 0 could be given to another test's connection before the
    // server this port is for binds it (omniORB then fails with "Address in use").
    int ephemeralLow = 32768;
    QFile range(QStringLiteral("/proc/sys/net/ipv4/ip_local_port_range"));
    if (range.open(QIODevice::ReadOnly))
        ephemeralLow = QString::fromLatin1(range.readAll()).split(QLatin1Char('\t')).value(0).trimmed().toInt();
    const int low = 10000;
    const int high = qMax(low + 1000, ephemeralLow);
    for (int attempt = 0; attempt < 100; ++attempt) {
        const quint16 port = quint16(QRandomGenerator::global()->bounded(low, high));
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        if (fd < 0)
            return 0;
        const sockaddr_in address = loopback(port);
        const bool bound = ::bind(fd, reinterpret_cast<const sockaddr *>(&address), sizeof(address)) == 0;
        ::close(fd);
        if (bound)
            return port;
    }
    return 0;
}

bool isListening(quint16 port)
{
    return accepts(loopback(port));
}

bool isListening(const QString &address, quint16 port)
{
    sockaddr_in target = loopback(port);
    return ::inet_pton(AF_INET, address.toLatin1().constData(), &target.sin_addr) == 1
        && accepts(target);
}

bool waitUntilStopped(qint64 pid, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (!deadline.hasExpired()) {
        const QDir tasks(QStringLiteral("/proc/%1/task").arg(pid));
        bool allStopped = true;
        for (const QString &task : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
            QFile stat(tasks.filePath(task) + QStringLiteral("/stat"));
            if (!stat.open(QIODevice::ReadOnly))
                continue;
            const QByteArray text = stat.readAll();
            const int close = text.lastIndexOf(')');
            allStopped
                = allStopped && close > 0 && text.size() > close + 2 && text.at(close + 2) == 'T';
        }
        if (allStopped)
            return true;
        QThread::yieldCurrentThread();
    }
    return false;
}

LiveSystem::LiveSystem(LiveHost host)
    : m_host(std::move(host))
{ }

LiveSystem::~LiveSystem()
{
    stopAll();
}

QByteArray managerLocation(quint16 port)
{
    return QStringLiteral("corbaloc:iiop:127.0.0.1:%1/manager").arg(port).toUtf8();
}

QProcessEnvironment openRtmEnvironment(const QString &prefix)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const auto &[name, folder] : {std::pair {QStringLiteral("LD_LIBRARY_PATH"), QStringLiteral("/lib")},
                                       std::pair {QStringLiteral("PATH"), QStringLiteral("/bin")}}) {
        const QString before = environment.value(name);
        environment.insert(name, prefix + folder + (before.isEmpty() ? QString() : QLatin1Char(':') + before));
    }
    return environment;
}

void useOpenRtm(const QString &prefix)
{
    const QProcessEnvironment environment = openRtmEnvironment(prefix);
    for (const char *name : {"LD_LIBRARY_PATH", "PATH"})
        qputenv(name, environment.value(QString::fromLatin1(name)).toLocal8Bit());
}

QList<qint64> childProcesses(qint64 parent)
{
    QList<qint64> children;
    const QStringList entries = QDir(QStringLiteral("/proc")).entryList(QDir::Dirs);
    for (const QString &entry : entries) {
        bool ok = false;
        const qint64 pid = entry.toLongLong(&ok);
        QFile stat(QStringLiteral("/proc/%1/stat").arg(entry));
        if (!ok || !stat.open(QIODevice::ReadOnly))
            continue;
        // "pid (comm) state ppid ...": comm may hold spaces, so fields count from the last ')'.
        const QByteArray text = stat.readAll();
        const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
        if (fields.size() > 1 && fields[1].toLongLong() == parent)
            children.append(pid);
    }
    return children;
}

QString LiveSystem::namingServer() const
{
    return QStringLiteral("%1:%2").arg(m_host.address).arg(m_namingPort);
}

bool LiveSystem::startNameServer(QString *error, quint16 port)
{
    m_namingPort = port ? port : freePort();
    return startOmniNames({QStringLiteral("-ORBendPoint"), QStringLiteral("giop:tcp:") + namingServer()},
                          QProcessEnvironment::systemEnvironment(), error);
}

bool LiveSystem::startTlsNameServer(const QString &caFile, const QString &keyFile, QString *error)
{
    m_namingPort = freePort();
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const auto &[name, value] :
         Tls::nameServerEnvironment({caFile.toStdString(), keyFile.toStdString(), {}}))
        environment.insert(QString::fromStdString(name), QString::fromStdString(value));
    QStringList arguments;
    for (const std::string &argument : Tls::nameServerArguments(namingServer().toStdString()))
        arguments << QString::fromStdString(argument);
    return startOmniNames(arguments, environment, error);
}

bool LiveSystem::startOmniNames(const QStringList &endpointArguments, const QProcessEnvironment &environment,
                                QString *error)
{
    const QString program = QStandardPaths::findExecutable(QStringLiteral("omniNames"));
    if (program.isEmpty()) {
        *error = QStringLiteral("omniNames is not installed (package omniorb-nameserver)");
        return false;
    }
    m_dataDir = std::make_unique<QTemporaryDir>();
    auto process = std::make_unique<QProcess>();
    prepareChild(*process, m_host.enterChild);
    process->setProcessChannelMode(QProcess::MergedChannels);
    process->setProcessEnvironment(environment);
    process->start(program, QStringList {QStringLiteral("-start"), QString::number(m_namingPort),
                                         QStringLiteral("-datadir"), m_dataDir->path(), QStringLiteral("-logdir"),
                                         m_dataDir->path()}
                                + endpointArguments);
    if (!process->waitForStarted(10000)) {
        *error = QStringLiteral("omniNames did not start: %1").arg(process->errorString());
        return false;
    }
    m_nameServer = process.get();
    m_processes.push_back(std::move(process));
    // Readiness is "accepts connections"; between attempts wait on the server's own output.
    const QDeadlineTimer deadline(20000);
    while (!isListening(m_host.address, m_namingPort)) {
        if (deadline.hasExpired() || m_nameServer->state() != QProcess::Running) {
            *error = QStringLiteral("omniNames is not listening on %1: %2")
                         .arg(namingServer(), QString::fromLocal8Bit(m_nameServer->readAll()));
            return false;
        }
        m_nameServer->waitForReadyRead(20);
    }
    return true;
}

QProcess *LiveSystem::startPeer(const QStringList &components, QString *error, quint16 *port,
                                const QString &host, bool zombies)
{
    const quint16 peerPort = freePort();
    if (port)
        *port = peerPort;
    QStringList arguments {QStringLiteral("--naming"), QString::number(m_namingPort),
                           QStringLiteral("--port"),   QString::number(peerPort),
                           QStringLiteral("--host"),   host};
    if (zombies)
        arguments << QStringLiteral("--zombies");
    arguments += components;
    return startProcess(RTSTUDIO_LIVEPEER_PATH, arguments, QStringLiteral("ready"),
                        error);
}

QProcess *LiveSystem::startManager(const QString &program, quint16 port, const QStringList &options,
                                   QString *error)
{
    // The tests load the modules they build where they build them, as a developer's own manager
    // (the local runtime) does; tst_managerlive proves the default refusal. `options` may say NO.
    QStringList arguments {QStringLiteral("-d"), QStringLiteral("-o"),
                           QStringLiteral("corba.endpoints=%1:%2").arg(m_host.address).arg(port),
                           QStringLiteral("-o"), QStringLiteral("manager.modules.abs_path_allowed=YES")};
    for (const QString &option : options)
        arguments << QStringLiteral("-o") << option;
    return startProcess(program, arguments, QStringLiteral("rtmanager ready"), error);
}

QProcess *LiveSystem::startHostManager(const QString &program, quint16 port, const QString &host,
                                       const QStringList &options, QString *error)
{
    return startManager(program, port,
                        QStringList {QStringLiteral("corba.nameservers=") + namingServer(),
                                     QStringLiteral("naming.formats=%1.host_cxt/%n.rtc").arg(host),
                                     QStringLiteral("manager.naming_formats=%1.host_cxt/%n.mgr").arg(host)}
                            + options,
                        error);
}

QProcess *LiveSystem::startRtcdMaster(const QString &prefix, const QString &confFile, quint16 masterPort,
                                      const QString &host, const QStringList &extraLines, QString *error)
{
    QFile conf(confFile);
    if (!conf.open(QIODevice::WriteOnly | QIODevice::Text)) {
        *error = confFile + QStringLiteral(": ") + conf.errorString();
        return nullptr;
    }
    const QStringList lines = QStringList {QStringLiteral("corba.nameservers: ") + namingServer(),
                                           QStringLiteral("corba.endpoints: 127.0.0.1:"),
                                           QStringLiteral("corba.master_manager: 127.0.0.1:%1").arg(masterPort),
                                           QStringLiteral("manager.is_master: YES"),
                                           QStringLiteral("naming.formats: %1.host_cxt/%n.rtc").arg(host),
                                           QStringLiteral("manager.naming_formats: %1.host_cxt/%n.mgr").arg(host),
                                           QStringLiteral("manager.modules.C++.manager_cmd: %1/bin/rtcd2").arg(prefix),
                                           QStringLiteral("logger.enable: NO")}
                              + extraLines;
    conf.write((lines.join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8());
    conf.close();
    // rtcd2 starts its slaves with the same environment.
    QProcess *master = startProcess(prefix + QStringLiteral("/bin/rtcd2"), {QStringLiteral("-f"), confFile},
                                    QString(), error, 0, openRtmEnvironment(prefix));
    if (master)
        m_rtcdMasters.insert(master);
    return master;
}

QProcess *LiveSystem::startOpenRtmExample(const QString &prefix, const QString &program, const QString &context,
                                          QString *error, const QStringList &options, const QStringList &arguments)
{
    QStringList all = arguments;
    for (const QString &option : QStringList {QStringLiteral("corba.nameservers:") + namingServer(),
                                              QStringLiteral("corba.endpoints:%1:").arg(m_host.address),
                                              QStringLiteral("naming.formats:%1.host_cxt/%n.rtc").arg(context),
                                              QStringLiteral("manager.corba_servant:NO"),
                                              QStringLiteral("logger.enable:NO")}
                                     + options)
        all << QStringLiteral("-o") << option;
    return startProcess(prefix + QStringLiteral("/share/openrtm-2.1/components/c++/examples/") + program, all,
                        QString(), error, 0, openRtmEnvironment(prefix));
}

QString PrintedOutput::of(QProcess *process)
{
    QString &text = m_text[process];
    text += QString::fromLocal8Bit(process->readAllStandardOutput());
    return text;
}

QProcess *LiveSystem::startRegistered(const QString &program, const QStringList &arguments,
                                      const std::function<bool()> &registered, QString *error,
                                      int timeoutMs, const QProcessEnvironment &environment)
{
    QProcess *process = startProcess(program, arguments, QString(), error, timeoutMs, environment);
    if (!process)
        return nullptr;
    const QDeadlineTimer deadline(timeoutMs);
    while (!registered()) {
        if (deadline.hasExpired() || process->state() == QProcess::NotRunning) {
            *error = QStringLiteral("%1 did not register: %2")
                         .arg(program, QString::fromLocal8Bit(process->readAllStandardOutput()));
            return nullptr;
        }
        QTest::qWait(50);
    }
    return process;
}

QProcess *LiveSystem::startProcess(const QString &program, const QStringList &arguments,
                                   const QString &readyText, QString *error, int timeoutMs,
                                   const QProcessEnvironment &environment)
{
    auto process = std::make_unique<QProcess>();
    prepareChild(*process, m_host.enterChild);
    if (!environment.isEmpty())
        process->setProcessEnvironment(environment);
    process->setProcessChannelMode(m_errorsRead ? QProcess::MergedChannels : QProcess::ForwardedErrorChannel);
    process->start(program, arguments);
    QProcess *raw = process.get();
    m_processes.push_back(std::move(process));
    // Without this, state() can say Starting long after the program runs when no ready text is
    // awaited: only an event loop or a wait notices that the start succeeded.
    if (!raw->waitForStarted(10000)) {
        *error = QStringLiteral("%1 did not start: %2").arg(program, raw->errorString());
        return nullptr;
    }
    QByteArray output;
    const QDeadlineTimer deadline(timeoutMs);
    while (!output.contains(readyText.toUtf8())) {
        if (deadline.hasExpired() || raw->state() == QProcess::NotRunning) {
            *error = QStringLiteral("%1 did not become ready: %2 %3")
                         .arg(program, raw->errorString(), QString::fromLocal8Bit(output));
            return nullptr;
        }
        if (raw->waitForReadyRead(int(qMax<qint64>(1, deadline.remainingTime()))))
            output += raw->readAllStandardOutput();
    }
    m_startOutput.insert(raw, output);
    return raw;
}

void LiveSystem::stop(QProcess *process)
{
    if (!process)
        return;
    if (process->state() != QProcess::NotRunning) {
        // Before the master: once it is gone they are no longer known as its children.
        if (m_rtcdMasters.count(process) > 0) {
            for (qint64 pid : childProcesses(process->processId()))
                ::kill(pid_t(pid), SIGKILL);
        }
        process->kill();
        process->waitForFinished(10000);
    }
    m_rtcdMasters.erase(process);
}

void LiveSystem::stopAll()
{
    for (auto it = m_processes.rbegin(); it != m_processes.rend(); ++it)
        stop(it->get());
    m_processes.clear();
    m_startOutput.clear();
    m_nameServer = nullptr;
}

} // namespace LiveTest
