// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/**
 * `rtctl package DIR [-o OUT] [--build-dir B] [--name P] [--maintainer M] [--depends D]…`: makes
 * the Debian package of a built component project (Packages::ComponentPackager) and prints its
 * file and control data. Exit 0 made, 1 refused (the message names the file and the reason).
 */
class PackageCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("package"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;
};

} // namespace Cli
