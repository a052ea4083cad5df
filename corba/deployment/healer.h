// SPDX-License-Identifier: MIT
#pragma once

#include "deployer.h"
#include "rtsprofile.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>
#include <QStringList>

namespace Deploy {

/**
 * Plans where every component of @p profile runs on @p nodes (those that answer; the planner with
 * each type loadable or installable from @p options' repository): components in @p free may go
 * anywhere, those in @p fixed stay on their node, the others keep their `deploy.pin` when they
 * have one. Component instance → node; empty, with the reason in @p why, when there is no plan.
 * Blocking: call it off the GUI thread.
 */
QHash<QString, QString> planPlacement(const Profile::RtsProfile &profile, const QStringList &nodes,
                                      const DeployOptions &options, const QHash<QString, QString> &fixed,
                                      const QStringList &free, QString *why);

/// Pins each component of @p placement to its node (`deploy.pin`) in @p profile.
void pinPlacement(Profile::RtsProfile *profile, const QHash<QString, QString> &placement);

/// How a deployed system is kept as planned.
struct WatchOptions
{
    DeployOptions deploy; ///< where the system's components are found, created and installed from
    /// The nodes (manager addresses) the system may move to; the nodes it runs on are added.
    QStringList nodes;
    /// How long a node may take to answer a check before it counts as gone (ms).
    int probeTimeoutMs = 1000;
};

/**
 * Keeps a deployed system running when a node dies: check() asks every node's manager whether
 * it is there (all at once, each under the probe timeout); when one is gone, the components it
 * ran are planned anew onto the nodes that answer (Planner::DeploymentPlanner, the system's other
 * components pinned where they run, installing from the repository where needed), pinned there
 * in the system, and deployed (create, configure, connect, activate in the system's order) with
 * the rest of the system left as it is. A node that comes back gets nothing moved back; it is a
 * candidate again for the next heal. Every action is a step of the report check() returns.
 */
class SystemHealer
{
    // What each round did, shown in the online diagram's status (English in rtctl deploy --watch).
    Q_DECLARE_TR_FUNCTIONS(Deploy::SystemHealer)

public:
    /// @p profile: the system as deployed; its components' nodes are their `deploy.pin`, else
    /// where the deploy created them (see creatingNode()).
    SystemHealer(Profile::RtsProfile profile, WatchOptions options);

    /// Reads where each component runs now (the live system) and the nodes to watch. Blocking.
    void start();
    /**
     * One round: checks the nodes and heals when some are gone. Returns an empty report (no
     * steps) when nothing happened. Blocking: call it off the GUI thread.
     */
    DeployReport check(const DeployControl &control = {});

    /// The system with the placement it has now (moved components pinned to their new node).
    const Profile::RtsProfile &system() const { return m_profile; }
    /// Component instance → the node it runs on.
    const QHash<QString, QString> &placement() const { return m_placement; }
    QStringList nodes() const { return m_nodes; }
    QSet<QString> goneNodes() const { return m_gone; }

private:
    /// The nodes that answer now, and those that do not.
    QSet<QString> probe() const;
    DeployReport heal(const QStringList &lost, const QSet<QString> &alive, const DeployControl &control);
    /// The new node of each of @p orphans, planned on @p alive; empty with @p why when no plan.
    QHash<QString, QString> replan(const QStringList &orphans, const QSet<QString> &alive, QString *why) const;

    Profile::RtsProfile m_profile;
    WatchOptions m_options;
    QStringList m_nodes;
    QSet<QString> m_gone;
    QHash<QString, QString> m_placement;
};

} // namespace Deploy
