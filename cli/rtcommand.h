// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

#include "componentproxy.h"
#include "managerproxy.h"
#include "namingbrowser.h"
#include "rtpath.h"

#include <QJsonValue>
#include <QMap>
#include <QSet>

#include <functional>
#include <optional>

namespace Cli {

/// Command-line options of one rtshell-style command, parsed by RtCommand::parse().
struct RtOptions
{
    QMap<QString, int> flags; ///< flag → how often given (`-l -l` or `-ll` = 2)
    QMap<QString, QStringList> values; ///< option → values in order (`-p a=1 -p b=2`)
    QStringList positionals;
    QList<QPair<QString, QString>> sequence; ///< options with values, in command-line order
    QString error;

    int count(const QString &flag) const { return flags.value(flag); }
    bool has(const QString &flag) const { return flags.contains(flag); }
    QString value(const QString &option, const QString &fallback = QString()) const
    {
        return values.value(option).isEmpty() ? fallback : values.value(option).last();
    }
};

/**
 * Base of the commands that work on the live RTC tree (rtshell's rtls, rtcat, rtact, ...): option
 * parsing with `--timeout MS`, paths relative to `RTCSH_CWD`, and error reporting that names the
 * path and the reason. Corba::Error is turned into exit code 1, usage problems into 2.
 */
class RtCommand : public Command
{
public:
    int run(const QStringList &arguments, Streams streams) final;

protected:
    /// Flags (no value) and options (one value each time) this command accepts besides --timeout.
    virtual QStringList flagNames() const { return {}; }
    virtual QStringList optionNames() const { return {}; }
    /// Runs with parsed options; may throw Corba::Error.
    virtual int execute(const RtOptions &options, Streams streams) = 0;

    /// Parses `text` relative to the current directory; throws Corba::Error (BadPath).
    Corba::RtPath path(const QString &text) const;
    /// The current tree directory (`RTCSH_CWD`, `/` when unset).
    static QString currentDirectory();
    /// A proxy for the component at `path`; WrongType when it is no component.
    Corba::ComponentProxy component(const Corba::RtPath &path) const;
    /// The manager at a path or `corbaloc::host:port/manager`; WrongType when it is no manager.
    Corba::ManagerProxy managerAt(const QString &text) const;
    /// Prints "rtctl NAME: message" to the error stream.
    void report(const QString &message, Streams streams) const;

    static QString jsonText(const QJsonValue &value);
};

/// Runs `action` for each of `paths`, reporting each failure; ExitProblems if any failed.
int forEachPath(const QStringList &paths, Streams streams,
                const std::function<void(const QString &)> &action, const QString &command);

} // namespace Cli
