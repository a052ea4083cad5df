// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace Deploy {

/**
 * A certificate authority for a robot network's TLS, kept in a folder and run with Debian's
 * `openssl` command: `ca.pem` (the authority's certificate, which every node and user trusts:
 * corba.ssl.certificate_authority_file), `ca.key` (its private key, readable by the owner only) and a
 * `<name>.pem` per node or operator, holding a private key and its certificate signed by the
 * authority (corba.ssl.key_file). Keys are P-256 EC keys without a password; certificates serve both as
 * client and as server.
 */
class CertificateAuthority
{
    Q_DECLARE_TR_FUNCTIONS(Deploy::CertificateAuthority)

public:
    explicit CertificateAuthority(const QString &folder);

    /// True when the folder holds an authority (ca.pem and ca.key).
    bool exists() const;
    /// Creates the authority named @p name, valid @p days; refuses to replace one.
    bool init(const QString &name, int days, QString *error);
    /**
     * Issues `<name>.pem` for a node or an operator called @p name (letters, digits, '.', '-', '_'),
     * valid @p days (0: expired from the start, for trying refusals), with @p hosts as the
     * certificate's DNS / IP names besides @p name. The path in @p path.
     */
    bool issue(const QString &name, int days, const QStringList &hosts, QString *path, QString *error);

    QString certificatePath() const;
    QString keyPath() const;
    /// `<folder>/<name>.pem`.
    QString issuedPath(const QString &name) const;

private:
    bool runOpenSsl(const QStringList &arguments, QString *error) const;

    QString m_folder;
};

} // namespace Deploy
