// SPDX-License-Identifier: MIT
#include "packagetool.h"

#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>

namespace Packages {

QString ToolResult::failure(const QString &program) const
{
    if (!started)
        return QStringLiteral("%1 could not be started (is it installed?)").arg(program);
    const QString text = QString::fromLocal8Bit(err.isEmpty() ? out : err).trimmed();
    const QStringList lines = text.split(QLatin1Char('\n'));
    const QString shown = lines.mid(0, 6).join(QLatin1Char('\n'));
    if (exitCode < 0)
        return QStringLiteral("%1 did not finish: %2").arg(program, shown);
    return QStringLiteral("%1 failed (exit %2): %3").arg(program).arg(exitCode).arg(shown);
}

bool haveTool(const QString &program)
{
    return !QStandardPaths::findExecutable(program).isEmpty();
}

ToolResult runTool(const QString &program, const QStringList &arguments, const ToolRun &run)
{
    ToolResult result;
    const QString path = QStandardPaths::findExecutable(program);
    if (path.isEmpty())
        return result;
    QProcess process;
    if (!run.workingDirectory.isEmpty())
        process.setWorkingDirectory(run.workingDirectory);
    if (!run.environment.isEmpty()) {
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        for (auto it = run.environment.cbegin(); it != run.environment.cend(); ++it)
            environment.insert(it.key(), it.value());
        process.setProcessEnvironment(environment);
    }
    process.start(path, arguments);
    if (!process.waitForStarted())
        return result;
    result.started = true;
    if (!run.input.isEmpty())
        process.write(run.input);
    process.closeWriteChannel();
    if (!process.waitForFinished(run.timeoutMs)) {
        process.kill();
        process.waitForFinished(5000);
        result.err = process.readAllStandardError() + "\n(timed out)";
        return result;
    }
    result.out = process.readAllStandardOutput();
    result.err = process.readAllStandardError();
    result.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    return result;
}

} // namespace Packages
