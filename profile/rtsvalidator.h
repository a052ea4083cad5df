// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtsprofile.h"

namespace Profile {

/**
 * Checks a system for problems a file format cannot express: duplicate instance names and
 * connector ids, connector ends and message-sequence targets that name no component (or no port of
 * a component that lists its ports), unknown enumeration values, malformed ids and numbers.
 *
 * Each finding carries its severity, the source location of the offending element (when the
 * profile was read from a file) and `fileName`.
 */
Diagnostics validateRtsProfile(const RtsProfile &profile, const QString &fileName);

} // namespace Profile
