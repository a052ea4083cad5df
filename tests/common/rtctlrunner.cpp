// SPDX-License-Identifier: MIT
#include "rtctlrunner.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QProcess>
#include <QProcessEnvironment>

RtctlResult runRtctl(const QStringList &arguments, const QHash<QString, QString> &environment)
{
    QProcess process;
    QProcessEnvironment processEnvironment = QProcessEnvironment::systemEnvironment();
    for (auto it = environment.cbegin(); it != environment.cend(); ++it)
        processEnvironment.insert(it.key(), it.value());
    process.setProcessEnvironment(processEnvironment);
    process.start(QStringLiteral(RTCTL_PATH), arguments);
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

RtctlResult runRtctlAt(const QString &context, const QStringList &arguments)
{
    return runRtctl(arguments, {{QStringLiteral("RTCSH_CWD"), context}, {QStringLiteral("RTCTREE_NAMESERVERS"), QString()}});
}
