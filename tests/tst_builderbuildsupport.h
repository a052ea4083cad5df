// SPDX-License-Identifier: MIT
#pragma once

// The Build tests' fixture projects (tests/data/projectbuild/<name>/: tiny CMake projects that
// need neither OpenRTM-aist nor the SDK), copied where a build may write.

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QString>

namespace BuildFixture {

inline QString source(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/projectbuild/")) + name;
}

/// Copies the fixture `name` into `target` (created when missing); false when a file failed.
inline bool copy(const QString &name, const QString &target)
{
    const QDir from(source(name));
    bool ok = from.exists() && QDir().mkpath(target);
    QDirIterator it(from.path(), QDir::Files, QDirIterator::Subdirectories);
    while (ok && it.hasNext()) {
        const QString file = it.next();
        const QString copy = QDir(target).filePath(from.relativeFilePath(file));
        ok = QDir().mkpath(QFileInfo(copy).absolutePath()) && QFile::copy(file, copy);
    }
    return ok;
}

/// True while process `pid` runs (a zombie nobody reaped counts as ended).
inline bool processRuns(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return false;
    const QByteArray text = stat.readAll();
    // `pid (name) S …`: the state follows the closing parenthesis of the name.
    const qsizetype close = text.lastIndexOf(')');
    return close >= 0 && close + 2 < text.size() && text.at(close + 2) != 'Z';
}

} // namespace BuildFixture
