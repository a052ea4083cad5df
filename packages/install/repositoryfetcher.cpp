// SPDX-License-Identifier: MIT
#include "repositoryfetcher.h"

#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QNetworkRequest>
#include <QSslConfiguration>

namespace Packages {

namespace {

std::optional<QByteArray> readLocal(const QString &path, QString *error, bool *missing)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *missing = !file.exists();
        *error = QStringLiteral("cannot read %1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return file.readAll();
}

QUrl withPath(QUrl url, const QString &path)
{
    url.setFragment(QString());
    url.setPath(path);
    return url;
}

bool writeFile(const QString &path, const QByteArray &data, QString *error)
{
    QFile file(path);
    if (file.open(QIODevice::WriteOnly) && file.write(data) == data.size() && file.flush())
        return true;
    *error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    return false;
}

} // namespace

RepositoryFetcher::RepositoryFetcher(QString nodeArchitecture, int timeoutMs,
                                     QString caCertificates)
    : m_architecture(std::move(nodeArchitecture))
    , m_timeoutMs(timeoutMs)
    , m_caCertificates(std::move(caCertificates))
{ }

std::optional<QByteArray> RepositoryFetcher::get(const QUrl &url, QString *error,
                                                 bool *missing) const
{
    bool ignored = false;
    missing = missing ? missing : &ignored;
    *missing = false;
    if (url.isLocalFile())
        return readLocal(url.toLocalFile(), error, missing);
    if (url.scheme() != QLatin1String("http") && url.scheme() != QLatin1String("https")) {
        *error
            = QStringLiteral("%1: only http, https and file URLs are fetched").arg(url.toString());
        return std::nullopt;
    }
    // A network access manager of this thread: installs run in the ORB's threads.
    QNetworkAccessManager network;
    QNetworkRequest request(url);
    request.setTransferTimeout(m_timeoutMs);
    if (!m_caCertificates.isEmpty() && url.scheme() == QLatin1String("https")) {
        QSslConfiguration ssl = QSslConfiguration::defaultConfiguration();
        if (!ssl.addCaCertificates(m_caCertificates)) {
            *error = QStringLiteral("cannot read the certificate authorities %1")
                         .arg(m_caCertificates);
            return std::nullopt;
        }
        request.setSslConfiguration(ssl);
    }
    QNetworkReply *reply = network.get(request);
    QEventLoop loop;
    QObject::connect(reply, &QNetworkReply::finished, &loop, &QEventLoop::quit);
    if (!reply->isFinished())
        loop.exec();
    const int status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
    const QByteArray data = reply->readAll();
    const QString reason = reply->errorString();
    const bool ok = reply->error() == QNetworkReply::NoError;
    delete reply;
    if (ok)
        return data;
    *missing = status == 404 || status == 410;
    *error = QStringLiteral("cannot fetch %1: %2").arg(url.toString(), reason);
    return std::nullopt;
}

std::optional<PackageSource> RepositoryFetcher::fetch(const QUrl &url, const QString &folder,
                                                      QString *error) const
{
    const QString path = url.path();
    const qsizetype pool = path.lastIndexOf(QLatin1String("/pool/"));
    const QString fileName = QFileInfo(path).fileName();
    const QStringList parts = fileName.chopped(fileName.endsWith(QLatin1String(".deb")) ? 4 : 0)
                                  .split(QLatin1Char('_'));
    if (pool < 0 || !fileName.endsWith(QLatin1String(".deb")) || parts.size() != 3) {
        *error = QStringLiteral("%1: not the URL of a package in a repository's pool "
                                "(…/pool/COMPONENT/…/NAME_VERSION_ARCH.deb[#SUITE])")
                     .arg(url.toString());
        return std::nullopt;
    }
    const QString root = path.left(pool);
    const QString suite = url.fragment().isEmpty() ? QStringLiteral("stable") : url.fragment();
    const QString component = path.mid(pool + 6).section(QLatin1Char('/'), 0, 0);
    const QString architecture = parts.at(2) == QLatin1String("all") ? m_architecture : parts.at(2);
    PackageSource source;
    source.poolPath = path.mid(pool + 1);
    source.indexPath
        = component + QStringLiteral("/binary-") + architecture + QStringLiteral("/Packages");
    const QString dists = root + QStringLiteral("/dists/") + suite + QLatin1Char('/');
    bool missing = false;
    std::optional<QByteArray> inRelease
        = get(withPath(url, dists + QStringLiteral("InRelease")), error, &missing);
    // An unsigned repository has only a Release; the installer decides whether to take it.
    if (!inRelease && missing)
        inRelease = get(withPath(url, dists + QStringLiteral("Release")), error);
    const std::optional<QByteArray> index
        = inRelease ? get(withPath(url, dists + source.indexPath), error) : std::nullopt;
    const std::optional<QByteArray> deb = index ? get(withPath(url, path), error) : std::nullopt;
    if (!deb)
        return std::nullopt;
    source.inRelease = *inRelease;
    source.index = *index;
    source.debFile = folder + QLatin1Char('/') + fileName;
    if (!writeFile(source.debFile, *deb, error))
        return std::nullopt;
    return source;
}

} // namespace Packages
