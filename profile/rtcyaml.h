// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtcprofile.h"

#include <QByteArray>

namespace Profile {

/**
 * Reads an RTC Profile in RTC Builder's YAML dialect: top key `rtcProfile:`, lowerCamel keys,
 * `"rtcDoc::doc"` / `"rtcExt::…"` extension keys, `actions: onExecute: implemented: true`, dates
 * as xs:dateTime text or as {year, month, day, hour, minute, second, …} mappings. The legacy keys
 * of older files (`doc`, `varname`, `position`, `versionUpLog`, `subscriprionType`) are accepted.
 *
 * Unknown keys are kept as XmlExtras (as elements or attributes of the element they belong to),
 * so they survive both a YAML save and a save as XML. Never throws; YAML syntax and type errors
 * become `FILE:LINE:COL` diagnostics. Returns nothing (plus at least one error) when the text is
 * not an RTC Profile.
 */
std::optional<RtcProfile> readRtcYaml(const QByteArray &data, const QString &fileName,
                                      Diagnostics *diagnostics);

/// Writes RTC Builder's YAML dialect (schema keys, `"rtcDoc::doc"`, `"rtcExt::…"`).
QByteArray writeRtcYaml(const RtcProfile &profile);

} // namespace Profile
