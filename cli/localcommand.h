// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/**
 * `rtctl local start|stop|status [--json]`: the local runtime (a name server and an rtmanager
 * master on this machine, see Deploy::LocalRuntime) that RT Studio's Online menu starts too.
 */
class LocalCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("local"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;
};

} // namespace Cli
