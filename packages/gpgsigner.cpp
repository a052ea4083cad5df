// SPDX-License-Identifier: MIT
#include "gpgsigner.h"

#include "packagetool.h"

#include <QDir>
#include <QFile>
#include <QStringList>

namespace Packages {

namespace {

QStringList homeArguments(const QString &homeDir)
{
    QStringList arguments {QStringLiteral("--batch"), QStringLiteral("--no-tty")};
    if (!homeDir.isEmpty())
        arguments << QStringLiteral("--homedir") << homeDir;
    return arguments;
}

/// The fingerprint of the first secret key in gpg's --with-colons listing.
QString firstFingerprint(const QByteArray &listing)
{
    bool inSecretKey = false;
    for (const QByteArray &line : listing.split('\n')) {
        if (line.startsWith("sec:"))
            inSecretKey = true;
        else if (inSecretKey && line.startsWith("fpr:"))
            return QString::fromLatin1(line.split(':').value(9));
    }
    return {};
}

} // namespace

GpgSigner::GpgSigner(QString keyId, QString homeDir)
    : m_keyId(std::move(keyId))
    , m_homeDir(std::move(homeDir))
{ }

std::optional<QString> GpgSigner::createKey(const QString &homeDir, const QString &userId,
                                            QString *error)
{
    if (!homeDir.isEmpty() && !QDir().mkpath(homeDir)) {
        *error = QStringLiteral("%1: cannot create the GnuPG home folder").arg(homeDir);
        return std::nullopt;
    }
    if (!homeDir.isEmpty())
        QFile::setPermissions(homeDir, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QStringList arguments = homeArguments(homeDir);
    arguments << QStringLiteral("--passphrase") << QString() << QStringLiteral("--pinentry-mode")
              << QStringLiteral("loopback") << QStringLiteral("--quick-generate-key") << userId
              << QStringLiteral("ed25519") << QStringLiteral("sign") << QStringLiteral("never");
    const ToolResult created = runTool(QStringLiteral("gpg"), arguments);
    if (!created.ok()) {
        *error = created.failure(QStringLiteral("gpg --quick-generate-key"));
        return std::nullopt;
    }
    const ToolResult listed = runTool(QStringLiteral("gpg"),
                                      homeArguments(homeDir)
                                          + QStringList {QStringLiteral("--with-colons"),
                                                         QStringLiteral("--list-secret-keys"),
                                                         QStringLiteral("=") + userId});
    const QString fingerprint = firstFingerprint(listed.out);
    if (!listed.ok() || fingerprint.isEmpty()) {
        *error = listed.failure(QStringLiteral("gpg --list-secret-keys"));
        return std::nullopt;
    }
    return fingerprint;
}

std::optional<QByteArray> GpgSigner::gpg(const QStringList &arguments, const QByteArray &input,
                                         const QString &step, QString *error) const
{
    ToolRun run;
    run.input = input;
    const ToolResult result
        = runTool(QStringLiteral("gpg"), homeArguments(m_homeDir) + arguments, run);
    if (!result.ok()) {
        *error = QStringLiteral("%1 with key %2: %3")
                     .arg(step, m_keyId, result.failure(QStringLiteral("gpg")));
        return std::nullopt;
    }
    return result.out;
}

std::optional<QByteArray> GpgSigner::clearSign(const QByteArray &data, QString *error) const
{
    return gpg({QStringLiteral("--local-user"), m_keyId, QStringLiteral("--digest-algo"),
                QStringLiteral("SHA256"), QStringLiteral("--clearsign")},
               data, QStringLiteral("signing InRelease"), error);
}

std::optional<QByteArray> GpgSigner::detachSign(const QByteArray &data, QString *error) const
{
    return gpg({QStringLiteral("--local-user"), m_keyId, QStringLiteral("--digest-algo"),
                QStringLiteral("SHA256"), QStringLiteral("--armor"),
                QStringLiteral("--detach-sign")},
               data, QStringLiteral("signing Release.gpg"), error);
}

std::optional<QByteArray> GpgSigner::exportPublicKey(bool armored, QString *error) const
{
    QStringList arguments {QStringLiteral("--export")};
    if (armored)
        arguments.prepend(QStringLiteral("--armor"));
    arguments << m_keyId;
    std::optional<QByteArray> key
        = gpg(arguments, {}, QStringLiteral("exporting the public key"), error);
    if (key && key->isEmpty()) {
        *error = QStringLiteral("exporting the public key: gpg has no key %1").arg(m_keyId);
        return std::nullopt;
    }
    return key;
}

std::optional<QString> GpgSigner::fingerprint(QString *error) const
{
    const std::optional<QByteArray> listing
        = gpg({QStringLiteral("--with-colons"), QStringLiteral("--list-secret-keys"), m_keyId}, {},
              QStringLiteral("finding the secret key"), error);
    if (!listing)
        return std::nullopt;
    const QString fingerprint = firstFingerprint(*listing);
    if (fingerprint.isEmpty()) {
        *error = QStringLiteral("gpg has no secret key %1").arg(m_keyId);
        return std::nullopt;
    }
    return fingerprint;
}

} // namespace Packages
