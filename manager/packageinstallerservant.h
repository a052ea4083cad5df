// SPDX-License-Identifier: MIT
#pragma once

#include <packageinstaller.h>
#include <packagestore.h>

#include <RTStudioManager.hh>

#include <mutex>
#include <string>

namespace Runtime {

class Manager;

/**
 * RTStudio::PackageInstaller servant: installs component packages into the manager's own package
 * store (Packages::PackageInstaller) from a repository URL or from bytes pushed through the call,
 * lists and uninstalls them. Installed modules are part of the manager's module load path from
 * the moment they are in the store. Configuration (the manager's):
 *
 *   manager.packages.enable          YES (NO: no installer, get_package_installer() gives nil)
 *   manager.packages.store           the store folder; default $XDG_DATA_HOME/rtstudio/packages
 *   manager.packages.keyring         the keyring file repositories are verified with (gpgv)
 *   manager.packages.allow_unsigned  YES takes unsigned and unverifiable repositories
 *   manager.packages.sdk_abi         the SDK's SONAME packages must be built for (default: this
 * SDK) manager.packages.fetch_timeout   ms for each file fetched (default 60000)
 *   manager.packages.ca_certificates a PEM file of certificate authorities trusted for https
 *
 * Installs run one at a time. A store belongs to one manager (and its slaves): the manager's start
 * deletes staging folders it finds there.
 */
class PackageInstallerServant : public virtual POA_RTStudio::PackageInstaller
{
public:
    /**
     * The installer of @p manager's configuration, its store prepared (leftovers of interrupted
     * installs deleted) and its module folders made part of the manager's load path; nullptr
     * when disabled, or with @p error when the store cannot be made. Call before the manager
     * starts; activate it once the manager serves.
     */
    static PackageInstallerServant *create(Manager &manager, std::string *error);

    RTStudio::InstalledPackage *install_url(const char *url) override;
    RTStudio::InstalledPackage *install_package(const RTStudio::OctetSeq &deb,
                                                const RTStudio::OctetSeq &in_release,
                                                const char *index_path,
                                                const RTStudio::OctetSeq &index,
                                                const char *package, const char *version) override;
    void uninstall(const char *package, const char *version) override;
    RTStudio::InstalledPackageList *list_installed() override;

private:
    /// A folder for the files of one install, deleted with it.
    class Download
    {
    public:
        /// Refuses the install of @p package when the folder cannot be made.
        Download(const Packages::PackageStore &store, const QString &package,
                 const PackageInstallerServant *servant);
        ~Download();
        Download(const Download &) = delete;
        Download &operator=(const Download &) = delete;
        QString path() const { return m_path; }

    private:
        const Packages::PackageStore &m_store;
        QString m_path;
    };

    PackageInstallerServant(Manager &manager, Packages::PackageStore store,
                            Packages::InstallPolicy policy, int fetchTimeoutMs,
                            QString caCertificates);
    /// The policy, the node's architecture known (call with m_mutex held).
    const Packages::InstallPolicy &policy();
    /// Installs @p source; the installed package, or InstallRefused.
    RTStudio::InstalledPackage *install(const Packages::PackageSource &source);
    [[noreturn]] void refuse(const QString &package, const QString &reason) const;
    /// Refuses when a running component was made from a module of @p package.
    void checkNotRunning(const Packages::InstalledPackage &package);
    /// Unloads the modules of @p package the manager has loaded.
    void unloadModules(const Packages::InstalledPackage &package);

    Manager &m_manager;
    Packages::PackageStore m_store;
    Packages::InstallPolicy m_policy;
    int m_fetchTimeoutMs;
    QString m_caCertificates;
    std::mutex m_mutex;
};

} // namespace Runtime
