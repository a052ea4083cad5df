// SPDX-License-Identifier: MIT
#include "remoteindex.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>
#include <QSet>

namespace Packages {

namespace {

QUrl repositoryUrl(const QString &text)
{
    const QUrl url(text);
    if (!url.scheme().isEmpty() && url.scheme().size() > 1)
        return url;
    // A folder: fragments are not part of file names here, so `#SUITE` is split off by hand.
    const qsizetype hash = text.lastIndexOf(QLatin1Char('#'));
    QUrl local = QUrl::fromLocalFile(QFileInfo(hash < 0 ? text : text.left(hash)).absoluteFilePath());
    if (hash >= 0)
        local.setFragment(text.mid(hash + 1));
    return local;
}

QUrl below(QUrl root, const QString &relative)
{
    QString path = root.path();
    if (!path.endsWith(QLatin1Char('/')))
        path += QLatin1Char('/');
    root.setPath(path + relative);
    root.setFragment(QString());
    return root;
}

} // namespace

QString RemoteIndex::packageUrl(const IndexEntry &entry) const
{
    QUrl url = below(root, entry.filename());
    url.setFragment(suite);
    return url.toString();
}

std::optional<RemoteIndex> readRemoteIndex(const QString &repository,
                                           const RepositoryFetcher &fetcher, QString *error)
{
    RemoteIndex index;
    index.root = repositoryUrl(repository);
    index.suite = index.root.fragment().isEmpty() ? QStringLiteral("stable") : index.root.fragment();
    index.root.setFragment(QString());
    const QString dists = QStringLiteral("dists/") + index.suite + QLatin1Char('/');
    const std::optional<QByteArray> releaseText
        = fetcher.get(below(index.root, dists + QStringLiteral("Release")), error);
    if (!releaseText)
        return std::nullopt;
    QString reason;
    const std::optional<DebControl> release = DebControl::parse(*releaseText, &reason);
    if (!release) {
        *error = QStringLiteral("%1: %2").arg(below(index.root, dists + QStringLiteral("Release")).toString(), reason);
        return std::nullopt;
    }
    const QStringList components = release->value(QStringLiteral("Components")).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QStringList architectures
        = release->value(QStringLiteral("Architectures")).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QSet<QString> seen;
    for (const QString &component : components) {
        for (const QString &architecture : architectures) {
            const QUrl url = below(index.root, dists + component + QStringLiteral("/binary-")
                                       + architecture + QStringLiteral("/Packages"));
            bool missing = false;
            const std::optional<QByteArray> text = fetcher.get(url, error, &missing);
            if (!text && missing)
                continue;
            if (!text)
                return std::nullopt;
            const auto paragraphs = DebControl::parseAll(*text, &reason);
            if (!paragraphs) {
                *error = QStringLiteral("%1: %2").arg(url.toString(), reason);
                return std::nullopt;
            }
            for (const DebControl &control : *paragraphs) {
                IndexEntry entry {control};
                if (!seen.contains(entry.key())) {
                    seen.insert(entry.key());
                    index.entries << entry;
                }
            }
        }
    }
    error->clear();
    return index;
}

std::optional<QList<PackagedProfile>> readRemoteRepositoryProfiles(const QString &repository,
                                                                   const RepositoryFetcher &fetcher,
                                                                   const QString &cacheFolder,
                                                                   QStringList *problems, QString *error)
{
    const std::optional<RemoteIndex> index = readRemoteIndex(repository, fetcher, error);
    if (!index)
        return std::nullopt;
    const QString downloads = QDir(cacheFolder).filePath(QStringLiteral("downloads"));
    const auto download = [&](const IndexEntry &entry, QString *reason) -> std::optional<QString> {
        const std::optional<QByteArray> deb = fetcher.get(below(index->root, entry.filename()), reason);
        if (!deb)
            return std::nullopt;
        QSaveFile file(QDir(downloads).filePath(QFileInfo(entry.filename()).fileName()));
        if (!QDir().mkpath(downloads) || !file.open(QIODevice::WriteOnly) || file.write(*deb) != deb->size()
            || !file.commit()) {
            *reason = QStringLiteral("%1: cannot write: %2").arg(file.fileName(), file.errorString());
            return std::nullopt;
        }
        return file.fileName();
    };
    QList<PackagedProfile> profiles = packagedProfiles(index->entries, cacheFolder, download, problems);
    // The packages were needed for their RTC.xml only.
    QDir(downloads).removeRecursively();
    return profiles;
}

} // namespace Packages
