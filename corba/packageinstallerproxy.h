// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

namespace Corba {

/// One installed version of a component package on a manager.
struct InstalledPackageInfo
{
    QString name;
    QString version;
    QString architecture;
    QStringList componentTypes;
    QString path; ///< its folder in the manager's package store
};

/// A package pushed to a manager with the repository files that vouch for it.
struct PushedPackage
{
    QByteArray deb;
    QByteArray inRelease; ///< the repository's InRelease (its Release when unsigned)
    QString indexPath; ///< below dists/<suite>/, e.g. main/binary-amd64/Packages
    QByteArray index;
    QString package; ///< the .deb's Package and Version, to find its index entry
    QString version;
};

/**
 * The package installer of an RT Studio manager (RTStudio::PackageInstaller, reached through
 * RTStudio::Manager::get_package_installer()). Every call throws Corba::Error naming the manager's
 * path: WrongType when the manager has no install service (an OpenRTM-aist manager, or one with
 * manager.packages.enable: NO), Refused with the package and the reason when the manager refuses.
 * Installs run under installTimeout (they fetch, verify and unpack), the other calls under the
 * configured call timeout.
 */
class PackageInstallerProxy
{
public:
    PackageInstallerProxy(QString managerIor, QString path);

    InstalledPackageInfo installUrl(const QString &url) const;
    InstalledPackageInfo installPackage(const PushedPackage &package) const;
    /// Removes @p package (every version when @p version is empty).
    void uninstall(const QString &package, const QString &version) const;
    QList<InstalledPackageInfo> installed() const;

    /// How long an install may take (ms); default 120 s.
    void setInstallTimeout(int milliseconds) { m_installTimeout = milliseconds; }

private:
    /// The installer's reference (an IOR string); throws WrongType when the manager has none.
    QString installer() const;

    QString m_ior;
    QString m_path;
    int m_installTimeout = 120000;
};

} // namespace Corba
