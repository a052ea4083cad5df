// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"

#include <QDateTime>
#include <QString>
#include <QStringList>

namespace Codegen {

/**
 * Backups of generated files, as RTC Builder keeps them: before a file is merged or
 * overwritten it is renamed `<file>YYYYMMDDHHMMSS` (local time) in its own folder. All files of
 * one generation share one time stamp, which names a backup set for "Code restore".
 */
namespace Backups {

/// How many backups of each file are kept unless configured otherwise.
inline constexpr int DefaultKept = 3;

/// `YYYYMMDDHHMMSS` of `when`.
QString stamp(const QDateTime &when);
/// `<file><stamp>`.
QString backupPath(const QString &file, const QString &stamp);
/// The stamp of a backup path of `file`, or an empty string when it is no backup of it.
QString stampOf(const QString &file, const QString &backup);
/// Existing backups of `file`, newest first.
QStringList backupsOf(const QString &file);
/// Deletes all but the newest `keep` backups of `file`; returns the deleted paths.
QStringList prune(const QString &file, int keep);

/// The stamps of all backup sets below `projectDir` (recursively), newest first.
QStringList stamps(const QString &projectDir);
/// The backup files (absolute paths) of one set.
QStringList filesOfSet(const QString &projectDir, const QString &stamp);
/**
 * Swaps the backup set `stamp` with the current files: each backup becomes the file again and
 * the file it replaces takes the backup's name, so restoring the same stamp again undoes it.
 * Checks every file first; returns false (nothing changed) when the set does not exist or a
 * rename fails on the way (what was swapped already is swapped back).
 */
bool restore(const QString &projectDir, const QString &stamp, Profile::Diagnostics *diagnostics);
/// Deletes every backup below `projectDir`; returns how many files were deleted.
int clear(const QString &projectDir);

} // namespace Backups

} // namespace Codegen
