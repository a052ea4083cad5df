// SPDX-License-Identifier: MIT
#pragma once

#include "rtcprofile.h"

#include <QStringList>

namespace Builder {

/**
 * What differs between two versions of a component, one readable line per change ("Data port
 * 'in' added", "Basic: name 'A' → 'B'", "onExecute: off → on" …), in the order of the file.
 * Empty when the profiles are equal. Used to show what applying the RTC.xml page will change.
 */
QStringList describeChanges(const Profile::RtcProfile &before, const Profile::RtcProfile &after);

} // namespace Builder
