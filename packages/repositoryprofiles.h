// SPDX-License-Identifier: MIT
#pragma once

#include "repositoryindex.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <functional>

#include <optional>

namespace Packages {

/// The RTC profile one package of a component repository ships.
struct PackagedProfile
{
    IndexEntry entry;
    QString profileFile; ///< the package's RTC.xml, extracted into the cache
};

/// The .deb of an index entry as a local file, or nothing with the reason.
using DebFileSource = std::function<std::optional<QString>(const IndexEntry &entry, QString *error)>;

/**
 * The RTC profiles shipped by the newest version of each component package among @p entries (a
 * repository's index), read from the .deb that @p debFile gives with dpkg-deb and kept in
 * @p cacheFolder, one file per package, version and checksum, so that a package is read once.
 * Packages that ship no RTC.xml (not component packages) are left out; a package that cannot be
 * read is named in @p problems.
 */
QList<PackagedProfile> packagedProfiles(const QList<IndexEntry> &entries, const QString &cacheFolder,
                                        const DebFileSource &debFile, QStringList *problems);

/**
 * packagedProfiles() of the repository folder @p root (made by `rtctl repo init`). Nothing, with
 * the reason, when the folder is no repository.
 */
std::optional<QList<PackagedProfile>> readRepositoryProfiles(const QString &root, const QString &cacheFolder,
                                                             QStringList *problems, QString *error);
/// The file @p path (absolute, as installed) of the .deb @p debFile; nothing when it has none.
std::optional<QByteArray> readPackageFile(const QString &debFile, const QString &path, QString *error);

} // namespace Packages
