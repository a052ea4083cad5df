// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/// `rtctl find PATH [-n PATTERN] [-i PATTERN] [-m DEPTH] [-t TYPES] [--json]` (rtshell's rtfind).
class RtFindCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("find"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override { return {QStringLiteral("--json")}; }
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;
};

} // namespace Cli
