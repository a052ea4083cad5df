// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtcprofile.h"

class QUndoCommand;

namespace Builder {

class ComponentModel;

/**
 * The Basic page's Import and Export of a component profile.
 *
 * Import reads an RTC.xml or RTC Profile YAML (told apart by content) and makes one undoable
 * command that replaces the open component with it; Export writes the current profile, XML or
 * YAML by the file's extension, atomically (a failed export leaves the old file as it was).
 */
namespace ProfileTransfer {

/**
 * The command that puts the profile of `path` into `model`; null when the file cannot be read,
 * holds a system (RTS Profile) rather than a component, or equals what is open. Problems
 * (errors naming FILE:LINE:COL, and the reader's warnings) go to `diagnostics`.
 */
QUndoCommand *importCommand(ComponentModel *model, const QString &path,
                            Profile::Diagnostics *diagnostics);

/// Writes `profile` to `path` (format by extension); false with the reason on failure.
bool exportProfile(const Profile::RtcProfile &profile, const QString &path,
                   Profile::Diagnostics *diagnostics);

/// The file dialog filter for profiles: "RTC Profile (*.xml *.yaml *.yml)" and "All files (*)".
QString fileFilter();

} // namespace ProfileTransfer

} // namespace Builder
