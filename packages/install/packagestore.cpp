// SPDX-License-Identifier: MIT
#include "packagestore.h"

#include <componentpackager.h>
#include <debnames.h>

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QStandardPaths>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace Packages {

namespace {

const QString controlFile = QStringLiteral("control");
const QString filesFolder = QStringLiteral("root");

QStringList subfolders(const QString &path)
{
    return QDir(path).entryList(QDir::Dirs | QDir::NoDotAndDotDot | QDir::Hidden, QDir::Name);
}

bool isStaging(const QString &name)
{
    return name.startsWith(QLatin1String(PackageStore::stagingPrefix));
}

} // namespace

QStringList InstalledPackage::moduleDirs() const
{
    // The multiarch folder is the one the package was built for; look at what it holds.
    QStringList dirs;
    const QString lib = path + QLatin1Char('/') + filesFolder + QStringLiteral("/usr/lib");
    for (const QString &triplet : subfolders(lib)) {
        const QString dir
            = lib + QLatin1Char('/') + triplet + QStringLiteral("/rtstudio/components/") + name;
        if (QFileInfo(dir).isDir())
            dirs << dir;
    }
    const QString plain = lib + QStringLiteral("/rtstudio/components/") + name;
    if (QFileInfo(plain).isDir())
        dirs << plain;
    return dirs;
}

PackageStore::PackageStore(QString root)
    : m_root(QDir::cleanPath(std::move(root)))
{ }

QString PackageStore::defaultRoot()
{
    QString data = qEnvironmentVariable("XDG_DATA_HOME");
    if (data.isEmpty())
        data = QDir::homePath() + QStringLiteral("/.local/share");
    return data + QStringLiteral("/rtstudio/packages");
}

bool PackageStore::prepare(QString *error) const
{
    // A manager that never installs leaves no store behind; the first install makes it.
    const QFileInfo info(m_root);
    if (!info.exists())
        return true;
    if (!info.isDir()) {
        *error = QStringLiteral("the package store %1 is not a folder").arg(m_root);
        return false;
    }
    for (const QString &name : subfolders(m_root)) {
        const QString path = m_root + QLatin1Char('/') + name;
        if (isStaging(name))
            QDir(path).removeRecursively();
        else if (subfolders(path).isEmpty())
            QDir(m_root).rmdir(name);
    }
    return true;
}

std::optional<InstalledPackage> PackageStore::read(const QString &name,
                                                   const QString &version) const
{
    InstalledPackage package;
    package.path = m_root + QLatin1Char('/') + name + QLatin1Char('/') + version;
    QFile file(package.path + QLatin1Char('/') + controlFile);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const std::optional<DebControl> control = DebControl::parse(file.readAll());
    if (!control)
        return std::nullopt;
    package.control = *control;
    package.name = control->value(QStringLiteral("Package"));
    package.version = control->value(QStringLiteral("Version"));
    package.architecture = control->value(QStringLiteral("Architecture"));
    package.componentTypes
        = control->value(Field::RtcTypes)
              .split(QRegularExpression(QStringLiteral("[,\\s]+")), Qt::SkipEmptyParts);
    return package;
}

QList<InstalledPackage> PackageStore::versions(const QString &name) const
{
    QList<InstalledPackage> found;
    for (const QString &version : subfolders(m_root + QLatin1Char('/') + name)) {
        if (std::optional<InstalledPackage> package = read(name, version))
            found << *package;
    }
    std::sort(found.begin(), found.end(), [](const InstalledPackage &a, const InstalledPackage &b) {
        return compareVersions(a.version, b.version) > 0;
    });
    return found;
}

QList<InstalledPackage> PackageStore::installed() const
{
    QList<InstalledPackage> all;
    for (const QString &name : subfolders(m_root)) {
        if (!isStaging(name))
            all << versions(name);
    }
    return all;
}

std::optional<QString> PackageStore::createStaging(QString *error) const
{
    if (!QDir().mkpath(m_root)) {
        *error = QStringLiteral("cannot create the package store %1").arg(m_root);
        return std::nullopt;
    }
    for (int attempt = 0; attempt < 16; ++attempt) {
        const QString name = QLatin1String(stagingPrefix)
            + QString::number(QRandomGenerator::global()->generate64(), 36);
        if (QDir(m_root).mkdir(name))
            return m_root + QLatin1Char('/') + name;
    }
    *error = QStringLiteral("cannot create a staging folder in %1").arg(m_root);
    return std::nullopt;
}

bool PackageStore::commit(const QString &staging, const QString &name, const QString &version,
                          QString *error) const
{
    const QString folder = m_root + QLatin1Char('/') + name;
    const QString target = folder + QLatin1Char('/') + version;
    if (QFileInfo::exists(target)) {
        *error = QStringLiteral("%1 %2 is already installed").arg(name, version);
        return false;
    }
    QDir().mkpath(folder);
    // One rename: the version is either absent or complete, whenever the process stops.
    if (std::rename(QFile::encodeName(staging).constData(), QFile::encodeName(target).constData())
        != 0) {
        *error = QStringLiteral("cannot move %1 into place as %2: %3")
                     .arg(staging, target, QString::fromLocal8Bit(std::strerror(errno)));
        QDir(m_root).rmdir(name);
        return false;
    }
    return true;
}

void PackageStore::discard(const QString &staging) const
{
    if (!staging.isEmpty())
        QDir(staging).removeRecursively();
}

bool PackageStore::remove(const InstalledPackage &package, QString *error) const
{
    // Renamed out of the listing first, so that a stop halfway leaves nothing that looks installed.
    const std::optional<QString> trash = createStaging(error);
    if (!trash)
        return false;
    const QString target = *trash + QStringLiteral("/removed");
    if (std::rename(QFile::encodeName(package.path).constData(),
                    QFile::encodeName(target).constData())
        != 0) {
        *error = QStringLiteral("cannot remove %1: %2")
                     .arg(package.path, QString::fromLocal8Bit(std::strerror(errno)));
        discard(*trash);
        return false;
    }
    discard(*trash);
    QDir(m_root).rmdir(package.name);
    return true;
}

QStringList PackageStore::moduleDirs(const QString &version) const
{
    QStringList dirs;
    for (const InstalledPackage &package : installed()) {
        if (version.isEmpty() || package.version == version)
            dirs << package.moduleDirs();
    }
    return dirs;
}

} // namespace Packages
