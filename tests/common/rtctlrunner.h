// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QJsonDocument>
#include <QString>
#include <QStringList>

/// What one run of the real rtctl binary gave: exit code (-1: did not finish, -2: crashed) and
/// its two output streams.
struct RtctlResult
{
    int code = -1;
    QString out;
    QString err;

    QStringList lines() const { return out.split(QLatin1Char('\n'), Qt::SkipEmptyParts); }
    QJsonDocument json() const { return QJsonDocument::fromJson(out.toUtf8()); }
};

/**
 * Runs @p program with extra environment variables set, reading the programs a test started
 * meanwhile. Gives up after a minute and kills the process.
 */
RtctlResult runProgram(const QString &program, const QStringList &arguments,
                       const QHash<QString, QString> &environment = {});

/// runProgram() of the rtctl binary the tests were built with (RTCTL_PATH), as a user or a script would.
RtctlResult runRtctl(const QStringList &arguments,
                     const QHash<QString, QString> &environment = {});

/// Runs rtctl once per entry of @p commands, in order; false at the first that fails, with it and its error.
bool runRtctlAll(const QList<QStringList> &commands, QString *error);

/// Runs rtctl with its current directory (RTCSH_CWD) at @p context, e.g. `/ns:port/host.host_cxt`,
/// and no RTCTREE_NAMESERVERS, as the live tests drive one host context.
RtctlResult runRtctlAt(const QString &context, const QStringList &arguments);
