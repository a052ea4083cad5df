// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/// `rtctl profile check FILE...` and `rtctl profile convert IN OUT`.
class ProfileCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("profile"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;

private:
    int check(const QStringList &files, Streams streams) const;
    int convert(const QStringList &arguments, Streams streams) const;
};

} // namespace Cli
