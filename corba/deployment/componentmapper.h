// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "deployreport.h"
#include "namingbrowser.h"

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QMutex>
#include <QString>
#include <QStringList>

namespace Profile {
struct RtsProfile;
struct RtsComponent;
} // namespace Profile

namespace Deploy {

/// Where a saved system is put: the live name servers and manager it is mapped onto.
struct TargetOptions
{
    /// Name servers (`host[:port]`) searched for components by instance name. Empty: the servers
    /// named by live pathUri values, else `RTCTREE_NAMESERVERS`, else `localhost`.
    QStringList nameServers;
    /// The manager that creates missing components: an rtshell path (`/ns/h.host_cxt/manager.mgr`)
    /// or a corbaloc (`corbaloc::host:2810`). Empty: each component's saved host context's
    /// `manager.mgr` (OpenRTM's default manager name), when its pathUri is a live path.
    QString manager;
    /// Saved host context name (`hostB` of `hostB.host_cxt` in a pathUri) → `manager_address`
    /// (`host:port`) of the manager that hosts that host's components; used when creating.
    QHash<QString, QString> hostManagers;
    /// Create components that are not found, through `manager`.
    bool create = false;
};

/// How one saved component is found on the live system.
enum class MappingKind {
    Existing, ///< a live component with this instance name and type was found
    Create, ///< not found; will be created through the manager
    Missing ///< not found (or of another type) and will not be created
};

/// "existing", "create", "missing": the names rtctl prints, never translated.
QString mappingKindName(MappingKind kind);

/// One saved component and its live counterpart (or how it will be created).
struct ComponentMapping
{
    QString instanceName; ///< the saved instance name (the component's key in the system)
    QString typeName; ///< the type part of the saved `RTC:vendor:category:type:version` id
    bool required = true;
    MappingKind kind = MappingKind::Missing;
    QString path; ///< the live rtshell path (or the manager's path + name when created)
    QString ior; ///< the live object reference; empty until found or created
    QString createArgument; ///< `Type?instance_name=…&…` for create_component
    /// The manager that creates it: `-m`, else the `manager.mgr` beside its saved live path.
    QString manager;
    QString message; ///< why it is missing, or a warning (other vendor/version)
    bool activate = true; ///< take part in start/stop (a GUI mapping dialog may untick it)
    /// An existing component's ports and connectors as the plan read them: a first guess for a
    /// step that runs right after planning, to be read again when it does not hold.
    std::vector<Corba::PortInfo> plannedPorts;
};

/**
 * Maps every component of a saved system onto the live system: by its pathUri when that is a
 * live path that resolves, else by instance name under the chosen name servers, else (with
 * `create`) as a component to create through the manager. Remote failures become `message`s,
 * never exceptions.
 */
class ComponentMapper
{
    // The reasons a component is not found are shown in the Restore dialog (English in rtctl).
    Q_DECLARE_TR_FUNCTIONS(Deploy::ComponentMapper)

public:
    explicit ComponentMapper(TargetOptions options);

    /// The mapping of every component of `profile`, in file order.
    QList<ComponentMapping> map(const Profile::RtsProfile &profile);
    /// The `create_component` argument for `component` (type, instance name, EC rate and the
    /// `manager_address` of its saved host when one is configured).
    QString createArgument(const Profile::RtsComponent &component) const;
    /// Problems met while looking (unreachable name servers, a manager that does not resolve).
    QStringList problems() const { return m_problems; }

    /// "no live component named X", in the UI's language.
    static QString notFound(const QString &instanceName);
    /// The type name of a saved component id (`RTC:v:c:Type:1.0` → `Type`; the id itself when it
    /// does not have that form).
    static QString typeNameOf(const QString &componentId);
    /// True when `pathUri` names a live object rather than an offline file.
    static bool isLivePath(const QString &pathUri);
    /// The IOR of the manager at `address` (rtshell path or corbaloc); throws Corba::Error.
    static QString resolveManager(const QString &address);

    /// A live component found in the RTC tree.
    struct LiveEntry
    {
        QString path;
        QString ior;
    };
    /**
     * The components at or below each of `paths` (rtshell paths: servers, contexts, managers or
     * components), by instance name; naming-context bindings win over a manager's listing.
     * Paths that cannot be walked, and components bound under an instance name that another one
     * found has too (only the first is kept), are added to `problems`. With Check::NamesOnly
     * only the name servers are asked (named components, no manager's listing): much quicker.
     */
    static QHash<QString, LiveEntry> liveComponents(
        const QStringList &paths, QStringList *problems,
        Corba::NamingBrowser::Check check = Corba::NamingBrowser::Check::Objects);

private:
    void indexServers(const Profile::RtsProfile &profile);
    /// The components bound by name on the servers (walked on first need).
    const QHash<QString, LiveEntry> &namedIndex();
    /// The components the managers know beside those bound by name (walked on first need).
    const QHash<QString, LiveEntry> &fullIndex();
    ComponentMapping mapOne(const Profile::RtsComponent &component);
    bool checkLive(ComponentMapping &mapping, const LiveEntry &entry) const;

    TargetOptions m_options;
    QStringList m_serverPaths;
    QMutex m_indexMutex;
    QHash<QString, LiveEntry> m_byInstance; ///< bound by name
    bool m_named = false;
    QHash<QString, LiveEntry> m_fullIndex;
    bool m_fullIndexed = false;
    QStringList m_problems;
};

} // namespace Deploy
