// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/**
 * `rtctl pwd` prints the current tree directory (`RTCSH_CWD`); `rtctl cd [PATH]` checks PATH and
 * prints a shell snippet that sets it, to be used as `eval "$(rtctl cd PATH)"` (a process cannot
 * change its parent's environment; rtshell's rtcwd works the same way through a shell function).
 */
class RtCwdCommand : public RtCommand
{
public:
    explicit RtCwdCommand(bool change)
        : m_change(change)
    { }

    QString name() const override
    {
        return m_change ? QStringLiteral("cd") : QStringLiteral("pwd");
    }
    QString summary() const override;
    QString usage() const override;

protected:
    int execute(const RtOptions &options, Streams streams) override;

private:
    bool m_change;
};

} // namespace Cli
