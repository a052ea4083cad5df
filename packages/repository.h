// SPDX-License-Identifier: MIT
#pragma once

#include "repositoryindex.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

class QLockFile;

namespace Packages {

struct Incoming;

/// How a repository is laid out and signed; kept in <repository>/conf/repository.
struct RepositoryConfig
{
    QString suite = QStringLiteral("stable");
    QString component = QStringLiteral("main");
    QStringList architectures; ///< empty at init: this machine's (dpkg --print-architecture)
    QString origin = QStringLiteral("RT Studio");
    QString label = QStringLiteral("RT-Components");
    QString signWith; ///< OpenPGP key id or fingerprint; empty: unsigned (apt refuses it)
    QString gnupgHome; ///< empty: gpg's default
};

/**
 * A Debian repository in a folder, dists style, that apt-get reads as
 * `deb [signed-by=KEY] file:/path/to/repo SUITE COMPONENT` (or over any static web server):
 *
 *   conf/repository                          this class's settings (deb822)
 *   pool/<component>/<p>/<package>/<file>     the .deb files
 *   dists/<suite>/Release, InRelease, Release.gpg
 *   dists/<suite>/<component>/binary-<arch>/Packages, Packages.gz, Packages.xz
 *   archive-key.asc, archive-key.gpg         the signing key's public half, for clients
 *
 * The indexes are written in full after every change into a new folder that then takes the place
 * of dists/<suite> in one rename; a failing step (gpg, a full disk) leaves the repository as it
 * was.
 */
class Repository
{
public:
    explicit Repository(QString root);

    /// Creates the repository (refused when @p root already holds one); with @p newKeyUserId,
    /// first creates a signing key in config.gnupgHome and signs with it.
    bool init(RepositoryConfig config, const QString &newKeyUserId, QString *error);
    /// Reads conf/repository; false when the folder holds no repository.
    bool open(QString *error);

    /**
     * Adds the .deb files; a package with the same name, version and architecture as one already
     * there (or twice among @p debFiles) is refused unless @p replace. Returns the entries added.
     */
    std::optional<QList<IndexEntry>> publish(const QStringList &debFiles, bool replace,
                                             QString *error);
    /// Removes every version of @p package, or only @p version when given; the entries removed
    /// (refused when none matches).
    std::optional<QList<IndexEntry>> remove(const QString &package, const QString &version,
                                            QString *error);
    /// The packages the index lists, by name and version.
    std::optional<QList<IndexEntry>> packages(QString *error) const;
    /// Writes the indexes again (and signs them) from the current entries.
    bool reindex(QString *error);

    /// Signs with @p keyId from @p gnupgHome in this session instead of the configured key (an
    /// empty argument keeps the configured value).
    void overrideSigning(const QString &keyId, const QString &gnupgHome);

    QString root() const { return m_root; }
    const RepositoryConfig &config() const { return m_config; }
    /// dists/<suite>
    QString suiteFolder() const;

private:
    bool lock(QLockFile *lockFile, QString *error) const;
    /// Reads @p debFiles into @p incoming, refusing duplicates; the existing entries that stay.
    std::optional<QList<IndexEntry>> readIncoming(const QStringList &debFiles,
                                                  const QList<IndexEntry> &existing, bool replace,
                                                  QList<Incoming> *incoming, QString *error);
    bool writeConfig(QString *error) const;
    bool writeIndex(const QList<IndexEntry> &entries, QString *error);
    bool exportKey(QString *error) const;

    QString m_root;
    RepositoryConfig m_config;
};

} // namespace Packages
