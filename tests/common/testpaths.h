// SPDX-License-Identifier: MIT
// Where a test finds the sources, its data and the programs of its build tree. The paths the tests
// are told (RTSTUDIO_TEST_DATA_DIR, RTMANAGER_PATH, ...) reach them as calls of these functions with
// a path relative to the build tree or to the sources (tests/testpaths.cmake), resolved when the
// test runs: object files then name no checkout, and ccache serves them to another clone.
#pragma once

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>

#include <cstdio>
#include <cstdlib>

namespace TestPaths {

/// The build tree of the running program: the nearest folder above it that holds CMakeCache.txt.
inline const QString &buildDir()
{
    static const QString dir = [] {
        QDir folder = QFileInfo(QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath()).dir();
        while (!folder.exists(QStringLiteral("CMakeCache.txt"))) {
            if (!folder.cdUp()) {
                std::fputs("test paths: the program is not inside a CMake build tree\n", stderr);
                std::abort();
            }
        }
        return folder.absolutePath();
    }();
    return dir;
}

/// The sources the build tree was configured from (its CMakeCache.txt's CMAKE_HOME_DIRECTORY).
inline const QString &sourceDir()
{
    static const QString dir = [] {
        QFile cache(buildDir() + QStringLiteral("/CMakeCache.txt"));
        if (cache.open(QIODevice::ReadOnly)) {
            const QByteArray key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
            while (!cache.atEnd()) {
                const QByteArray line = cache.readLine().trimmed();
                if (line.startsWith(key))
                    return QString::fromLocal8Bit(line.mid(key.size()));
            }
        }
        std::fputs("test paths: the build tree's CMakeCache.txt names no source folder\n", stderr);
        std::abort();
    }();
    return dir;
}

/// @p relative (to the build tree) as an absolute path.
inline QString build(const char *relative)
{
    return QDir::cleanPath(buildDir() + QLatin1Char('/') + QString::fromUtf8(relative));
}

/// @p relative (to the sources) as an absolute path.
inline QString source(const char *relative)
{
    return QDir::cleanPath(sourceDir() + QLatin1Char('/') + QString::fromUtf8(relative));
}

} // namespace TestPaths
