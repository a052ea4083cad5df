// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "profileio.h"

#include <QHash>

namespace SystemEditor {

class SystemModel;

/// A system file read from disk with the RTC profiles its components point at.
struct LoadedSystem
{
    Profile::RtsProfile profile;
    Profile::FileFormat format = Profile::FileFormat::Xml;
    QHash<QString, Profile::RtcProfile> rtcProfiles; ///< by instance name; only those found
    QHash<QString, QString> rtcFiles; ///< instance name → the RTC profile file it came from
    Profile::Diagnostics warnings; ///< reader warnings and RTC profiles that could not be read
};

/**
 * The local file a component's `pathUri` names: a `file:` URI, or a path absolute or relative to
 * the folder of `systemFilePath`. Empty when the URI names no existing file (e.g. a naming
 * service path such as `localhost/ConsoleIn0.rtc`).
 */
QString resolvePathUri(const QString &pathUri, const QString &systemFilePath);

/**
 * Reads the RTC profiles of the components whose pathUri resolves to a file. Components without
 * one are left out (their ports come from the system file); a file that exists but is no
 * readable RTC profile becomes a warning naming the component.
 */
QHash<QString, Profile::RtcProfile> resolveRtcProfiles(const Profile::RtsProfile &profile,
                                                       const QString &systemFilePath,
                                                       Profile::Diagnostics *warnings,
                                                       QHash<QString, QString> *files = nullptr);

/// Opens an RTS profile (XML or YAML, by content) and resolves its components' RTC profiles.
/// Nothing, with errors, when the file is no readable RTS profile.
std::optional<LoadedSystem> loadSystemFile(const QString &path, Profile::Diagnostics *diagnostics);

/// How saveSystemFile() writes.
struct SaveOptions
{
    /// Offline save: write each known RTC profile to `RTCs/<instance>.xml` beside the system
    /// file and point the component's pathUri (and COMPONENT_PATH_ID of connector ends) there.
    bool copyRtcProfiles = true;
    /// Set updateDate to now (and creationDate when empty).
    bool stampDates = true;
    /// The format to write; by default the one the file name's extension names.
    std::optional<Profile::FileFormat> format;
};

/// The profile as saveSystemFile() writes it (dates, pathUris `RTCs/<instance>.xml`, relative
/// to the system file), without writing anything.
Profile::RtsProfile profileForSave(const SystemModel &model, const SaveOptions &options);

/**
 * Saves the model's system to `path` (format by extension): RTC copies first, then the system
 * file, each atomically (temporary file + rename), so a failure leaves the old system file
 * untouched. On success the model takes the saved pathUris and dates (not an undoable edit: it
 * is where the files now are). On failure returns false with reasons in `diagnostics` and the
 * model unchanged.
 */
bool saveSystemFile(SystemModel &model, const QString &path, Profile::Diagnostics *diagnostics,
                    const SaveOptions &options = {});

} // namespace SystemEditor
