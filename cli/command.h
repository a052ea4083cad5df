// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>
#include <QTextStream>

namespace Cli {

/// Exit codes shared by every rtctl command.
enum ExitCode { ExitOk = 0, ExitProblems = 1, ExitUsage = 2 };

/// Where a command writes: normal output and messages (diagnostics, errors).
struct Streams
{
    QTextStream &out;
    QTextStream &err;
};

/**
 * One top-level rtctl word (`profile`, later `ls`, `gen`, ...). Commands get the arguments after
 * their word and return an ExitCode.
 */
class Command
{
public:
    virtual ~Command() = default;

    virtual QString name() const = 0;
    /// One line for `rtctl --help`.
    virtual QString summary() const = 0;
    /// Full usage text for `rtctl <name> --help`.
    virtual QString usage() const = 0;
    virtual int run(const QStringList &arguments, Streams streams) = 0;

protected:
    /// Prints `message` and the usage to the error stream and returns ExitUsage.
    int usageError(const QString &message, Streams streams) const;
};

} // namespace Cli
