// SPDX-License-Identifier: MIT
#pragma once

#include "planproblem.h"
#include "rtcprofile.h"

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace Deploy {

/// What a component repository gives the planner.
struct PlanRepository
{
    QList<Planner::RepositoryPackage> packages; ///< what can be installed, and where
    /// The RTC profiles its packages ship, under their `RTC:…` id and implementation id: the
    /// requirements of their types (see Planner::addTypeProfile()).
    QHash<QString, Profile::RtcProfile> typeProfiles;
};

/**
 * Reads the component repository folder @p root (made by `rtctl repo init`): its index and the
 * RTC profiles inside its packages (unpacked into a temporary folder). Nothing, with the reason
 * in @p error, when the repository cannot be opened or its index read; packages whose profile
 * cannot be read are named in @p warnings. Reads files only, but may take a while for a large
 * repository: call it off the GUI thread.
 */
std::optional<PlanRepository> readPlanRepository(const QString &root, QStringList *warnings,
                                                 QString *error);

} // namespace Deploy
