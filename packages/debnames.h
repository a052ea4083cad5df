// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <optional>

namespace Packages {

/// Debian's rule for package names (Policy 5.6.1): lowercase letters, digits, '+', '-', '.', at
/// least two characters, starting with a letter or digit.
bool isValidPackageName(const QString &name);

/// Debian's rule for versions (Policy 5.6.12): [epoch:]upstream[-revision], the upstream part
/// starting with a digit and made of [A-Za-z0-9.+~-] (':' only after an epoch, '-' only when there
/// is a revision).
bool isValidVersion(const QString &version);

/**
 * The package name of a component: "rtc-<vendor>-<category>-<name>", each part lowercased with
 * every run of characters Debian does not allow replaced by '-' (an empty category is left out).
 * Nothing, with the reason in @p error, when the name is empty or the result is not a valid name.
 */
std::optional<QString> componentPackageName(const QString &vendor, const QString &category,
                                            const QString &name, QString *error);

/**
 * The Debian version of a profile version: trimmed, a leading 'v' before a digit dropped, spaces
 * and '_' made '.'. Nothing, with the reason in @p error, when the result is still not valid
 * (empty, not starting with a digit, other characters).
 */
std::optional<QString> debianVersion(const QString &profileVersion, QString *error);

/// The version as it appears in a .deb's file name (without the epoch).
QString versionInFileName(const QString &version);

/// Debian's order of versions (dpkg --compare-versions): <0, 0, >0.
int compareVersions(const QString &a, const QString &b);

} // namespace Packages
