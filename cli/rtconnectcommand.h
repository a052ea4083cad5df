// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/**
 * `rtctl con [-n NAME] [-i ID] [-p KEY=VALUE]... [--no-duplicates] SRC:PORT DST:PORT...` (rtcon)
 * and `rtctl dis [-i ID] PATH[:PORT] [PATH:PORT...]` (rtdis).
 */
class RtConnectCommand : public RtCommand
{
public:
    explicit RtConnectCommand(bool connect)
        : m_connect(connect)
    { }

    QString name() const override
    {
        return m_connect ? QStringLiteral("con") : QStringLiteral("dis");
    }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override;
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    int connect(const RtOptions &options, Streams streams);
    int disconnect(const RtOptions &options, Streams streams);
    std::vector<Corba::PortInfo> ports(const QStringList &texts) const;

    bool m_connect;
};

} // namespace Cli
