// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtsprofile.h"

#include <QByteArray>

namespace Profile {

/**
 * Reads an RTS Profile in rtsprofile's YAML dialect (top key `rtsProfile:`, lowerCamel keys,
 * `"rtsExt::…"` extension keys, dates as {year, month, day, hour, minute, second}).
 *
 * Unknown keys are kept in the model's RtsYamlExtras. Never throws; syntax and type errors
 * become `FILE:LINE:COL` diagnostics. Returns nothing (plus at least one error) when the text is
 * not an RTS Profile.
 */
std::optional<RtsProfile> readRtsYaml(const QByteArray &data, const QString &fileName,
                                      Diagnostics *diagnostics);

/// Writes the rtsprofile YAML dialect; unknown keys read from YAML are written back.
QByteArray writeRtsYaml(const RtsProfile &profile);

} // namespace Profile
