// SPDX-License-Identifier: MIT
#pragma once

#include "rtcommand.h"

namespace Corba {
class PackageInstallerProxy;
}

namespace Cli {

/**
 * `rtctl node install|uninstall|packages MANAGER …` installs component packages into an RT Studio
 * manager's own package store, without root (RTStudio::PackageInstaller), and
 * `rtctl node enable|disable` writes or removes the systemd unit that starts rtmanager at boot.
 * MANAGER is named as for `rtctl mgr`. Exit 0 done, 1 refused or failed, 2 usage error.
 */
class NodeCommand : public RtCommand
{
public:
    QString name() const override { return QStringLiteral("node"); }
    QString summary() const override;
    QString usage() const override;

protected:
    QStringList flagNames() const override;
    QStringList optionNames() const override;
    int execute(const RtOptions &options, Streams streams) override;

private:
    int install(const Corba::PackageInstallerProxy &installer, const RtOptions &options,
                Streams streams) const;
    int uninstall(const Corba::PackageInstallerProxy &installer, const QString &argument,
                  Streams streams) const;
    int packages(const Corba::PackageInstallerProxy &installer, bool json, Streams streams) const;
    int unit(bool enable, const RtOptions &options, Streams streams) const;
};

} // namespace Cli
