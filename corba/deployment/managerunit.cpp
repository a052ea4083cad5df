// SPDX-License-Identifier: MIT
#include "managerunit.h"

#include "packagetool.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>

namespace Deploy {

ManagerUnit::ManagerUnit(bool system, QString configFile, QString unitDir, QString program)
    : m_system(system)
    , m_configFile(std::move(configFile))
    , m_unitDir(std::move(unitDir))
    , m_program(std::move(program))
{ }

QString ManagerUnit::managerProgram()
{
    const QString beside = QCoreApplication::applicationDirPath() + QStringLiteral("/rtmanager");
    if (QFileInfo(beside).isExecutable())
        return beside;
    const QString found = QStandardPaths::findExecutable(QStringLiteral("rtmanager"));
    return found.isEmpty() ? QStringLiteral("/usr/bin/rtmanager") : found;
}

QString ManagerUnit::text() const
{
    QString exec = m_program.isEmpty() ? managerProgram() : QFileInfo(m_program).absoluteFilePath();
    if (!m_configFile.isEmpty())
        exec += QStringLiteral(" -f ") + QFileInfo(m_configFile).absoluteFilePath();
    return QStringLiteral("# Written by RT Studio (rtctl node enable, or Online > Start a Manager at Boot); disabling removes it.\n"
                          "[Unit]\n"
                          "Description=RT Studio component manager (rtmanager)\n"
                          "Wants=network-online.target\n"
                          "After=network-online.target\n\n"
                          "[Service]\n"
                          "Type=simple\n"
                          "ExecStart=%1\n"
                          "Restart=on-failure\n"
                          "RestartSec=2\n\n"
                          "[Install]\n"
                          "WantedBy=%2\n")
        .arg(exec,
             m_system ? QStringLiteral("multi-user.target") : QStringLiteral("default.target"));
}

QString ManagerUnit::path() const
{
    QString dir = m_unitDir;
    if (dir.isEmpty() && m_system)
        dir = QStringLiteral("/etc/systemd/system");
    else if (dir.isEmpty())
        dir = QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation)
            + QStringLiteral("/systemd/user");
    return dir + QLatin1Char('/') + QLatin1String(fileName);
}

bool ManagerUnit::systemctl(const QString &action, QString *error) const
{
    if (!m_unitDir.isEmpty())
        return true;
    QStringList arguments;
    if (!m_system)
        arguments << QStringLiteral("--user");
    // The manager of units reads the new or removed file first.
    Packages::runTool(QStringLiteral("systemctl"),
                      arguments + QStringList {QStringLiteral("daemon-reload")});
    const Packages::ToolResult result = Packages::runTool(
        QStringLiteral("systemctl"), arguments + QStringList {action, QLatin1String(fileName)});
    if (result.ok())
        return true;
    *error = result.failure(QStringLiteral("systemctl ") + action);
    return false;
}

bool ManagerUnit::enable(QString *error) const
{
    if (!m_configFile.isEmpty() && !QFileInfo(m_configFile).isFile()) {
        *error = QStringLiteral("%1: no such configuration file").arg(m_configFile);
        return false;
    }
    QDir().mkpath(QFileInfo(path()).path());
    QSaveFile file(path());
    const QByteArray data = text().toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.commit()) {
        *error = QStringLiteral("cannot write %1: %2").arg(path(), file.errorString());
        return false;
    }
    return systemctl(QStringLiteral("enable"), error);
}

bool ManagerUnit::disable(QString *error) const
{
    if (!QFileInfo::exists(path())) {
        *error = QStringLiteral("%1: no unit to remove").arg(path());
        return false;
    }
    if (!systemctl(QStringLiteral("disable"), error))
        return false;
    if (!QFile::remove(path())) {
        *error = QStringLiteral("cannot remove %1").arg(path());
        return false;
    }
    return true;
}

} // namespace Deploy
