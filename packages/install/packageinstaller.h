// SPDX-License-Identifier: MIT
#pragma once

#include "packagestore.h"

#include <releaseverifier.h>
#include <repositoryindex.h>

#include <QByteArray>
#include <QString>

#include <optional>

namespace Packages {

/// What a node requires before it installs a package.
struct InstallPolicy
{
    QString keyring; ///< the keyring file gpgv checks InRelease with; empty: none
    bool allowUnsigned = false; ///< take unsigned or unverifiable repositories
    QString architecture; ///< the node's (dpkg --print-architecture)
    QString sdkAbi; ///< SONAME of the node's component SDK; empty: not checked
};

/// A package and the repository files that vouch for it.
struct PackageSource
{
    QByteArray inRelease; ///< the repository's InRelease, or its Release when unsigned
    QString indexPath; ///< of the index below dists/<suite>/, e.g. main/binary-amd64/Packages
    QByteArray index; ///< that Packages file
    QString debFile; ///< the .deb, on this machine
    QString poolPath; ///< its Filename in the index when known (install by URL)
    QString package; ///< else its name and version, to find its index entry
    QString version;
};

/// Why an install was refused: the package (when known) and the reason.
struct InstallError
{
    QString package;
    QString reason;

    /// "<package>: <reason>"
    QString message() const;
};

/**
 * Installs component packages into a PackageStore in apt's order of trust: the InRelease verified
 * with gpgv against the policy's keyring, the index checked against the Release, the .deb's size
 * and SHA-256 against its index entry; then the node's Architecture, SDK ABI and Debian library
 * dependencies; only then unpacked (dpkg-deb -x) into a staging folder that is renamed into place.
 * Any refusal names the package and the reason and leaves the store as it was.
 */
class PackageInstaller
{
public:
    PackageInstaller(const PackageStore &store, InstallPolicy policy);

    std::optional<InstalledPackage> install(const PackageSource &source, InstallError *error) const;

    /// The Release @p inRelease vouches for, verified as the policy requires.
    std::optional<VerifiedRelease> trustedRelease(const QByteArray &inRelease,
                                                  QString *reason) const;

private:
    std::optional<IndexEntry> indexEntry(const PackageSource &source,
                                         const VerifiedRelease &release, InstallError *error) const;
    bool checkNode(const IndexEntry &entry, QString *reason) const;
    std::optional<InstalledPackage> unpack(const IndexEntry &entry, const QString &debFile,
                                           QString *reason) const;

    const PackageStore &m_store;
    InstallPolicy m_policy;
};

} // namespace Packages
