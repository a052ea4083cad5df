// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QHash>
#include <QString>
#include <QStringList>

namespace Packages {

/// What one run of a Debian tool gave.
struct ToolResult
{
    bool started = false;
    int exitCode = -1;
    QByteArray out;
    QByteArray err;

    bool ok() const { return started && exitCode == 0; }
    /// "<program>: <first lines of its errors>" for messages.
    QString failure(const QString &program) const;
};

/// Options of one tool run.
struct ToolRun
{
    QString workingDirectory;
    QHash<QString, QString> environment; ///< added to the process's environment
    QByteArray input; ///< written to its standard input
    int timeoutMs = 120000;
};

/// Runs @p program (found on PATH) with @p arguments and waits for it.
ToolResult runTool(const QString &program, const QStringList &arguments, const ToolRun &run = {});

/// True when @p program is on PATH.
bool haveTool(const QString &program);

} // namespace Packages
