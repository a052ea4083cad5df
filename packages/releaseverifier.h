// SPDX-License-Identifier: MIT
#pragma once

#include "debcontrol.h"
#include "repositoryindex.h"

#include <QByteArray>
#include <QHash>
#include <QString>

#include <optional>

namespace Packages {

/// One index file a Release lists.
struct ReleaseFile
{
    QString path; ///< relative to dists/<suite>/
    qint64 size = -1;
    QByteArray sha256; ///< hex
};

/**
 * A repository's Release, once its signature is verified: apt's order of trust for those that
 * install from a repository. Verify InRelease with gpgv against the keys trusted, then check each
 * index file against the sizes and SHA-256 sums it lists, then each package against its index
 * entry, and only then unpack.
 */
class VerifiedRelease
{
public:
    /**
     * Verifies the clear-signed @p inRelease with Debian's gpgv against @p keyring (a keyring
     * file, as apt's signed-by takes); nothing, with gpgv's reason, when the signature is bad,
     * made by a key not in the keyring, or missing.
     */
    static std::optional<VerifiedRelease> verify(const QByteArray &inRelease,
                                                 const QString &keyring, QString *error);
    /// Reads a Release without a signature (for a caller that trusts it by other means).
    static std::optional<VerifiedRelease> parse(const QByteArray &release, QString *error);

    QString value(const QString &field) const { return m_fields.value(field); }
    /// The entry of @p path in the SHA256 list, or nothing.
    std::optional<ReleaseFile> file(const QString &path) const;
    /// True when @p data is the file @p path as listed (size and SHA-256); otherwise the reason.
    bool check(const QString &path, const QByteArray &data, QString *error) const;

private:
    DebControl m_fields;
    QHash<QString, ReleaseFile> m_files;
};

/// True when the file @p debFile has the size and SHA-256 its index @p entry gives; otherwise the
/// reason, naming the package.
bool checkPackageFile(const IndexEntry &entry, const QString &debFile, QString *error);

} // namespace Packages
