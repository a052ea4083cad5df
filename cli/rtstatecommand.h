// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Cli {

/// `rtctl act|deact|reset [-e EC_INDEX] PATH...` and `rtctl exit PATH...` (rtact, rtdeact, ...).
class RtStateCommand : public RtCommand
{
public:
    enum class Action { Activate, Deactivate, Reset, Exit };
    explicit RtStateCommand(Action action)
        : m_action(action)
    { }

    QString name() const override;
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    Action m_action;
};

} // namespace Cli
