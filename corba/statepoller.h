// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QStringList>

#include <memory>
#include <vector>

namespace Corba {

/**
 * Reads the life-cycle state of many components in their first execution context, as the online
 * views do every second: several at once and one remote call per component. A component keeps its
 * contexts for its life, so the references of each component and of its context are kept between
 * rounds; an entry goes when a call through it fails or when it was not asked about for a minute.
 * Safe to use from several threads.
 */
class StatePoller
{
public:
    StatePoller();
    ~StatePoller();
    StatePoller(const StatePoller &) = delete;
    StatePoller &operator=(const StatePoller &) = delete;

    /// The state of each component (`iors[i]`, named `paths[i]` in errors); Unknown where one
    /// did not answer.
    std::vector<LifeCycleState> poll(const QStringList &iors, const QStringList &paths);

private:
    struct Cache;
    std::unique_ptr<Cache> m_cache;
};

} // namespace Corba
