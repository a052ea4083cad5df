// SPDX-License-Identifier: MIT
#pragma once

#include "deployreport.h"
#include "restoreplan.h"

namespace Profile {
struct RtsProfile;
}

namespace Deploy {

/**
 * Restores a saved system onto live components following `plan` (see planRestore()): creates the
 * components marked Create through `options.manager`, connects every connector of the plan with
 * its saved properties and id, writes the configuration sets and activates the saved active set,
 * and sets the execution-context rates.
 *
 * Transactional: when a step of a required component or connector fails (or the caller cancels),
 * the components this restore created are made to exit and the connections it made are
 * disconnected, in reverse order; the report lists them as rolled back. Configuration values
 * written before the failure stay. Safe to call from a worker thread.
 */
DeployReport restoreSystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                           const TargetOptions &options, const DeployControl &control = {});

/**
 * Disconnects every connector of `profile` by its id (rtteardown). Connectors that are not
 * connected, or whose components are not found, are skipped.
 */
DeployReport teardownSystem(const RestorePlan &plan, const DeployControl &control = {});

} // namespace Deploy
