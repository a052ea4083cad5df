// SPDX-License-Identifier: MIT
#pragma once

#include "repositoryfetcher.h"
#include "repositoryindex.h"
#include "repositoryprofiles.h"

#include <QList>
#include <QString>
#include <QUrl>

#include <optional>

namespace Packages {

/**
 * What a client reads of a repository made by `rtctl repo` to find the package that provides a
 * component type: the Release file of the suite and every Packages index it lists. The index is
 * not checked against the signature here; each manager verifies with its own keyring what it
 * installs.
 */
struct RemoteIndex
{
    QUrl root; ///< the repository (the folder holding dists/ and pool/)
    QString suite;
    QList<IndexEntry> entries; ///< every package once, whatever indexes list it

    /// The URL a manager installs @p entry from: its pool file with the suite as the fragment.
    QString packageUrl(const IndexEntry &entry) const;
};

/**
 * Reads the index of @p repository: an http, https or file URL, or a folder, optionally with
 * `#SUITE` (default `stable`). Nothing, with the file and the reason in @p error, when the
 * Release file or one of the indexes it names cannot be read or parsed.
 */
std::optional<RemoteIndex> readRemoteIndex(const QString &repository,
                                           const RepositoryFetcher &fetcher, QString *error);

/**
 * The RTC profiles of the component packages of the repository at @p repository (a URL or folder,
 * see readRemoteIndex()): each package not read before is downloaded once, its RTC.xml kept in
 * @p cacheFolder. Nothing, with the reason, when the index cannot be read.
 */
std::optional<QList<PackagedProfile>> readRemoteRepositoryProfiles(const QString &repository,
                                                                   const RepositoryFetcher &fetcher,
                                                                   const QString &cacheFolder,
                                                                   QStringList *problems, QString *error);

} // namespace Packages
