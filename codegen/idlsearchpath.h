// SPDX-License-Identifier: MIT
#pragma once

#include "rtcprofile.h"

#include <QString>
#include <QStringList>

namespace Codegen {

/**
 * The folders the IDL of a profile's types is looked up in, as both `rtctl gen` and the RTC
 * Builder's Generate use them: `leading` (e.g. the bundled OpenRTM set), the profile's folder and
 * its `idl/`, the folders of the IDL files the profile's ports name (relative to the profile's
 * folder), then `trailing`. Folders that do not exist are left out, each folder appears once.
 *
 * `profileDir` empty (a profile never saved): only absolute IDL file names of ports count.
 */
QStringList idlSearchDirs(const Profile::RtcProfile &profile, const QString &profileDir,
                          const QStringList &leading, const QStringList &trailing = {});

} // namespace Codegen
