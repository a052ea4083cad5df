// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Deploy {
struct DeployOptions;
struct TargetOptions;
}
namespace Profile {
struct RtsProfile;
}

namespace Cli {

/**
 * The commands that apply a saved system file to the live system through the deployment engine
 * (rtsshell's rtresurrect, rtteardown, rtstart, rtstop, and a drift check):
 * `rtctl resurrect [--create] [--dry-run] FILE`, `teardown FILE`, `start FILE`, `stop FILE`,
 * `diff FILE`, `deploy [--repo URL] [--dry-run] FILE`, `undeploy [--uninstall] FILE`, each with `-s SERVER`, `-m MANAGER` and `--host-manager HOST=ADDRESS`.
 */
class RtSystemCommand : public RtCommand
{
public:
    enum class Action { Resurrect, Teardown, Start, Stop, Diff, Deploy, Undeploy };
    explicit RtSystemCommand(Action action)
        : m_action(action)
    { }

    QString name() const override;
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override;
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    bool targetOptions(const RtOptions &options, Deploy::TargetOptions *target,
                       Streams streams) const;

    /// `rtctl deploy`: plans installs and the restore, prints the plan or runs it.
    int deploy(Profile::RtsProfile profile, const Deploy::TargetOptions &target,
               const RtOptions &options, Streams streams) const;

    /// `rtctl deploy --watch`: heals the deployed system until interrupted.
    int watch(const Profile::RtsProfile &profile, const Deploy::DeployOptions &deploy,
              const RtOptions &options, Streams streams) const;

    Action m_action;
};

} // namespace Cli
