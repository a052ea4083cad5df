// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtcprofile.h"

#include <QByteArray>

namespace Profile {

/**
 * Reads an RTC Profile XML file (RTC.xml of OpenRTP's RTC Builder), versions 0.3, 0.2 and the
 * older files of OpenRTM-aist's templates.
 *
 * Legacy spellings are mapped onto the schema fields (`varname` → variableName,
 * `VersionUpLog` → versionUpLogs, lower-case positions, `subscriprionType`); anything the model
 * does not know (e.g. `rtc:Java` under Language) is kept in the XmlExtras of the element it was
 * found in. Missing required attributes are warnings. Never throws; problems become
 * `FILE:LINE:COL` diagnostics. Returns nothing (plus at least one error) when the text is not an
 * RTC Profile (not XML, wrong root element, wrong namespace).
 */
std::optional<RtcProfile> readRtcXml(const QByteArray &data, const QString &fileName,
                                     Diagnostics *diagnostics);

/// Writes version 0.3 in the schema's spelling with OpenRTP's prefixes and xsi:types
/// (basic_info_ext, action_status_doc, configuration_ext, dataport_ext …); unknown content
/// goes back in place. The format version written is always RtcProfile::CurrentVersion: saving
/// upgrades an old file, as RTC Builder does.
QByteArray writeRtcXml(const RtcProfile &profile);

/// The element tree writeRtcXml() serialises.
XmlNode rtcProfileToXml(const RtcProfile &profile);

} // namespace Profile
