// SPDX-License-Identifier: MIT
#include "releaseverifier.h"

#include "packagetool.h"

#include <QCryptographicHash>
#include <QFile>
#include <QStringList>

namespace Packages {

std::optional<VerifiedRelease> VerifiedRelease::verify(const QByteArray &inRelease,
                                                       const QString &keyring, QString *error)
{
    ToolRun run;
    run.input = inRelease;
    // gpgv writes the signed text only when the signature is good.
    const ToolResult result
        = runTool(QStringLiteral("gpgv"),
                  {QStringLiteral("--keyring"), keyring, QStringLiteral("--output"),
                   QStringLiteral("-"), QStringLiteral("-")},
                  run);
    if (!result.ok()) {
        *error = QStringLiteral("verifying InRelease with %1: %2")
                     .arg(keyring, result.failure(QStringLiteral("gpgv")));
        return std::nullopt;
    }
    return parse(result.out, error);
}

std::optional<VerifiedRelease> VerifiedRelease::parse(const QByteArray &release, QString *error)
{
    QString reason;
    const std::optional<DebControl> fields = DebControl::parse(release, &reason);
    if (!fields || fields->value(QStringLiteral("SHA256")).isEmpty()) {
        *error = QStringLiteral("unreadable Release: %1")
                     .arg(reason.isEmpty() ? QStringLiteral("no SHA256 list") : reason);
        return std::nullopt;
    }
    VerifiedRelease verified;
    verified.m_fields = *fields;
    for (const QString &line : fields->value(QStringLiteral("SHA256")).split(QLatin1Char('\n'))) {
        const QStringList parts = line.simplified().split(QLatin1Char(' '));
        if (parts.size() != 3)
            continue;
        verified.m_files.insert(
            parts.at(2),
            ReleaseFile {parts.at(2), parts.at(1).toLongLong(), parts.at(0).toLatin1()});
    }
    return verified;
}

std::optional<ReleaseFile> VerifiedRelease::file(const QString &path) const
{
    const auto it = m_files.constFind(path);
    return it == m_files.cend() ? std::nullopt : std::optional<ReleaseFile>(*it);
}

bool VerifiedRelease::check(const QString &path, const QByteArray &data, QString *error) const
{
    const std::optional<ReleaseFile> listed = file(path);
    if (!listed) {
        *error = QStringLiteral("%1: not listed in Release").arg(path);
        return false;
    }
    const QByteArray sum = QCryptographicHash::hash(data, QCryptographicHash::Sha256).toHex();
    if (listed->size != data.size() || listed->sha256 != sum) {
        *error = QStringLiteral("%1: does not match Release (size %2, SHA256 %3; Release: %4, %5)")
                     .arg(path)
                     .arg(data.size())
                     .arg(QString::fromLatin1(sum))
                     .arg(listed->size)
                     .arg(QString::fromLatin1(listed->sha256));
        return false;
    }
    return true;
}

bool checkPackageFile(const IndexEntry &entry, const QString &debFile, QString *error)
{
    QFile file(debFile);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: cannot read %2").arg(entry.package(), debFile);
        return false;
    }
    QCryptographicHash sha256(QCryptographicHash::Sha256);
    while (!file.atEnd())
        sha256.addData(file.read(1 << 20));
    const QString sum = QString::fromLatin1(sha256.result().toHex());
    const QString expected = entry.control.value(QStringLiteral("SHA256"));
    if (QString::number(file.size()) != entry.control.value(QStringLiteral("Size"))
        || sum != expected) {
        *error = QStringLiteral("%1 %2: %3 does not match the index (SHA256 %4, index %5)")
                     .arg(entry.package(), entry.version(), debFile, sum, expected);
        return false;
    }
    return true;
}

} // namespace Packages
