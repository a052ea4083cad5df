// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>

namespace Packages {

/**
 * Signs repository indexes with an OpenPGP key through Debian's gpg (SHA-256 digests, as apt
 * requires). The key lives in a GnuPG home folder (empty: gpg's default, $GNUPGHOME or ~/.gnupg),
 * never in the repository; keys with a passphrase need a gpg-agent that has it.
 */
class GpgSigner
{
public:
    GpgSigner(QString keyId, QString homeDir);

    /// Creates a signing key without passphrase (for trials and tests) in @p homeDir; its
    /// fingerprint.
    static std::optional<QString> createKey(const QString &homeDir, const QString &userId,
                                            QString *error);

    /// The InRelease form of @p data: clear-signed.
    std::optional<QByteArray> clearSign(const QByteArray &data, QString *error) const;
    /// The Release.gpg form: an ASCII-armoured detached signature.
    std::optional<QByteArray> detachSign(const QByteArray &data, QString *error) const;
    /// The public key, ASCII-armoured or binary (a keyring apt's signed-by takes).
    std::optional<QByteArray> exportPublicKey(bool armored, QString *error) const;
    /// The key's fingerprint; nothing when gpg has no secret key of that id.
    std::optional<QString> fingerprint(QString *error) const;

    QString keyId() const { return m_keyId; }
    QString homeDir() const { return m_homeDir; }

private:
    std::optional<QByteArray> gpg(const QStringList &arguments, const QByteArray &input,
                                  const QString &step, QString *error) const;

    QString m_keyId;
    QString m_homeDir;
};

} // namespace Packages
