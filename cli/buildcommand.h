// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/**
 * `rtctl build DIR [--prefix SDK_PREFIX] [--config Release|Debug] [--clean] [-j N]`: configures
 * and builds a generated C++ project with CMake into DIR/build, as the Builder's Build does,
 * printing the tools' output as it comes and then the errors and warnings found as
 * `FILE:LINE:COL: severity: message`. Exit 0 built, 1 failed.
 */
class BuildCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("build"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;
};

} // namespace Cli
