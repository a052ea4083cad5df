// SPDX-License-Identifier: MIT
#include "localruntime.h"

#include "certificateauthority.h"
#include "tlstransport.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSaveFile>
#include <QStandardPaths>
#include <QThread>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

namespace Deploy {

namespace {

constexpr quint16 DefaultNamingPort = 2809;
constexpr quint16 DefaultManagerPort = 2810;

sockaddr_in address(quint16 port, in_addr_t host)
{
    sockaddr_in result {};
    result.sin_family = AF_INET;
    result.sin_port = htons(port);
    result.sin_addr.s_addr = htonl(host);
    return result;
}

bool listening(quint16 port)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0)
        return false;
    sockaddr_in to = address(port, INADDR_LOOPBACK);
    const bool connected = ::connect(fd, reinterpret_cast<sockaddr *>(&to), sizeof to) == 0;
    ::close(fd);
    return connected;
}

/// True when a server could listen on `port` on every interface.
bool portIsFree(quint16 port)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0)
        return false;
    const int yes = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in at = address(port, INADDR_ANY);
    const bool bound = ::bind(fd, reinterpret_cast<sockaddr *>(&at), sizeof at) == 0;
    ::close(fd);
    return bound;
}

quint16 firstFree(quint16 from, quint16 taken)
{
    for (quint16 port = from; port < from + 200; ++port) {
        if (port != taken && portIsFree(port))
            return port;
    }
    return 0;
}

/// The process lives and is the program we started (not another one that got its pid).
bool alive(qint64 pid, const QString &program)
{
    if (pid <= 0 || (::kill(pid_t(pid), 0) != 0 && errno != EPERM))
        return false;
    QFile cmdline(QStringLiteral("/proc/%1/cmdline").arg(pid));
    return !cmdline.open(QIODevice::ReadOnly) || cmdline.readAll().contains(program.toLocal8Bit());
}

LocalProcess readProcess(const QJsonObject &object, const QString &program)
{
    LocalProcess process;
    process.pid = object.value(QStringLiteral("pid")).toInteger();
    process.port = quint16(object.value(QStringLiteral("port")).toInt());
    process.running = alive(process.pid, program) && listening(process.port);
    return process;
}

QJsonObject writeProcess(const LocalProcess &process)
{
    return {{QStringLiteral("pid"), process.pid}, {QStringLiteral("port"), process.port}};
}

/// Starts `program` detached with its output in `log`; 0 when it did not start.
qint64 startDetached(const QString &program, const QStringList &arguments, const QString &log,
                     const QProcessEnvironment &environment)
{
    QProcess process;
    process.setProgram(program);
    process.setArguments(arguments);
    process.setProcessEnvironment(environment);
    process.setStandardInputFile(QProcess::nullDevice());
    process.setStandardOutputFile(log, QIODevice::Append);
    process.setStandardErrorFile(log, QIODevice::Append);
    qint64 pid = 0;
    return process.startDetached(&pid) ? pid : 0;
}

bool waitUntilListening(const LocalProcess &process, const QString &program, const QDeadlineTimer &deadline)
{
    while (!listening(process.port)) {
        if (deadline.hasExpired() || !alive(process.pid, program))
            return false;
        QThread::msleep(20);
    }
    return true;
}

void terminate(qint64 pid, const QString &program)
{
    if (!alive(pid, program))
        return;
    ::kill(pid_t(pid), SIGTERM);
    const QDeadlineTimer deadline(3000);
    while (alive(pid, program) && !deadline.hasExpired())
        QThread::msleep(20);
    if (alive(pid, program))
        ::kill(pid_t(pid), SIGKILL);
}

QString lastLines(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return QString();
    const QStringList lines = QString::fromLocal8Bit(file.readAll()).trimmed().split(QLatin1Char('\n'));
    return lines.mid(qMax(0, int(lines.size()) - 3)).join(QLatin1Char(' '));
}

const QString NameServerProgram = QStringLiteral("omniNames");
const QString ManagerProgram = QStringLiteral("rtmanager");

} // namespace

QString LocalRuntimeState::nameServerAddress() const
{
    return QStringLiteral("127.0.0.1:%1").arg(nameServer.port);
}

QString LocalRuntimeState::managerAddress() const
{
    return QStringLiteral("corbaloc:iiop:127.0.0.1:%1/manager").arg(manager.port);
}

QString LocalRuntime::defaultFolder()
{
    // Without XDG_RUNTIME_DIR Qt would pick a folder of its own and say so on standard error, in
    // every rtctl command (each looks whether the local runtime runs with TLS).
    if (!qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        const QString runtime = QStandardPaths::writableLocation(QStandardPaths::RuntimeLocation);
        if (!runtime.isEmpty())
            return QDir(runtime).filePath(QStringLiteral("rtstudio"));
    }
    return QDir::temp().filePath(QStringLiteral("rtstudio-%1").arg(::getuid()));
}

LocalRuntime::LocalRuntime(const QString &folder)
    : m_folder(folder)
{ }

QString LocalRuntime::statePath() const
{
    return QDir(m_folder).filePath(QStringLiteral("state.json"));
}

QJsonObject LocalRuntime::readStateFile() const
{
    QFile file(statePath());
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

LocalRuntimeState LocalRuntime::status() const
{
    LocalRuntimeState state;
    state.folder = m_folder;
    const QJsonObject object = readStateFile();
    state.nameServer = readProcess(object.value(QStringLiteral("nameServer")).toObject(), NameServerProgram);
    state.manager = readProcess(object.value(QStringLiteral("manager")).toObject(), ManagerProgram);
    state.tls = object.value(QStringLiteral("tls")).toBool();
    return state;
}

LocalRuntimeTls LocalRuntime::tls() const
{
    LocalRuntimeTls files;
    const CertificateAuthority authority(QDir(m_folder).filePath(QStringLiteral("tls")));
    // Every rtctl command asks this before its first call: the state file and the manager's process
    // tell without a connection to either port.
    const QJsonObject object = readStateFile();
    const qint64 managerPid = object.value(QStringLiteral("manager")).toObject().value(QStringLiteral("pid")).toInteger();
    files.enabled = object.value(QStringLiteral("tls")).toBool() && alive(managerPid, ManagerProgram);
    files.certificateAuthorityFile = authority.certificatePath();
    files.nodeKeyFile = authority.issuedPath(QStringLiteral("localhost"));
    files.userKeyFile = authority.issuedPath(QStringLiteral("user"));
    return files;
}

bool LocalRuntime::prepareTls(LocalRuntimeTls *files, QString *error) const
{
    CertificateAuthority authority(QDir(m_folder).filePath(QStringLiteral("tls")));
    const auto expired = [](const QString &path) {
        Tls::CertificateInfo info;
        std::string ignored;
        return !Tls::readCertificate(path.toStdString(), &info, &ignored) || info.expired;
    };
    if (authority.exists() && expired(authority.certificatePath()))
        QDir(QDir(m_folder).filePath(QStringLiteral("tls"))).removeRecursively();
    if (!authority.exists() && !authority.init(QStringLiteral("RT Studio local runtime"), 3650, error))
        return false;
    for (const QString &name : {QStringLiteral("localhost"), QStringLiteral("user")}) {
        if (expired(authority.issuedPath(name))
            && !authority.issue(name, 825, {QStringLiteral("127.0.0.1")}, nullptr, error))
            return false;
    }
    *files = tls();
    files->enabled = true;
    return true;
}

void LocalRuntime::writeState(const LocalRuntimeState &state) const
{
    QSaveFile file(statePath());
    if (!file.open(QIODevice::WriteOnly))
        return;
    file.write(QJsonDocument(QJsonObject {{QStringLiteral("nameServer"), writeProcess(state.nameServer)},
                                          {QStringLiteral("manager"), writeProcess(state.manager)},
                                          {QStringLiteral("tls"), state.tls}})
                   .toJson());
    file.commit();
}

LocalRuntimeState LocalRuntime::start(const QString &managerProgram, QString *error, int timeoutMs)
{
    return start(managerProgram, false, error, timeoutMs);
}

LocalRuntimeState LocalRuntime::start(const QString &managerProgram, bool tls, QString *error, int timeoutMs)
{
    LocalRuntimeState state = status();
    if (state.running() && state.tls == tls)
        return state;
    // Half a runtime (one of the two gone), or one running the other way, is started afresh.
    if (state.nameServer.running || state.manager.running)
        stop(nullptr);
    state = LocalRuntimeState();
    state.folder = m_folder;
    state.tls = tls;
    const auto fail = [&](const QString &message) {
        if (error)
            *error = message;
        stop(nullptr);
        LocalRuntimeState failed;
        failed.folder = m_folder;
        return failed;
    };

    const QString omniNames = QStandardPaths::findExecutable(NameServerProgram);
    if (omniNames.isEmpty())
        return fail(tr("omniNames is not installed (Debian package omniorb-nameserver)"));
    if (!QFileInfo(managerProgram).isExecutable())
        return fail(tr("%1: no rtmanager program there").arg(managerProgram));
    // A fresh name server each time: omniNames -start refuses a folder with an old log.
    QDir folder(m_folder);
    const QString data = folder.filePath(QStringLiteral("omninames"));
    QDir(data).removeRecursively();
    if (!folder.mkpath(QStringLiteral("omninames")))
        return fail(tr("%1: cannot create the folder").arg(data));

    const QDeadlineTimer deadline(timeoutMs);
    state.nameServer.port = firstFree(DefaultNamingPort, 0);
    state.manager.port = firstFree(DefaultManagerPort, state.nameServer.port);
    if (state.nameServer.port == 0 || state.manager.port == 0)
        return fail(tr("no free port from 2809 on"));
    LocalRuntimeTls files;
    if (tls && !prepareTls(&files, error))
        return fail(tr("cannot prepare TLS: %1").arg(*error));
    const QString namingLog = folder.filePath(QStringLiteral("omniNames.log"));
    QStringList namingArguments {QStringLiteral("-start"), QString::number(state.nameServer.port),
                                 QStringLiteral("-datadir"), data, QStringLiteral("-logdir"), data};
    QProcessEnvironment namingEnvironment = QProcessEnvironment::systemEnvironment();
    // This machine only, as the manager below.
    if (!tls)
        namingArguments << QStringLiteral("-ignoreport") << QStringLiteral("-ORBendPoint")
                        << QStringLiteral("giop:tcp:127.0.0.1:%1").arg(state.nameServer.port);
    if (tls) {
        const Tls::Settings settings {files.certificateAuthorityFile.toStdString(), files.nodeKeyFile.toStdString(), {}};
        for (const auto &[name, value] : Tls::nameServerEnvironment(settings))
            namingEnvironment.insert(QString::fromStdString(name), QString::fromStdString(value));
        for (const std::string &argument :
             Tls::nameServerArguments("127.0.0.1:" + std::to_string(state.nameServer.port)))
            namingArguments << QString::fromStdString(argument);
    }
    state.nameServer.pid = startDetached(omniNames, namingArguments, namingLog, namingEnvironment);
    writeState(state);
    if (state.nameServer.pid == 0 || !waitUntilListening(state.nameServer, NameServerProgram, deadline))
        return fail(tr("omniNames did not start on port %1: %2")
                        .arg(state.nameServer.port)
                        .arg(lastLines(namingLog)));
    state.nameServer.running = true;

    const QString managerLog = folder.filePath(QStringLiteral("rtmanager.log"));
    // The local runtime is this user's trial bench: reachable from this machine only, so it may
    // load the modules the Builder builds wherever their projects are.
    QStringList managerArguments {QStringLiteral("-d"), QStringLiteral("-o"),
                                  QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(state.manager.port),
                                  QStringLiteral("-o"), QStringLiteral("corba.nameservers=") + state.nameServerAddress(),
                                  QStringLiteral("-o"), QStringLiteral("manager.modules.abs_path_allowed=YES")};
    if (tls)
        managerArguments << QStringLiteral("-o")
                         << QStringLiteral("corba.ssl.certificate_authority_file=") + files.certificateAuthorityFile
                         << QStringLiteral("-o") << QStringLiteral("corba.ssl.key_file=") + files.nodeKeyFile;
    state.manager.pid = startDetached(managerProgram, managerArguments, managerLog,
                                      QProcessEnvironment::systemEnvironment());
    writeState(state);
    if (state.manager.pid == 0 || !waitUntilListening(state.manager, ManagerProgram, deadline))
        return fail(tr("rtmanager did not start on port %1: %2")
                        .arg(state.manager.port)
                        .arg(lastLines(managerLog)));
    state.manager.running = true;
    state.startedNow = true;
    return state;
}

bool LocalRuntime::stop(QString *error)
{
    QFile file(statePath());
    if (!file.exists())
        return true;
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(statePath(), file.errorString());
        return false;
    }
    const QJsonObject object = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    // The manager first, so that it can leave the name server while that still runs.
    terminate(object.value(QStringLiteral("manager")).toObject().value(QStringLiteral("pid")).toInteger(),
              ManagerProgram);
    terminate(object.value(QStringLiteral("nameServer")).toObject().value(QStringLiteral("pid")).toInteger(),
              NameServerProgram);
    QFile::remove(statePath());
    return true;
}

} // namespace Deploy
