// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/**
 * `rtctl repo init|publish|remove|list|show REPO …`: a Debian repository of component packages
 * in a folder (Packages::Repository) that apt-get reads, signed through gpg. Exit 0 done,
 * 1 refused or failed (the repository unchanged), 2 usage error.
 */
class RepoCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("repo"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;
};

} // namespace Cli
