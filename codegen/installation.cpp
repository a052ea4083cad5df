// SPDX-License-Identifier: MIT
#include "installation.h"

#include <QCoreApplication>
#include <QDir>

namespace Codegen::Installation {

bool runsFromBuildTree()
{
    const QString program = QDir::cleanPath(QCoreApplication::applicationDirPath());
    const QString buildTree = QDir::cleanPath(QStringLiteral(RTSTUDIO_BUILD_TREE));
    return program == buildTree || program.startsWith(buildTree + QLatin1Char('/'));
}

QString prefix()
{
    if (runsFromBuildTree())
        return QDir::cleanPath(QStringLiteral(RTSTUDIO_BUILD_TREE));
    const QDir bin(QCoreApplication::applicationDirPath());
    if (bin.dirName() == QLatin1String("bin"))
        return QDir::cleanPath(bin.filePath(QStringLiteral("..")));
    return QStringLiteral(RTSTUDIO_INSTALL_PREFIX);
}

QString bundledIdlDirectory()
{
    if (runsFromBuildTree())
        return QStringLiteral(RTSTUDIO_SOURCE_IDL_DIR);
    return QDir(prefix()).filePath(QStringLiteral("share/rtstudio/idl"));
}

QString managerProgram()
{
    if (runsFromBuildTree())
        return QDir(QStringLiteral(RTSTUDIO_BUILD_TREE)).filePath(QStringLiteral("manager/rtmanager"));
    return QDir(prefix()).filePath(QStringLiteral("bin/rtmanager"));
}

QString rtctlProgram()
{
    if (runsFromBuildTree())
        return QDir(QStringLiteral(RTSTUDIO_BUILD_TREE)).filePath(QStringLiteral("cli/rtctl"));
    return QDir(prefix()).filePath(QStringLiteral("bin/rtctl"));
}

} // namespace Codegen::Installation
