// SPDX-License-Identifier: MIT
#pragma once

#include <debcontrol.h>

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace Packages {

/// One version of a component package in a PackageStore.
struct InstalledPackage
{
    QString name;
    QString version;
    QString architecture;
    QStringList componentTypes; ///< X-RTC-Types
    QString path; ///< <store>/<name>/<version>
    DebControl control;

    /// The folders holding its component modules (usr/lib/<multiarch>/rtstudio/components/<name>).
    QStringList moduleDirs() const;
};

/**
 * A manager's own package store, which needs no root: each installed package version is a folder
 *
 *   <root>/<name>/<version>/control      the package's control data
 *   <root>/<name>/<version>/root/...     its files as `dpkg-deb -x` unpacks them
 *
 * An install unpacks into a staging folder in the store (`<root>/.staging-*`), which then takes
 * its place in one rename; an uninstall renames the version folder away before deleting it. So a
 * failed or killed install or uninstall leaves no half package listed, and prepare() (at a
 * manager's start) deletes what such a run left.
 */
class PackageStore
{
public:
    explicit PackageStore(QString root);

    /// `$XDG_DATA_HOME/rtstudio/packages` (`~/.local/share` when unset).
    static QString defaultRoot();

    QString root() const { return m_root; }
    /// Deletes leftover staging folders and empty package folders; false with the reason when
    /// the store is not a folder. A missing store is made by the first install.
    bool prepare(QString *error) const;

    /// Every installed version, by name, each package's newest version first.
    QList<InstalledPackage> installed() const;
    /// The versions of @p name, newest first.
    QList<InstalledPackage> versions(const QString &name) const;

    /// A new, empty staging folder; nothing with the reason when it cannot be made.
    std::optional<QString> createStaging(QString *error) const;
    /// Moves the unpacked @p staging into place as @p name @p version (refused when present).
    bool commit(const QString &staging, const QString &name, const QString &version,
                QString *error) const;
    /// Deletes a staging folder.
    void discard(const QString &staging) const;
    /// Removes one installed version.
    bool remove(const InstalledPackage &package, QString *error) const;

    /// The module folders of every installed version (each package's newest first), or of
    /// @p version only when given.
    QStringList moduleDirs(const QString &version) const;

    static constexpr const char *stagingPrefix = ".staging-";

private:
    std::optional<InstalledPackage> read(const QString &name, const QString &version) const;

    QString m_root;
};

} // namespace Packages
