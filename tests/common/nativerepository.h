// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace TestSupport {

/**
 * Makes a component repository in the folder @p dir holding one package built for this
 * machine's architecture from tests/data/packages/debtree (type NativeProbe, its RTC profile
 * inside), with dpkg-deb and `rtctl repo init` / `publish`. Returns the repository's folder and
 * sets @p arch to the architecture; empty, with what failed in @p error, when a step fails.
 */
QString makeNativeRepository(const QString &dir, QString *arch, QString *error);

} // namespace TestSupport
