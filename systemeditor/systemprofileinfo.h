// SPDX-License-Identifier: MIT
#pragma once

#include <QSet>
#include <QString>

#include <optional>

namespace Profile {
struct RtsProfile;
}

namespace SystemEditor {

/**
 * What the reference's save dialog asks about a system: vendor, system name and version (which
 * make the id `RTSystem:<vendor>:<name>:<version>`), the abstract, the creation and update
 * dates and which component instances are required (`isRequired`).
 */
struct SystemProfileInfo
{
    QString vendor;
    QString systemName;
    QString version;
    std::optional<QString> abstract;
    QString creationDate; ///< xs:dateTime text
    QString updateDate; ///< xs:dateTime text
    QSet<QString> requiredComponents; ///< instance names

    /// `RTSystem:<vendor>:<name>:<version>`.
    QString systemId() const;
    /// The info a profile holds (an id that does not split keeps empty parts).
    static SystemProfileInfo fromProfile(const Profile::RtsProfile &profile);
    /// Writes id, abstract, dates and the components' isRequired into `profile`.
    void applyTo(Profile::RtsProfile &profile) const;
    /// Empty when acceptable, else a message per problem (empty or ':'-holding parts).
    QStringList problems() const;

    bool operator==(const SystemProfileInfo &other) const;
    bool operator!=(const SystemProfileInfo &other) const { return !(*this == other); }
};

} // namespace SystemEditor
