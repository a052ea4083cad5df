// SPDX-License-Identifier: MIT
#pragma once

#include "debcontrol.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace Profile {
struct RtcProfile;
}

namespace Packages {

/// The custom control fields of component packages.
namespace Field {
inline const QString RtcTypes = QStringLiteral("X-RTC-Types"); ///< implementation ids it provides
inline const QString RtcProfileId
    = QStringLiteral("X-RTC-Profile-Id"); ///< RTC:vendor:category:name:version
inline const QString RtcProfileSha256
    = QStringLiteral("X-RTC-Profile-SHA256"); ///< of the shipped RTC.xml
inline const QString SdkAbi
    = QStringLiteral("X-RTStudio-SDK-ABI"); ///< SONAME of the SDK library it links
} // namespace Field

/// What `rtctl package` is asked to do.
struct PackageOptions
{
    QString projectDir; ///< the component project (RTC.xml at its top)
    QString buildDir; ///< where it was built; empty: <projectDir>/build
    /// A .deb file name, or a folder to write <package>_<version>_<arch>.deb into; empty: the
    /// current directory.
    QString output;
    QString packageName; ///< instead of the derived name
    QString maintainer; ///< "Name <mail>" instead of the profile's creator/vendor
    QStringList depends; ///< more Depends entries (other component packages)
};

/// A package made.
struct PackageResult
{
    QString debFile;
    DebControl control;
    QStringList files; ///< absolute paths the package installs, sorted
    QStringList warnings;
};

/**
 * Makes the Debian binary package of a built component project with dpkg-deb, its Depends from
 * dpkg-shlibdeps. Installed layout, for package P on multiarch triplet M:
 *
 *   /usr/lib/M/rtstudio/components/P/       <Name>.so, <Name>Comp (compiled components)
 *   /usr/share/rtstudio/components/P/       RTC.xml, the .conf files, the IDL files in idl/,
 *                                           Python sources
 *
 * Libraries that come from no Debian package (the SDK of a build tree) are left out of Depends
 * with a warning; the SDK's own ABI is the X-RTStudio-SDK-ABI field.
 */
class ComponentPackager
{
public:
    explicit ComponentPackager(PackageOptions options);

    /// Builds the package; nothing, with a message naming the file or step, when it cannot.
    std::optional<PackageResult> build(QString *error);

    /// /usr/lib/<multiarch>/rtstudio/components/<package>
    static QString libraryFolder(const QString &multiarch, const QString &package);
    /// /usr/share/rtstudio/components/<package>
    static QString dataFolder(const QString &package);
    /// "RTC:vendor:category:name:version" of @p profile (its id when set).
    static QString profileId(const Profile::RtcProfile &profile);

private:
    struct Staged;
    bool stage(Staged *staged, QString *error);
    bool readProfile(Staged *staged, QString *error);
    bool copyFiles(Staged *staged, QString *error);
    bool findBinaries(Staged *staged, QString *error);
    bool computeDepends(Staged *staged, QString *error);
    void writeControl(Staged *staged);
    bool buildDeb(Staged *staged, QString *error);

    PackageOptions m_options;
};

} // namespace Packages
