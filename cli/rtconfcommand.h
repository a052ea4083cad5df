// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/// `rtctl conf PATH [-a] [-s SET] [--json] [list | set PARAM VALUE | get PARAM | act]` (rtconf).
class RtConfCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("conf"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override;
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    int list(const Corba::ComponentProxy &rtc, const RtOptions &options, Streams streams) const;
};

} // namespace Cli
