// SPDX-License-Identifier: MIT
#include "backups.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>

using namespace Profile;

namespace Codegen::Backups {

namespace {

constexpr int StampLength = 14;

const QRegularExpression &stampSuffix()
{
    static const QRegularExpression re(QStringLiteral("^(.+)(\\d{14})$"));
    return re;
}

/// Every backup below a folder, as (path, stamp) pairs. A name only counts as a backup when the
/// file it belongs to (name without stamp) still exists beside it, so that a user file that
/// happens to end in 14 digits is never touched.
QList<QPair<QString, QString>> allBackups(const QString &projectDir)
{
    QList<QPair<QString, QString>> found;
    QDirIterator it(projectDir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        const QRegularExpressionMatch match = stampSuffix().match(path);
        if (match.hasMatch() && QFileInfo::exists(match.captured(1)))
            found.append({path, match.captured(2)});
    }
    std::sort(found.begin(), found.end());
    return found;
}

Diagnostic failure(const QString &file, const QString &message)
{
    return Diagnostic::error(file, 0, 0, message);
}

} // namespace

QString stamp(const QDateTime &when)
{
    return when.toString(QStringLiteral("yyyyMMddHHmmss"));
}

QString backupPath(const QString &file, const QString &stamp)
{
    return file + stamp;
}

QString stampOf(const QString &file, const QString &backup)
{
    if (backup.size() != file.size() + StampLength || !backup.startsWith(file))
        return {};
    const QString suffix = backup.mid(file.size());
    const bool digits = std::all_of(suffix.cbegin(), suffix.cend(),
                                    [](QChar c) { return c.isDigit() && c.unicode() < 128; });
    return digits ? suffix : QString();
}

QStringList backupsOf(const QString &file)
{
    const QFileInfo info(file);
    const QDir dir = info.dir();
    QStringList backups;
    const QStringList names = dir.entryList({info.fileName() + QStringLiteral("*")},
                                            QDir::Files | QDir::Hidden, QDir::Name);
    for (const QString &name : names) {
        const QString path = dir.filePath(name);
        if (!stampOf(dir.filePath(info.fileName()), path).isEmpty())
            backups << path;
    }
    std::reverse(backups.begin(), backups.end()); // the stamp sorts by time: newest first
    return backups;
}

QStringList prune(const QString &file, int keep)
{
    QStringList removed;
    const QStringList backups = backupsOf(file);
    for (int i = std::max(keep, 0); i < backups.size(); ++i) {
        if (QFile::remove(backups.at(i)))
            removed << backups.at(i);
    }
    return removed;
}

QStringList stamps(const QString &projectDir)
{
    QStringList result;
    for (const auto &backup : allBackups(projectDir)) {
        if (!result.contains(backup.second))
            result << backup.second;
    }
    std::sort(result.begin(), result.end(), std::greater<QString>());
    return result;
}

QStringList filesOfSet(const QString &projectDir, const QString &stamp)
{
    QStringList files;
    for (const auto &backup : allBackups(projectDir)) {
        if (backup.second == stamp)
            files << backup.first;
    }
    return files;
}

bool restore(const QString &projectDir, const QString &stamp, Diagnostics *diagnostics)
{
    const QStringList backups = filesOfSet(projectDir, stamp);
    if (backups.isEmpty()) {
        diagnostics->append(failure(projectDir, QStringLiteral("no backup set %1").arg(stamp)));
        return false;
    }
    // Each swap goes through a third name so that no content is ever lost on failure.
    QStringList swapped;
    for (const QString &backup : backups) {
        const QString file = backup.left(backup.size() - StampLength);
        const QString aside = file + QStringLiteral(".rtstudio-restore");
        QFile::remove(aside);
        const bool ok = QFile::rename(file, aside) && QFile::rename(backup, file)
            && QFile::rename(aside, backup);
        if (!ok) {
            if (QFile::exists(aside) && !QFile::exists(file))
                QFile::rename(aside, file);
            diagnostics->append(failure(file, QStringLiteral("cannot restore from %1")
                                                  .arg(QFileInfo(backup).fileName())));
            for (const QString &done : std::as_const(swapped)) {
                const QString doneFile = done.left(done.size() - StampLength);
                const QString back = doneFile + QStringLiteral(".rtstudio-restore");
                QFile::rename(doneFile, back);
                QFile::rename(done, doneFile);
                QFile::rename(back, done);
            }
            return false;
        }
        swapped << backup;
    }
    return true;
}

int clear(const QString &projectDir)
{
    int count = 0;
    for (const auto &backup : allBackups(projectDir))
        count += QFile::remove(backup.first) ? 1 : 0;
    return count;
}

} // namespace Codegen::Backups
