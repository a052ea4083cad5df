// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Deploy {

/**
 * The systemd unit `rtmanager.service` that starts rtmanager at boot with its configuration file
 * (its package store, keyring and precreated components are that file's). A user unit
 * (`~/.config/systemd/user`, started with the user's session or at boot with lingering) or a
 * system unit (`/etc/systemd/system`); @p unitDir writes it elsewhere and leaves systemctl out.
 */
class ManagerUnit
{
public:
    /// @p program: the rtmanager to start; empty: the one beside rtctl, else the one on PATH.
    ManagerUnit(bool system, QString configFile, QString unitDir, QString program = QString());

    /// The unit's text.
    QString text() const;
    /// Where the unit file is written.
    QString path() const;
    /// Writes the unit and, unless a unit folder was given, enables it with systemctl.
    bool enable(QString *error) const;
    /// Disables the unit (systemctl, unless a unit folder was given) and removes its file.
    bool disable(QString *error) const;

    static constexpr const char *fileName = "rtmanager.service";

private:
    bool systemctl(const QString &action, QString *error) const;
    /// The rtmanager beside this rtctl, else the one on PATH.
    static QString managerProgram();

    bool m_system;
    QString m_configFile;
    QString m_unitDir;
    QString m_program;
};

} // namespace Deploy
