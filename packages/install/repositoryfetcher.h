// SPDX-License-Identifier: MIT
#pragma once

#include "packageinstaller.h"

#include <QByteArray>
#include <QString>
#include <QUrl>

#include <optional>

namespace Packages {

/**
 * Fetches a package of a Debian repository (made by `rtctl repo`) by the URL of its .deb in the
 * repository's pool (http, https through QtNetwork, or file), with the InRelease (the Release of
 * an unsigned repository) and the Packages index that vouch for it: the repository is the part of
 * the URL before `/pool/`, the component the folder after it, the suite the URL's fragment
 * (`#SUITE`, default `stable`), the index that of the package's architecture (the node's for
 * `all`). Every transfer gives up after the timeout.
 */
class RepositoryFetcher
{
public:
    /// @p caCertificates: a PEM file of certificate authorities https servers are trusted by,
    /// besides the system's (a fleet's own); empty: the system's only.
    RepositoryFetcher(QString nodeArchitecture, int timeoutMs, QString caCertificates = QString());

    /**
     * Downloads into @p folder; the PackageSource an installer takes. Nothing, with the file and
     * the reason in @p error, when a file cannot be fetched or the URL names no pool file.
     */
    std::optional<PackageSource> fetch(const QUrl &url, const QString &folder,
                                       QString *error) const;

    /// The contents at @p url; nothing with the reason. @p missing is set when the server or the
    /// file system says there is no such file.
    std::optional<QByteArray> get(const QUrl &url, QString *error, bool *missing = nullptr) const;

private:
    QString m_architecture;
    int m_timeoutMs;
    QString m_caCertificates;
};

} // namespace Packages
