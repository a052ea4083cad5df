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
 * Runs `action` on every execution context of every mapped component, ordered by the message
 * sequence `kind` of `profile` (rtstart / rtstop): its targets first by `sequence`, each after its
 * `WaitTime` (ms) or, with `Preceding sendingTiming=SYNC`, once the preceding components have
 * reached the resulting state (`timeout` ms, 0 = no limit; a timeout cancels the rest of the
 * plan); ASYNC/NO_SYNC run right after the preceding action was sent. Then the components' other
 * contexts in file order. Contexts already in the wanted state are skipped; failures of optional
 * components are not fatal. Waits poll the cancel flag. Safe to call from a worker thread.
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
