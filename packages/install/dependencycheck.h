// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

namespace Packages {

class PackageStore;

/**
 * The entries of a Depends field (`a (>= 1.0), b | c`) this node does not satisfy, as written in
 * the field: each alternative is looked up among the component packages of @p store, then among
 * the Debian packages installed on the node (`dpkg-query -W`), its version relation compared the
 * way dpkg does. An empty list when all are met.
 */
QStringList unmetDependencies(const QString &depends, const PackageStore &store);

/// True when @p version satisfies @p relation (`<<`, `<=`, `=`, `>=`, `>>`; empty: any) @p wanted.
bool versionSatisfies(const QString &version, const QString &relation, const QString &wanted);

} // namespace Packages
