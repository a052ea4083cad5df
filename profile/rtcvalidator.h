// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtcprofile.h"

namespace Profile {

/**
 * Checks a component profile for what RTC Builder would refuse or what breaks code generation:
 * duplicate data/service port names, duplicate configuration names, duplicate variable names,
 * unknown enumeration values (componentType, activityType, portType, direction, position),
 * a malformed id (`RTC:vendor:category:name:version`), bad numbers (executionRate,
 * maxInstances ≥ 0), names outside `[0-9A-Za-z_\-:]`, a radio widget without an enumeration
 * constraint.
 *
 * Each finding carries its severity, the source location of the offending element (when the
 * profile was read from a file) and `fileName`.
 */
Diagnostics validateRtcProfile(const RtcProfile &profile, const QString &fileName);

} // namespace Profile
