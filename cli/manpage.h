// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Cli {

class CommandLine;

/**
 * rtctl(1), made from the same command table as `rtctl --help`: the page's prose (rtctl.1.in,
 * built in) with a COMMANDS section that holds each command's summary and its full usage, exactly
 * as `rtctl COMMAND --help` prints it. The build writes it with `rtctl --man`, so the installed
 * page and the program cannot disagree.
 */
class ManPage
{
public:
    /// The whole page, in roff (man macros), for @p commandLine's commands and RT Studio @p
    /// version.
    static QString roff(const CommandLine &commandLine, const QString &version);
    /// The COMMANDS section alone.
    static QString commandsSection(const CommandLine &commandLine);
    /// @p text made literal for roff: backslashes, hyphens, lines starting with a control
    /// character and characters beyond ASCII (as groff's \[uXXXX]).
    static QString escape(const QString &text);
};

} // namespace Cli
