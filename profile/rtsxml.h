// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtsprofile.h"

#include <QByteArray>

namespace Profile {

/**
 * Reads an RTS Profile XML file (OpenRTP's RT System Editor, rtsprofile).
 *
 * Accepts the legacy spellings of the reference tools (groupID, VersionUpLog, lower-case Location
 * direction, isRequired `1`, elements in any order, missing rts:abstract). Unknown attributes and
 * elements are kept in the model's XmlExtras. Never throws; problems become `FILE:LINE:COL`
 * diagnostics. Returns nothing (plus at least one error) when the file is not an RTS Profile.
 */
std::optional<RtsProfile> readRtsXml(const QByteArray &data, const QString &fileName,
                                     Diagnostics *diagnostics);

/// Writes the schema form with OpenRTP's prefixes and xsi:types; unknown content back in place.
QByteArray writeRtsXml(const RtsProfile &profile);

} // namespace Profile
