// SPDX-License-Identifier: MIT
#pragma once

#include "debcontrol.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace Packages {

/// One package of a repository: its control data with the fields the index adds (Filename, Size,
/// MD5sum, SHA256).
struct IndexEntry
{
    DebControl control;

    QString package() const { return control.value(QStringLiteral("Package")); }
    QString version() const { return control.value(QStringLiteral("Version")); }
    QString architecture() const { return control.value(QStringLiteral("Architecture")); }
    QString filename() const { return control.value(QStringLiteral("Filename")); }
    /// "name version arch", what may be published once.
    QString key() const;
};

/**
 * The entry of the .deb @p debFile, to be stored at @p poolPath (relative to the repository),
 * its control data read with `dpkg-deb -f`. Nothing, with the reason in @p error, when dpkg-deb
 * cannot read it or it lacks Package, Version or Architecture.
 */
std::optional<IndexEntry> readDebEntry(const QString &debFile, const QString &poolPath,
                                       QString *error);

/// "pool/<component>/<first letter or lib?>/<package>/<package>_<version>_<arch>.deb"
QString poolPath(const QString &component, const IndexEntry &entry);

/// The Packages file of @p architecture: its own packages and those of "all", sorted by name and
/// version.
QByteArray packagesText(const QList<IndexEntry> &entries, const QString &architecture);

/// An index file under dists/<suite>/.
struct IndexFile
{
    QString path; ///< relative to dists/<suite>/, e.g. main/binary-amd64/Packages.gz
    QByteArray data;
};

/// What the Release file describes besides its index files.
struct ReleaseInfo
{
    QString origin;
    QString label;
    QString suite;
    QString codename;
    QString component;
    QStringList architectures;
    QString description;
    QDateTime date;
};

/// Packages, Packages.gz (gzip) and Packages.xz (when xz is installed) of every architecture.
std::optional<QList<IndexFile>> packagesFiles(const QList<IndexEntry> &entries,
                                              const ReleaseInfo &info, QString *error);

/// The Release file listing @p files with their sizes and MD5 and SHA256 checksums.
QByteArray releaseText(const ReleaseInfo &info, const QList<IndexFile> &files);

} // namespace Packages
