// SPDX-License-Identifier: MIT
#include "planrepository.h"

#include "deployer.h"
#include "profileio.h"
#include "remoteindex.h"
#include "repository.h"
#include "repositoryprofiles.h"
#include "requirements.h"

#include <QTemporaryDir>

namespace Deploy {

std::optional<PlanRepository> readPlanRepository(const QString &root, QStringList *warnings,
                                                 QString *error)
{
    Packages::Repository repository(root);
    if (!repository.open(error))
        return std::nullopt;
    const auto entries = repository.packages(error);
    if (!entries)
        return std::nullopt;
    PlanRepository result;
    Packages::RemoteIndex index;
    index.entries = *entries;
    result.packages = plannerPackages(index);
    QTemporaryDir cache;
    const auto packaged = Packages::readRepositoryProfiles(root, cache.path(), warnings, error);
    if (!packaged)
        return std::nullopt;
    for (const Packages::PackagedProfile &p : *packaged) {
        Profile::Diagnostics diagnostics;
        const auto loaded = Profile::loadProfileFile(p.profileFile, &diagnostics);
        if (loaded && loaded->rtc)
            Planner::addTypeProfile(*loaded->rtc, &result.typeProfiles);
    }
    return result;
}

} // namespace Deploy
