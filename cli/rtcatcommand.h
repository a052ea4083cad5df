// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/// `rtctl cat [-l...] [--json] PATH[:PORT]...` (rtshell's rtcat).
class RtCatCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("cat"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    void printComponent(const Corba::ComponentProxy &rtc, const QString &port, int detail,
                        Streams streams) const;
    void printManager(const QString &ior, const QString &path, Streams streams) const;
    QJsonObject managerJson(const QString &ior, const QString &path) const;
    QJsonObject componentJson(const Corba::ComponentProxy &rtc, const QString &port) const;
};

} // namespace Cli
