// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace Profile {
struct RtcProfile;
struct RtsProfile;
} // namespace Profile

namespace Planner {

/// Property names of RTC profiles (`rtcExt:Properties` of the basic information or the language)
/// and RTS profile components (`rtsExt:Properties`, which override the type's) that state
/// requirements. docs/planner.md describes them.
namespace Key {
inline const QString Devices = QStringLiteral("deploy.devices"); ///< devices the node must have
inline const QString CpuShare = QStringLiteral("deploy.cpu_share"); ///< CPUs it needs (0.5)
inline const QString NodeFactPrefix
    = QStringLiteral("deploy.node."); ///< `deploy.node.role: onboard`
inline const QString Process = QStringLiteral("deploy.process"); ///< shares the process so named
inline const QString Pin = QStringLiteral("deploy.pin"); ///< RTS only: the node it must run on
inline const QString Rate = QStringLiteral("deploy.rate"); ///< connectors: data rate in Hz
} // namespace Key

/// What one component of a system needs from the node it runs on.
struct ComponentRequirements
{
    QString instanceName; ///< its key in the system
    QString typeName; ///< implementation id (`ConsoleIn`): what a node must load or install
    QString typeId; ///< `RTC:vendor:category:name:version`
    QString language; ///< empty: any (no RTC profile)
    QStringList oses; ///< any of these (`Linux`); empty: any
    QStringList osVersions; ///< any of these, matched as a prefix of the distribution or release
    QStringList architectures; ///< any of these; empty: any
    QStringList devices; ///< every one must be in the node's `node.devices`
    QMap<QString, QString> nodeFacts; ///< user fact → value the node's `node.<fact>` must hold
    double cpuShare = 0; ///< CPUs it takes (0: not counted against capacity)
    QString pinnedNode; ///< empty: free
    QString process; ///< shares its process with the components of the same name; empty: own
};

/// A data connector between two components, with the rate its data flows at (Hz).
struct Link
{
    QString source;
    QString target;
    double rate = 0;
};

/// The requirements of a system, read from its RTS profile and its types' RTC profiles.
struct SystemRequirements
{
    QList<ComponentRequirements> components;
    QList<Link> links;
    QStringList warnings; ///< types without an RTC profile, unreadable property values
};

/**
 * The requirements of every component of @p system. The RTC profile of each type (by its
 * `RTC:…` id, else by implementation id) gives language, OS, OS versions, CPUs and the
 * `deploy.*` properties; the component's own properties override them. Members of a composite
 * whose execution context is shared (Periodic/Fsm EC or state shared) get one process.
 */
SystemRequirements readRequirements(const Profile::RtsProfile &system,
                                    const QHash<QString, Profile::RtcProfile> &typeProfiles);

/// Keeps @p profile in @p typeProfiles under its `RTC:…` id and its implementation id, the two
/// ways an RTS profile names a type.
void addTypeProfile(const Profile::RtcProfile &profile,
                    QHash<QString, Profile::RtcProfile> *typeProfiles);

} // namespace Planner
