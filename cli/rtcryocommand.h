// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/**
 * `rtctl cryo [-n NAME] [-v VERSION] [-e VENDOR] [-a ABSTRACT] [-o FILE] [PATH...]` (rtshell's
 * rtcryo): saves the components under PATHs (default: the name servers of RTCTREE_NAMESERVERS)
 * and their connections as an RTS profile, XML (YAML when FILE ends in .yaml) to FILE or stdout.
 */
class RtCryoCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("cryo"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;
};

} // namespace Cli
