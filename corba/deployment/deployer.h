// SPDX-License-Identifier: MIT
#pragma once

#include "deployreport.h"
#include "planproblem.h"
#include "remoteindex.h"
#include "restoreplan.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

namespace Profile {
struct RtsProfile;
}

namespace Deploy {

/// Where a system is deployed from and onto.
struct DeployOptions
{
    /// The live system: name servers and the managers that create components. A deploy always
    /// creates what is missing.
    TargetOptions target;
    /// The component repository (http, https or file URL, or a folder; `#SUITE` picks a suite)
    /// the packages of missing component types come from. Empty: nothing is installed, and a
    /// type no node loads fails the plan.
    QString repository;
    /// Certificate authorities (PEM) trusted for an https repository besides the system's.
    QString caCertificates;
    /// How long one install may take on a manager (ms).
    int installTimeoutMs = 120000;
    /// Start the system once restored (rtctl deploy); the Restore dialog leaves that to Start All.
    bool start = true;
};

/// One package a deploy installs on one node.
struct PackageInstall
{
    QString node; ///< the manager's address as the restore creates through it
    QString package;
    QString version;
    QString url; ///< what the manager fetches
    QStringList types; ///< the system's component types it brings
};

/**
 * What a deploy will do: the restore of the system (which components are found, which created
 * and by which manager) and the packages installed before, per node. Nothing is changed by
 * planning; a dry run prints it.
 */
struct DeployPlan
{
    RestorePlan restore;
    QList<PackageInstall> installs;
    /// Reasons the deploy cannot start: a type no node can load or install, an unreachable node,
    /// an unreadable repository. A deploy with problems changes nothing.
    QStringList problems;

    /// The nodes that create components, in the order first named.
    QStringList nodes() const;
    /// The installs and the restore plan, one line each, then the problems (translated in the GUI).
    QString toText() const;

    Q_DECLARE_TR_FUNCTIONS(Deploy::DeployPlan)
};

/// The node that creates @p mapping: its `deploy.pin` when the system pins it, else the manager
/// the restore creates through (the component's own, else the target's).
QString creatingNode(const ComponentMapping &mapping, const TargetOptions &target);

/// The node @p component is pinned to (its `deploy.pin`), or an empty string.
QString pinOf(const Profile::RtsComponent &component);

/// Makes the pinned components of @p plan created by their node directly; with @p create, also
/// those the mapper found no manager for.
void applyPins(const Profile::RtsProfile &profile, RestorePlan *plan, bool create);

/// The index of @p options' repository; nothing with the reason in @p error when it cannot be
/// read (an empty index when no repository is given).
std::optional<Packages::RemoteIndex> readRepositoryIndex(const DeployOptions &options, QString *error);

/// The packages of @p index as the planner weighs them.
QList<Planner::RepositoryPackage> plannerPackages(const Packages::RemoteIndex &index);

/**
 * Plans the deploy of @p profile: maps it onto the live system as a restore with create does,
 * reads the facts of every node that will create components (its loadable types, architecture
 * and SDK ABI, all nodes at once) and the repository's index, and picks for each type a node
 * cannot load the newest package that fits it. Blocking: call it off the GUI thread.
 */
DeployPlan planDeploy(const Profile::RtsProfile &profile, const DeployOptions &options);

/**
 * Deploys following @p plan as one transaction: installs the packages (the nodes side by side),
 * restores the system (create, connect, configure) and starts it in its activation order. When a
 * required step fails or the caller cancels, everything this deploy did is undone in reverse
 * order: the system stopped and disconnected, the components it created made to exit and the
 * packages it installed uninstalled. A plan with problems is refused before any change.
 */
DeployReport deploySystem(const Profile::RtsProfile &profile, const DeployPlan &plan,
                          const DeployOptions &options, const DeployControl &control = {});

/**
 * The reverse of a deploy: stops the system, disconnects its connectors, makes its components
 * exit and, with @p uninstall, removes from every node of the system the installed packages that
 * provide the system's component types (a package still used by other components there is kept,
 * with the reason in the report). Components that are not found are skipped.
 */
DeployReport undeploySystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                            const TargetOptions &target, bool uninstall,
                            const DeployControl &control = {});

} // namespace Deploy
