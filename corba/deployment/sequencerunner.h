// SPDX-License-Identifier: MIT
#pragma once

#include "deployreport.h"
#include "restoreplan.h"

namespace Profile {
struct RtsProfile;
enum class RtsSequenceKind;
} // namespace Profile

namespace Deploy {

/// What a message sequence does to each execution context it names.
enum class SequenceAction {
    Activate, ///< activate the component in the context (Activation)
    Deactivate, ///< deactivate it (Deactivation)
    StartContext, ///< start the context (StartUp)
    StopContext ///< stop the context (ShutDown)
};

/**
 * Runs `action` on every execution context of every mapped component as rtshell's rtstart /
 * rtstop execute the message sequence `kind` of `profile`:
 * - immediate actions first: the sequence's targets without a condition, one after the other by
 *   ascending `sequence`, then the components' contexts the sequence does not name (several at
 *   once; none for StartUp/ShutDown, which act on their targets only);
 * - every delayed action waits in a thread of its own, all started with the plan: `WaitTime` (ms)
 *   counts from the plan's start; `Preceding sendingTiming=SYNC` polls the preceding contexts
 *   (every 10 ms) until they are in the state the action leads to, its `timeout` (ms, 0 = no limit)
 *   also counted from the plan's start, and a timeout cancels the whole plan with a message naming
 *   the component and the preceding ones; other sendingTimings run once the preceding components'
 *   actions were sent.
 * Contexts already in the wanted state are skipped; failures of optional components are not
 * fatal, the first required failure or the caller's cancel ends every wait and the actions not yet
 * sent. Returns when all actions are done. Safe to call from a worker thread.
 */
DeployReport runSequence(const Profile::RtsProfile &profile, const RestorePlan &plan,
                         Profile::RtsSequenceKind kind, SequenceAction action,
                         const DeployControl &control = {});

/// rtstart: the StartUp sequence (when the file has one), then Activation.
DeployReport startSystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                         const DeployControl &control = {});
/// rtstop: Deactivation, then the ShutDown sequence (when the file has one).
DeployReport stopSystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                        const DeployControl &control = {});

} // namespace Deploy
