// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/// `rtctl ls [-l] [-R] [--json] [PATH...]` (rtshell's rtls).
class RtLsCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("ls"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    void printListing(const Corba::NamingNode &directory, bool longForm, bool recursive,
                      Streams streams) const;
    QString row(const Corba::NamingNode &node, bool longForm) const;
    QJsonObject detailedJson(const Corba::NamingNode &node, bool longForm) const;
};

} // namespace Cli
