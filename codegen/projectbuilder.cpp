// SPDX-License-Identifier: MIT
#include "projectbuilder.h"

#include "installation.h"
#include "pythonproject.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <utility>

#ifdef Q_OS_UNIX
#include <signal.h>
#include <unistd.h>
#endif

using namespace Profile;

namespace Codegen {

namespace {

/// How long a cancelled build may take to end on SIGTERM before its processes are killed.
constexpr int killDelayMs = 2000;

QString nativePath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

QString resolved(const QString &file, const QString &baseDir)
{
    return QDir::cleanPath(QDir(baseDir).absoluteFilePath(file));
}

QString withoutColours(QString line)
{
    static const QRegularExpression escape(QStringLiteral("\x1b\\[[0-9;]*[A-Za-z]"));
    return line.remove(escape);
}

} // namespace

QString BuildOptions::effectiveBuildDir() const
{
    return buildDir.isEmpty() ? QDir(projectDir).filePath(QStringLiteral("build")) : buildDir;
}

ProjectBuilder::ProjectBuilder(QObject *parent)
    : QObject(parent)
    , m_killTimer(new QTimer(this))
{
    m_killTimer->setSingleShot(true);
    m_killTimer->setInterval(killDelayMs);
    connect(m_killTimer, &QTimer::timeout, this, [this] { signalProcessGroup(SIGKILL); });
}

ProjectBuilder::~ProjectBuilder()
{
    // Nothing may outlive the builder: a build left running would hold the folder.
    if (isRunning() && m_process) {
        m_process->disconnect(this);
        signalProcessGroup(SIGKILL);
        m_process->waitForFinished(killDelayMs);
    }
}

QString ProjectBuilder::cmakeProgram() const
{
    return m_cmake.isEmpty() ? QStandardPaths::findExecutable(QStringLiteral("cmake")) : m_cmake;
}

bool ProjectBuilder::isRunning() const
{
    return m_step != Step::Idle;
}

bool ProjectBuilder::start(const BuildOptions &options)
{
    if (isRunning())
        return false;
    m_options = options;
    m_options.projectDir = QDir::cleanPath(QDir(options.projectDir).absolutePath());
    m_options.buildDir = QDir::cleanPath(QDir(m_options.effectiveBuildDir()).absolutePath());
    m_problems.clear();
    m_cmakeMessage.reset();
    m_pending.clear();
    m_cancelled = false;
    m_registered.clear();
    const QString folder = nativePath(m_options.projectDir);
    m_python = PythonProject::inFolder(m_options.projectDir);
    if (m_python) {
        // Nothing to compile but the project's own IDL; the module is checked by loading it
        // into a manager process of its own, as Run in Manager will.
        m_plan = {Step::CheckModule};
        if (!m_python->ownIdlFiles().isEmpty())
            m_plan.prepend(Step::CompileIdl);
        runStep(m_plan.takeFirst());
        return true;
    }
    if (!QFileInfo::exists(QDir(m_options.projectDir).filePath(QStringLiteral("CMakeLists.txt")))) {
        const QString message
            = tr("%1 has no CMakeLists.txt nor a Python component; generate the project first.").arg(folder);
        m_problems << Diagnostic::error(m_options.projectDir, 0, 0, message);
        emit problem(m_problems.last());
        emit finished(false, message);
        return false;
    }
    if (cmakeProgram().isEmpty()) {
        const QString message = tr("Cannot build %1: cmake was not found.").arg(folder);
        emit finished(false, message);
        return false;
    }
    m_plan = {Step::Build};
    runStep(Step::Configure);
    return true;
}

QStringList ProjectBuilder::stepCommand(Step step, QString *program) const
{
    *program = cmakeProgram();
    QStringList arguments;
    if (step == Step::CompileIdl) {
        *program = QStringLiteral("sh");
        arguments << m_python->idlCompileScript();
    } else if (step == Step::CheckModule) {
        // The manager prints the component types the module registers, or why it does not load.
        *program = Installation::managerProgram();
        arguments << QStringLiteral("--module-profile") << m_python->modulePath();
    } else if (step == Step::Configure) {
        arguments << QStringLiteral("-S") << m_options.projectDir << QStringLiteral("-B")
                  << m_options.buildDir
                  << QStringLiteral("-DCMAKE_BUILD_TYPE=") + m_options.configuration;
        if (!m_options.prefixPath.isEmpty())
            arguments << QStringLiteral("-DCMAKE_PREFIX_PATH=") + m_options.prefixPath;
    } else {
        const int jobs = m_options.jobs > 0 ? m_options.jobs : qMax(1, QThread::idealThreadCount());
        arguments << QStringLiteral("--build") << m_options.buildDir
                  << QStringLiteral("-j%1").arg(jobs) << QStringLiteral("--config")
                  << m_options.configuration;
        if (m_options.clean)
            arguments << QStringLiteral("--clean-first");
    }
    return arguments;
}

void ProjectBuilder::runStep(Step step)
{
    m_step = step;
    QString program;
    const QStringList arguments = stepCommand(step, &program);
    if (step != Step::Build)
        emit progress(0, 0);
    auto *process = new QProcess(this);
    m_process = process;
    process->setProcessChannelMode(QProcess::MergedChannels);
    process->setWorkingDirectory(stepDir());
    // Compiler messages are parsed, so they must not be translated; the rest of the locale
    // (file name encoding) stays the user's.
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("LC_ALL"));
    environment.insert(QStringLiteral("LC_MESSAGES"), QStringLiteral("C"));
    // A Python project's idlcompile.sh runs this installation's IDL compiler, unless told otherwise.
    if (step == Step::CompileIdl && !environment.contains(QStringLiteral("RTCTL")))
        environment.insert(QStringLiteral("RTCTL"), Installation::rtctlProgram());
    process->setProcessEnvironment(environment);
#ifdef Q_OS_UNIX
    // A group of its own, so that cancel() reaches make/ninja and the compilers too.
    process->setChildProcessModifier([] { ::setpgid(0, 0); });
#endif
    connect(process, &QProcess::started, this,
            [this, process] { m_processGroup = process->processId(); });
    connect(process, &QProcess::readyRead, this, &ProjectBuilder::readOutput);
    connect(process, &QProcess::finished, this, &ProjectBuilder::stepFinished);
    connect(process, &QProcess::errorOccurred, this, [this, process](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart && process == m_process)
            stepFinished(-1, QProcess::CrashExit);
    });
    emit output(QStringLiteral("$ %1 %2").arg(program, arguments.join(QLatin1Char(' '))));
    process->start(program, arguments);
}

QString ProjectBuilder::stepDir() const
{
    // CMake names files relative to the source folder; compilers run in the build folder; a
    // Python module runs where its generated code expects its IDL modules (sys.path ".").
    return m_step == Step::Build ? m_options.buildDir : m_options.projectDir;
}

void ProjectBuilder::readOutput()
{
    if (!m_process)
        return;
    m_pending += m_process->readAll();
    qsizetype end;
    while ((end = m_pending.indexOf('\n')) >= 0) {
        QByteArray line = m_pending.left(end);
        m_pending.remove(0, end + 1);
        if (line.endsWith('\r'))
            line.chop(1);
        handleLine(QString::fromLocal8Bit(line));
    }
}

void ProjectBuilder::handleLine(const QString &line)
{
    emit output(line);
    const QString plain = withoutColours(line);
    if (m_step == Step::CheckModule) {
        handleModuleLine(plain);
        return;
    }
    if (handleCMakeMessage(plain))
        return;
    if (const std::optional<BuildProgress> step = parseProgressLine(plain))
        emit progress(step->done, step->total);
    if (std::optional<Diagnostic> found = parseProblemLine(plain, stepDir())) {
        m_problems << *found;
        emit problem(*found);
    }
}

bool ProjectBuilder::handleCMakeMessage(const QString &line)
{
    // `CMake Error at CMakeLists.txt:12 (add_executable):` and its message: indented
    // paragraphs, up to the next line that is not indented.
    static const QRegularExpression header(QStringLiteral(
        "^CMake (Error|Warning)(?: \\(dev\\))?(?: (?:at|in) (.+?)(?::(\\d+))?(?: \\([^)]*\\))?)?:"
        "\\s*(.*)$"));
    const QRegularExpressionMatch match = header.match(line);
    if (match.hasMatch()) {
        flushCMakeMessage();
        const bool error = match.captured(1) == QLatin1String("Error");
        const QString file = match.captured(2).isEmpty()
            ? QString()
            : resolved(match.captured(2), m_options.projectDir);
        const int lineNumber = match.captured(3).toInt();
        m_cmakeMessage = error
            ? Diagnostic::error(file, lineNumber, 0, match.captured(4).trimmed())
            : Diagnostic::warning(file, lineNumber, 0, match.captured(4).trimmed());
        return true;
    }
    if (!m_cmakeMessage)
        return false;
    const bool indented = line.startsWith(QLatin1Char(' ')) || line.startsWith(QLatin1Char('\t'));
    if (indented && !line.trimmed().isEmpty()) {
        QString &message = m_cmakeMessage->message;
        message += (message.isEmpty() ? QString() : QStringLiteral(" ")) + line.trimmed();
        return true;
    }
    if (line.trimmed().isEmpty())
        return true;
    flushCMakeMessage();
    return false;
}

void ProjectBuilder::handleModuleLine(const QString &line)
{
    static const QRegularExpression registered(QStringLiteral("^\\d+\\.implementation_id: (.*)$"));
    const QRegularExpressionMatch match = registered.match(line);
    if (match.hasMatch())
        m_registered << match.captured(1).trimmed();
    if (std::optional<Diagnostic> found = PythonProject::parseLoadProblem(line)) {
        m_problems << *found;
        emit problem(*found);
    }
}

void ProjectBuilder::flushCMakeMessage()
{
    if (!m_cmakeMessage)
        return;
    const Diagnostic found = *m_cmakeMessage;
    m_cmakeMessage.reset();
    m_problems << found;
    emit problem(found);
}

void ProjectBuilder::stepFinished(int exitCode, QProcess::ExitStatus status)
{
    QProcess *process = m_process;
    if (!process || m_step == Step::Idle)
        return;
    readOutput();
    if (!m_pending.isEmpty()) {
        const QByteArray rest = std::exchange(m_pending, QByteArray());
        handleLine(QString::fromLocal8Bit(rest));
    }
    flushCMakeMessage();
    m_killTimer->stop();
    const bool failedToStart = process->error() == QProcess::FailedToStart;
    const QString processError = process->errorString();
    process->deleteLater();
    m_process.clear();
    if (m_cancelled)
        signalProcessGroup(SIGKILL);
    m_processGroup = 0;
    const QString folder = nativePath(m_options.projectDir);
    if (m_cancelled) {
        finish(false, tr("Build of %1 cancelled.").arg(folder));
    } else if (failedToStart) {
        finish(false, tr("Cannot build %1: %2").arg(folder, processError));
    } else if (status != QProcess::NormalExit || exitCode != 0) {
        finish(false, failureMessage(exitCode));
    } else if (!m_plan.isEmpty()) {
        runStep(m_plan.takeFirst());
    } else if (m_python) {
        finishPythonCheck();
    } else {
        finish(true, tr("Built %1 into %2.").arg(folder, nativePath(m_options.buildDir)));
    }
}

void ProjectBuilder::finishPythonCheck()
{
    const QString module = nativePath(m_python->modulePath());
    if (!m_registered.contains(m_python->componentName())) {
        const QString message = tr("%1 loads but does not register the component type %2 in %3().")
                                    .arg(module, m_python->componentName(), m_python->initFunction());
        m_problems << Diagnostic::error(m_python->modulePath(), 0, 0, message);
        emit problem(m_problems.last());
        finish(false, message);
        return;
    }
    finish(true, tr("Checked %1: it loads into a manager and registers %2.").arg(module, m_registered.join(QStringLiteral(", "))));
}

QString ProjectBuilder::failureMessage(int exitCode) const
{
    const QString folder = nativePath(m_options.projectDir);
    const auto isError
        = [](const Diagnostic &d) { return d.severity == Diagnostic::Severity::Error; };
    const int errors = int(std::count_if(m_problems.cbegin(), m_problems.cend(), isError));
    if (m_step == Step::CompileIdl)
        return tr("Compiling the IDL of %1 to Python failed (exit code %2).").arg(folder).arg(exitCode);
    if (m_step == Step::CheckModule) {
        return errors > 0 ? tr("Checking %1 failed with %n error(s).", nullptr, errors).arg(folder)
                          : tr("Checking %1 failed (exit code %2).").arg(folder).arg(exitCode);
    }
    const bool configuring = m_step == Step::Configure;
    if (errors > 0)
        return (configuring ? tr("Configuring %1 failed with %n error(s).", nullptr, errors)
                            : tr("Building %1 failed with %n error(s).", nullptr, errors))
            .arg(folder);
    return (configuring ? tr("Configuring %1 failed (exit code %2).")
                        : tr("Building %1 failed (exit code %2)."))
        .arg(folder)
        .arg(exitCode);
}

void ProjectBuilder::finish(bool ok, const QString &message)
{
    m_step = Step::Idle;
    emit output(message);
    emit finished(ok, message);
}

void ProjectBuilder::cancel()
{
    if (!isRunning() || m_cancelled)
        return;
    m_cancelled = true;
    signalProcessGroup(SIGTERM);
    m_killTimer->start();
}

void ProjectBuilder::signalProcessGroup(int signal)
{
#ifdef Q_OS_UNIX
    // After the group leader (cmake) ended, what it left behind still belongs to its group.
    if (m_processGroup > 0) {
        ::kill(-pid_t(m_processGroup), signal);
        return;
    }
#endif
    if (!m_process)
        return;
    if (signal == SIGKILL)
        m_process->kill();
    else
        m_process->terminate();
}

std::optional<Diagnostic> ProjectBuilder::parseProblemLine(const QString &line,
                                                           const QString &baseDir)
{
    // GCC and Clang: `src/a.cpp:12:5: error: …`, `a.h:3: warning: …`, `fatal error:` too.
    static const QRegularExpression compiler(
        QStringLiteral("^(.+?):(\\d+)(?::(\\d+))?:\\s+(?:fatal\\s+)?(error|warning):\\s*(.*)$"));
    const QRegularExpressionMatch match = compiler.match(withoutColours(line));
    if (!match.hasMatch())
        return std::nullopt;
    const QString file = resolved(match.captured(1).trimmed(), baseDir);
    const int lineNumber = match.captured(2).toInt();
    const int column = match.captured(3).toInt();
    const QString message = match.captured(5).trimmed();
    if (match.captured(4) == QLatin1String("error"))
        return Diagnostic::error(file, lineNumber, column, message);
    return Diagnostic::warning(file, lineNumber, column, message);
}

std::optional<BuildProgress> ProjectBuilder::parseProgressLine(const QString &line)
{
    static const QRegularExpression ninja(QStringLiteral("^\\[(\\d+)/(\\d+)\\]"));
    static const QRegularExpression make(QStringLiteral("^\\[\\s*(\\d+)%\\]"));
    QRegularExpressionMatch match = ninja.match(line);
    if (match.hasMatch())
        return BuildProgress {match.captured(1).toInt(), match.captured(2).toInt()};
    match = make.match(line);
    if (match.hasMatch())
        return BuildProgress {match.captured(1).toInt(), 100};
    return std::nullopt;
}

QString ProjectBuilder::defaultSdkPrefix()
{
    return Installation::prefix();
}

} // namespace Codegen
