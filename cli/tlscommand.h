// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/**
 * `rtctl tls init|issue|show`: a certificate authority for a robot network (one per fleet), a
 * certificate per node and per operator, and what a certificate or this program's TLS settings say.
 */
class TlsCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("tls"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;

private:
    int init(const QStringList &words, int days, const QString &name, Streams streams) const;
    int issue(const QStringList &words, int days, const QStringList &hosts, Streams streams) const;
    int show(const QStringList &words, Streams streams) const;
};

} // namespace Cli
