// SPDX-License-Identifier: MIT
#include "packageinstaller.h"

#include "dependencycheck.h"

#include <componentpackager.h>
#include <packagetool.h>

#include <QFile>
#include <QFileInfo>

namespace Packages {

namespace {

const QByteArray signedHeader = "-----BEGIN PGP SIGNED MESSAGE-----";

/// The text a clear-signed message signs, its signature not verified (allow_unsigned only).
QByteArray clearSignedBody(const QByteArray &message)
{
    qsizetype start = message.indexOf("\n\n");
    const qsizetype end = message.indexOf("\n-----BEGIN PGP SIGNATURE-----");
    if (start < 0 || end < start)
        return message;
    start += 2;
    QByteArray body = message.mid(start, end - start + 1);
    // Dash-escaped lines (RFC 4880 7.1).
    body.replace("\n- ", "\n");
    return body.startsWith("- ") ? body.mid(2) : body;
}

} // namespace

QString InstallError::message() const
{
    return package.isEmpty() ? reason : package + QStringLiteral(": ") + reason;
}

PackageInstaller::PackageInstaller(const PackageStore &store, InstallPolicy policy)
    : m_store(store)
    , m_policy(std::move(policy))
{ }

std::optional<VerifiedRelease> PackageInstaller::trustedRelease(const QByteArray &inRelease,
                                                                QString *reason) const
{
    const bool isSigned = inRelease.startsWith(signedHeader);
    if (isSigned && !m_policy.keyring.isEmpty() && QFileInfo::exists(m_policy.keyring)) {
        QString verifyError;
        if (std::optional<VerifiedRelease> release
            = VerifiedRelease::verify(inRelease, m_policy.keyring, &verifyError))
            return release;
        if (!m_policy.allowUnsigned) {
            *reason = QStringLiteral("the repository's signature is not trusted: ") + verifyError;
            return std::nullopt;
        }
    } else if (!m_policy.allowUnsigned) {
        *reason = isSigned ? QStringLiteral("no keyring to verify the repository's signature with "
                                            "(manager.packages.keyring: '%1')")
                                 .arg(m_policy.keyring)
                           : QStringLiteral("the repository is unsigned (no InRelease) and "
                                            "manager.packages.allow_unsigned is not set");
        return std::nullopt;
    }
    return VerifiedRelease::parse(isSigned ? clearSignedBody(inRelease) : inRelease, reason);
}

std::optional<IndexEntry> PackageInstaller::indexEntry(const PackageSource &source,
                                                       const VerifiedRelease &release,
                                                       InstallError *error) const
{
    QString reason;
    if (!release.check(source.indexPath, source.index, &reason)) {
        error->reason = QStringLiteral("the index does not match the signed Release: ") + reason;
        return std::nullopt;
    }
    const std::optional<QList<DebControl>> entries = DebControl::parseAll(source.index, &reason);
    if (!entries) {
        error->reason = QStringLiteral("unreadable index %1: %2").arg(source.indexPath, reason);
        return std::nullopt;
    }
    for (const DebControl &control : *entries) {
        const IndexEntry entry {control};
        const bool byPath = !source.poolPath.isEmpty() && entry.filename() == source.poolPath;
        const bool byName = source.poolPath.isEmpty() && entry.package() == source.package
            && entry.version() == source.version;
        if (byPath || byName) {
            error->package = entry.package() + QLatin1Char(' ') + entry.version();
            return entry;
        }
    }
    error->reason = QStringLiteral("not listed in the repository's index %1").arg(source.indexPath);
    return std::nullopt;
}

bool PackageInstaller::checkNode(const IndexEntry &entry, QString *reason) const
{
    const QString architecture = entry.architecture();
    if (architecture != QLatin1String("all") && architecture != m_policy.architecture) {
        *reason = QStringLiteral("built for architecture %1, this node is %2")
                      .arg(architecture, m_policy.architecture);
        return false;
    }
    const QString abi = entry.control.value(Field::SdkAbi);
    if (!abi.isEmpty() && !m_policy.sdkAbi.isEmpty() && abi != m_policy.sdkAbi) {
        *reason = QStringLiteral("built for the component SDK %1, this manager's SDK is %2")
                      .arg(abi, m_policy.sdkAbi);
        return false;
    }
    const QStringList unmet
        = unmetDependencies(entry.control.value(QStringLiteral("Depends")), m_store);
    if (!unmet.isEmpty()) {
        *reason = QStringLiteral("missing dependencies on this node: ")
            + unmet.join(QStringLiteral(", "));
        return false;
    }
    for (const InstalledPackage &installed : m_store.versions(entry.package())) {
        if (installed.version == entry.version()) {
            *reason = QStringLiteral("already installed");
            return false;
        }
    }
    return true;
}

std::optional<InstalledPackage>
PackageInstaller::unpack(const IndexEntry &entry, const QString &debFile, QString *reason) const
{
    const std::optional<QString> staging = m_store.createStaging(reason);
    if (!staging)
        return std::nullopt;
    const auto failed = [this, &staging, reason](const QString &why) {
        *reason = why;
        m_store.discard(*staging);
        return std::nullopt;
    };
    const ToolResult unpacked
        = runTool(QStringLiteral("dpkg-deb"),
                  {QStringLiteral("-x"), debFile, *staging + QStringLiteral("/root")});
    if (!unpacked.ok())
        return failed(QStringLiteral("unpacking: ") + unpacked.failure(QStringLiteral("dpkg-deb")));
    QFile control(*staging + QStringLiteral("/control"));
    const QByteArray text = entry.control.toText();
    if (!control.open(QIODevice::WriteOnly) || control.write(text) != text.size()
        || !control.flush())
        return failed(
            QStringLiteral("cannot write %1: %2").arg(control.fileName(), control.errorString()));
    control.close();
    QString why;
    if (!m_store.commit(*staging, entry.package(), entry.version(), &why))
        return failed(why);
    for (const InstalledPackage &installed : m_store.versions(entry.package())) {
        if (installed.version == entry.version())
            return installed;
    }
    *reason = QStringLiteral("not found in the store after installing");
    return std::nullopt;
}

std::optional<InstalledPackage> PackageInstaller::install(const PackageSource &source,
                                                          InstallError *error) const
{
    error->package = source.package.isEmpty() ? QFileInfo(source.poolPath).fileName()
                                              : source.package + QLatin1Char(' ') + source.version;
    const std::optional<VerifiedRelease> release = trustedRelease(source.inRelease, &error->reason);
    if (!release)
        return std::nullopt;
    const std::optional<IndexEntry> entry = indexEntry(source, *release, error);
    if (!entry)
        return std::nullopt;
    if (!checkPackageFile(*entry, source.debFile, &error->reason)) {
        // Its message names the package already, and the file is the manager's download.
        const QString named = error->package + QStringLiteral(": ");
        if (error->reason.startsWith(named))
            error->reason.remove(0, named.size());
        error->reason.replace(source.debFile, QStringLiteral("the package"));
        return std::nullopt;
    }
    if (!checkNode(*entry, &error->reason))
        return std::nullopt;
    return unpack(*entry, source.debFile, &error->reason);
}

} // namespace Packages
