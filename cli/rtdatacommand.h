// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Codegen {
class CdrCodec;
}

namespace Cli {

/**
 * `rtctl print PATH:PORT`, `rtctl inject PATH:PORT VALUE…` and `rtctl log` (rtshell's rtprint,
 * rtinject and rtlog):
 * samples of a data port as text or JSON lines, through a connector of rtctl's own that is
 * removed again on exit, on Ctrl-C and on errors. Types come from OpenRTM's IDL and the folders
 * given with --idl-dir.
 */
class RtDataCommand : public RtCommand
{
public:
    enum class Mode { Print, Inject, Log };
    explicit RtDataCommand(Mode mode)
        : m_mode(mode)
    { }

    QString name() const override;
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override;
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    int print(const RtOptions &options, const Corba::PortInfo &port, const QString &where,
              Streams streams);
    int inject(const RtOptions &options, const Corba::PortInfo &port, const QString &where,
               Streams streams);
    int record(const RtOptions &options, Streams streams);
    int play(const RtOptions &options, Streams streams);
    /// The port named by a `PATH:PORT` argument, and that text as a full path.
    std::pair<Corba::PortInfo, QString> port(const QString &text) const;

    Mode m_mode;
};

} // namespace Cli
