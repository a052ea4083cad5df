// SPDX-License-Identifier: MIT
#pragma once

#include "repositoryindex.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

namespace Packages {

/// The RTC profile one package of a component repository ships.
struct PackagedProfile
{
    IndexEntry entry;
    QString profileFile; ///< the package's RTC.xml, extracted into the cache
};

/**
 * The RTC profiles of the component packages in the repository folder @p root (made by
 * `rtctl repo init`), the newest version of each package, read from its .deb with dpkg-deb and kept
 * in @p cacheFolder (a file per package and version, reused while the .deb is not newer). Packages
 * that ship no RTC.xml (not component packages) are left out. Nothing, with the reason, when the
 * folder is no repository; a package that cannot be read is named in @p problems.
 */
std::optional<QList<PackagedProfile>> readRepositoryProfiles(const QString &root, const QString &cacheFolder,
                                                             QStringList *problems, QString *error);

/// The file @p path (absolute, as installed) of the .deb @p debFile; nothing when it has none.
std::optional<QByteArray> readPackageFile(const QString &debFile, const QString &path, QString *error);

} // namespace Packages
