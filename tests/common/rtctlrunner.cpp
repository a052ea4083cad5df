// SPDX-License-Identifier: MIT
#include "rtctlrunner.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QProcess>
#include <QProcessEnvironment>

RtctlResult runProgram(const QString &program, const QStringList &arguments,
                       const QHash<QString, QString> &environment)
{
    QProcess process;
    QProcessEnvironment processEnvironment = QProcessEnvironment::systemEnvironment();
    for (auto it = environment.cbegin(); it != environment.cend(); ++it)
        processEnvironment.insert(it.key(), it.value());
    process.setProcessEnvironment(processEnvironment);
    process.start(program, arguments);
    RtctlResult result;
    // The other programs a test started keep being read meanwhile: a manager whose output pipe
    // fills up stops in the middle of a call rtctl is waiting for.
    const QDeadlineTimer deadline(60000);
    while (!process.waitForFinished(20) && process.state() != QProcess::NotRunning && !deadline.hasExpired())
        QCoreApplication::processEvents();
    if (process.state() != QProcess::NotRunning || process.error() == QProcess::FailedToStart) {
        process.kill();
        process.waitForFinished();
        return result;
    }
    result.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    result.out = QString::fromUtf8(process.readAllStandardOutput());
    result.err = QString::fromUtf8(process.readAllStandardError());
    return result;
}

RtctlResult runRtctl(const QStringList &arguments, const QHash<QString, QString> &environment)
{
    return runProgram(RTCTL_PATH, arguments, environment);
}

bool runRtctlAll(const QList<QStringList> &commands, QString *error)
{
    for (const QStringList &command : commands) {
        const RtctlResult r = runRtctl(command);
        if (r.code != 0) {
            *error = command.join(QLatin1Char(' ')) + QStringLiteral(": ") + r.err;
            return false;
        }
    }
    return true;
}

RtctlResult runRtctlAt(const QString &context, const QStringList &arguments)
{
    return runRtctl(arguments, {{QStringLiteral("RTCSH_CWD"), context}, {QStringLiteral("RTCTREE_NAMESERVERS"), QString()}});
}
