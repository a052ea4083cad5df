// SPDX-License-Identifier: MIT
#include "repositoryprofiles.h"

#include "componentpackager.h"
#include "debnames.h"
#include "packagetool.h"
#include "repository.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QSaveFile>

namespace Packages {

namespace {

/// The newest version of each package, in the index's order.
QList<IndexEntry> newestVersions(const QList<IndexEntry> &entries)
{
    QHash<QString, int> newest;
    QList<IndexEntry> result;
    for (const IndexEntry &entry : entries) {
        const auto found = newest.constFind(entry.package());
        if (found == newest.constEnd()) {
            newest.insert(entry.package(), int(result.size()));
            result << entry;
        } else if (compareVersions(entry.version(), result.at(*found).version()) > 0) {
            result[*found] = entry;
        }
    }
    return result;
}

bool writeFile(const QString &path, const QByteArray &data, QString *error)
{
    QSaveFile file(path);
    if (!QDir().mkpath(QFileInfo(path).absolutePath()) || !file.open(QIODevice::WriteOnly)
        || file.write(data) != data.size() || !file.commit()) {
        *error = QStringLiteral("%1: cannot write: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace

std::optional<QByteArray> readPackageFile(const QString &debFile, const QString &path, QString *error)
{
    const ToolResult tar = runTool(QStringLiteral("dpkg-deb"), {QStringLiteral("--fsys-tarfile"), debFile});
    if (!tar.ok()) {
        *error = QStringLiteral("%1: %2").arg(debFile, tar.failure(QStringLiteral("dpkg-deb")));
        return std::nullopt;
    }
    ToolRun run;
    run.input = tar.out;
    const ToolResult member = runTool(QStringLiteral("tar"),
                                      {QStringLiteral("-xOf"), QStringLiteral("-"), QLatin1Char('.') + path}, run);
    if (!member.ok()) {
        *error = QStringLiteral("%1 has no %2").arg(QFileInfo(debFile).fileName(), path);
        return std::nullopt;
    }
    return member.out;
}

QList<PackagedProfile> packagedProfiles(const QList<IndexEntry> &entries, const QString &cacheFolder,
                                        const DebFileSource &debFile, QStringList *problems)
{
    QList<PackagedProfile> profiles;
    for (const IndexEntry &entry : newestVersions(entries)) {
        if (entry.control.value(Field::RtcProfileId).isEmpty())
            continue; // a Debian package of other software
        // The checksum tells a package republished under the same version from the one read before.
        const QString cached = QDir(cacheFolder).filePath(
            QStringLiteral("%1_%2_%3.xml")
                .arg(entry.package(), versionInFileName(entry.version()),
                     entry.control.value(QStringLiteral("SHA256")).left(16)));
        if (!QFileInfo::exists(cached)) {
            QString reason;
            const std::optional<QString> deb = debFile(entry, &reason);
            const std::optional<QByteArray> xml = deb ? readPackageFile(
                *deb, ComponentPackager::dataFolder(entry.package()) + QStringLiteral("/RTC.xml"), &reason)
                                                      : std::nullopt;
            if (!xml || !writeFile(cached, *xml, &reason)) {
                problems->append(QStringLiteral("%1 %2: %3").arg(entry.package(), entry.version(), reason));
                continue;
            }
        }
        profiles << PackagedProfile{entry, cached};
    }
    return profiles;
}

std::optional<QList<PackagedProfile>> readRepositoryProfiles(const QString &root, const QString &cacheFolder,
                                                             QStringList *problems, QString *error)
{
    Repository repository(root);
    if (!repository.open(error))
        return std::nullopt;
    const std::optional<QList<IndexEntry>> entries = repository.packages(error);
    if (!entries)
        return std::nullopt;
    return packagedProfiles(*entries, cacheFolder,
                            [&root](const IndexEntry &entry, QString *) -> std::optional<QString> {
                                return QDir(root).filePath(entry.filename());
                            },
                            problems);
}

} // namespace Packages
