// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtcprofile.h"
#include "rtsprofile.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace Profile {

/// Which of the two profile kinds a file holds.
enum class ProfileKind { Unknown, Rtc, Rts };
/// How a profile file is written.
enum class FileFormat { Xml, Yaml };

/// `.yaml` / `.yml` (any case) → Yaml; everything else → Xml.
FileFormat formatForFileName(const QString &path);
/// Tells XML from YAML by the text itself (an XML document starts with '<').
FileFormat detectFormat(const QByteArray &data);
/// Looks at the root element (XML) or the top key (YAML); never parses the whole file.
ProfileKind detectProfileKind(const QByteArray &data);

/// A profile read from a file, with the warnings the reader had.
struct LoadedProfile
{
    ProfileKind kind = ProfileKind::Unknown;
    FileFormat format = FileFormat::Xml;
    std::optional<RtcProfile> rtc;
    std::optional<RtsProfile> rts;
    Diagnostics diagnostics; ///< warnings; errors make loading fail
};

/// Reads a profile from memory; `fileName` is only used in diagnostics.
std::optional<LoadedProfile> loadProfileData(const QByteArray &data, const QString &fileName,
                                             Diagnostics *diagnostics);
/// Reads an RTC or RTS profile, XML or YAML, detected by content. On failure returns nothing
/// and appends errors naming the file (and line/column where the text is at fault).
std::optional<LoadedProfile> loadProfileFile(const QString &path, Diagnostics *diagnostics);

/// The profile as text in the given format.
QByteArray serializeRtcProfile(const RtcProfile &profile, FileFormat format);
QByteArray serializeRtsProfile(const RtsProfile &profile, FileFormat format);

/// Writes the profile atomically (temporary file + rename) in the format the extension names.
/// The old file stays untouched when anything fails; the reason goes to `diagnostics`.
bool saveRtcProfileFile(const RtcProfile &profile, const QString &path, Diagnostics *diagnostics);
bool saveRtsProfileFile(const RtsProfile &profile, const QString &path, Diagnostics *diagnostics);

/// Writes bytes atomically; used by the save functions and by tools that write other files.
bool writeFileAtomically(const QString &path, const QByteArray &data, Diagnostics *diagnostics);

} // namespace Profile
