// SPDX-License-Identifier: MIT
#include "pythonproject.h"

#include "rtcxml.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

using namespace Profile;

namespace Codegen {

PythonProject::PythonProject(QString folder, QString componentName)
    : m_folder(std::move(folder))
    , m_name(std::move(componentName))
{
}

std::optional<PythonProject> PythonProject::inFolder(const QString &folder)
{
    QFile xml(QDir(folder).filePath(QStringLiteral("RTC.xml")));
    if (!xml.open(QIODevice::ReadOnly))
        return std::nullopt;
    Diagnostics ignored;
    const std::optional<RtcProfile> profile = readRtcXml(xml.readAll(), xml.fileName(), &ignored);
    if (!profile)
        return std::nullopt;
    PythonProject project(folder, profile->basicInfo.name);
    if (!project.exists())
        return std::nullopt;
    return project;
}

bool PythonProject::exists() const
{
    const QDir folder(m_folder);
    return !m_folder.isEmpty() && !m_name.isEmpty() && QFileInfo(modulePath()).isFile()
        && !folder.exists(QStringLiteral("CMakeLists.txt"));
}

QString PythonProject::modulePath() const
{
    return QDir::cleanPath(QDir(m_folder).absoluteFilePath(m_name + QStringLiteral(".py")));
}

QStringList PythonProject::ownIdlFiles() const
{
    const QDir idl(QDir(m_folder).filePath(QStringLiteral("idl")));
    QStringList files;
    for (const QString &name : idl.entryList({QStringLiteral("*.idl")}, QDir::Files, QDir::Name))
        files << idl.filePath(name);
    return files;
}

QString PythonProject::idlCompileScript() const
{
    return QDir(m_folder).filePath(QStringLiteral("idlcompile.sh"));
}

std::optional<Diagnostic> PythonProject::parseLoadProblem(const QString &line)
{
    // Runtime::Manager's words (manager/managermodules.cpp, python/embed/embeddedpython.cpp).
    static const QRegularExpression raised(
        QStringLiteral("load_module: '([^']+)' does not load: (?:(.+?):(\\d+): )?(.*)$"));
    static const QRegularExpression noInit(QStringLiteral("load_module: '([^']+)' (has no init function .*)$"));
    QRegularExpressionMatch match = raised.match(line);
    if (match.hasMatch()) {
        const QString file = match.captured(2).isEmpty() ? match.captured(1) : match.captured(2);
        return Diagnostic::error(QDir::cleanPath(file), match.captured(3).toInt(), 0, match.captured(4));
    }
    match = noInit.match(line);
    if (match.hasMatch())
        return Diagnostic::error(QDir::cleanPath(match.captured(1)), 0, 0, match.captured(2));
    return std::nullopt;
}

} // namespace Codegen
