// SPDX-License-Identifier: MIT
#include "sdkproject.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>

namespace SdkTest {

RunResult run(const QString &program, const QStringList &arguments, const QProcessEnvironment &environment,
              const QString &workingDirectory, int timeoutMs)
{
    constexpr int startTimeoutMs = 30 * 1000;
    QProcess process;
    process.setProcessEnvironment(environment);
    process.setWorkingDirectory(workingDirectory);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    RunResult result;
    result.finished = process.waitForStarted(startTimeoutMs) && process.waitForFinished(timeoutMs);
    if (!result.finished) {
        process.kill();
        process.waitForFinished(startTimeoutMs);
    }
    result.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    result.output = QString::fromLocal8Bit(process.readAll());
    if (!result.finished)
        result.output += QStringLiteral("\n[%1 did not finish: %2]").arg(program, process.errorString());
    return result;
}

QString failure(const QString &what, const RunResult &result)
{
    return QStringLiteral("%1 failed (exit %2):\n%3").arg(what).arg(result.exitCode).arg(result.output.right(6000));
}

bool copyTree(const QString &from, const QString &to)
{
    QDir().mkpath(to);
    const QDir source(from);
    for (const QFileInfo &entry : source.entryInfoList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden)) {
        const QString target = to + QLatin1Char('/') + entry.fileName();
        if (entry.isDir() ? !copyTree(entry.filePath(), target) : !QFile::copy(entry.filePath(), target))
            return false;
    }
    return true;
}

bool runTool(const QString &program, const QStringList &arguments, const QString &cwd, int timeoutMs, QString *log)
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("CCACHE_BASEDIR"), QDir::tempPath());
    environment.insert(QStringLiteral("CCACHE_NOHASHDIR"), QStringLiteral("true"));
    process.setProcessEnvironment(environment);
    process.setWorkingDirectory(cwd);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    const bool finished = process.waitForFinished(timeoutMs);
    *log = QString::fromLocal8Bit(process.readAll());
    if (!finished) {
        process.kill();
        process.waitForFinished(5000);
        *log += QStringLiteral("\n(%1 timed out)").arg(program);
        return false;
    }
    return process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
}

bool buildProject(const QString &dir, const QString &sdkPrefix, QString *log, const QStringList &cmakeArguments)
{
    const QString cmake = QStandardPaths::findExecutable(QStringLiteral("cmake"));
    QStringList configure{"-S", dir, "-B", dir + "/build", "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                          "-DCMAKE_PREFIX_PATH=" + sdkPrefix};
    const QString ccache = QStandardPaths::findExecutable(QStringLiteral("ccache"));
    if (!ccache.isEmpty())
        configure << "-DCMAKE_CXX_COMPILER_LAUNCHER=" + ccache;
    configure << cmakeArguments;
    return runTool(cmake, configure, dir, 120000, log)
           && runTool(cmake, {"--build", dir + "/build", "-j2"}, dir, 600000, log);
}

bool applyEdit(const QString &root, const UserEdit &edit, QString *error)
{
    QFile file(root + '/' + QString::fromUtf8(edit.file));
    if (!file.open(QIODevice::ReadOnly)) {
        *error = "cannot read " + file.fileName();
        return false;
    }
    QByteArray text = file.readAll();
    file.close();
    if (!text.contains(edit.before)) {
        *error = QStringLiteral("%1 has no '%2'").arg(QString::fromUtf8(edit.file), QString::fromUtf8(edit.before));
        return false;
    }
    text.replace(edit.before, edit.after);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(text) != text.size()) {
        *error = "cannot write " + file.fileName();
        return false;
    }
    return true;
}

} // namespace SdkTest
