// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <atomic>
#include <functional>

namespace Deploy {

/// What became of one step of a deployment operation.
enum class StepStatus {
    Planned, ///< dry run: would be done
    Running, ///< about to be sent (reported before the remote call)
    Done, ///< succeeded
    Skipped, ///< nothing to do (already there) or not required
    Failed, ///< failed; `message` says why
    RolledBack ///< was done, then undone because a later required step failed
};

/// "planned", "running", "done", "skipped", "failed", "rolled back": the names rtctl's JSON and
/// scripts read, never translated.
QString stepStatusName(StepStatus status);

/// One step: an action on one subject (a component instance, a connector id, a set).
struct DeployStep
{
    QString action; ///< e.g. "create", "connect", "activate", "wait"
    QString subject; ///< instance name, connector id, `Instance.set`
    StepStatus status = StepStatus::Planned;
    QString message; ///< reason of a failure, or a detail of what was done
    bool required = true; ///< a failure of a required step fails the operation
    qint64 elapsedMs = 0; ///< since the operation began, when the status was set

    /// `action subject`: what the step does, in the UI's language (English in rtctl).
    QString heading() const;
    /// `action subject: message`, in the UI's language; a failed required step's is the report's
    /// error.
    QString summary() const;
    /// `STATUS action subject: message`, one line as rtctl prints it (translated in the GUI).
    QString toString() const;

    Q_DECLARE_TR_FUNCTIONS(Deploy::DeployStep)
};

/**
 * The result of a deployment operation: every step in the order it happened, and whether the
 * operation as a whole succeeded. A plain value, safe to hand from a worker thread to the GUI.
 */
struct DeployReport
{
    QList<DeployStep> steps;
    bool ok = true;
    bool cancelled = false;
    QString error; ///< the first required failure (empty when ok)

    /// The steps with `status`.
    QList<DeployStep> stepsWith(StepStatus status) const;
    /// One line per step, then a summary line.
    QString toText() const;
    /// The error of an operation the caller cancelled.
    static QString cancelledError();

    Q_DECLARE_TR_FUNCTIONS(Deploy::DeployReport)
};

/**
 * How a caller follows and steers an operation that may run in a worker thread: `progress` is
 * called (in the worker thread) for every step as its status changes; `cancel` is polled between
 * remote calls and during waits, and makes the operation stop (a restore then rolls back).
 */
struct DeployControl
{
    std::function<void(const DeployStep &)> progress;
    const std::atomic_bool *cancel = nullptr;

    bool cancelled() const { return cancel && cancel->load(); }
};

} // namespace Deploy
