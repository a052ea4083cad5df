// SPDX-License-Identifier: MIT
#pragma once

#include "deployreport.h"

#include <QElapsedTimer>
#include <QMutex>

namespace Deploy {

/**
 * Records the steps of one operation into a DeployReport and tells the caller's progress callback
 * about each change. Safe to use from several threads (ConcurrentCalls' jobs finish their steps);
 * the callback is never called by two threads at once. Internal to the deployment library.
 */
class StepRecorder
{
public:
    explicit StepRecorder(DeployControl control);

    /// Adds a step in state Running and returns its index.
    int begin(const QString &action, const QString &subject, bool required = true);
    /// Adds a finished step (Skipped, Planned, ...) and returns its index.
    int add(const QString &action, const QString &subject, StepStatus status,
            const QString &message = QString(), bool required = true);
    void finish(int index, StepStatus status, const QString &message = QString());
    /// Marks the step failed; a required failure fails the operation (the first one is the error).
    void fail(int index, const QString &message);
    /// Marks the operation cancelled (and failed) once the caller asked for it.
    bool checkCancelled();

    DeployStep step(int index) const;
    bool ok() const;
    DeployReport report() const;
    const DeployControl &control() const { return m_control; }
    qint64 elapsed() const { return m_timer.elapsed(); }

private:
    void announce(int index);

    mutable QMutex m_mutex;
    DeployControl m_control;
    DeployReport m_report;
    QElapsedTimer m_timer;
};

} // namespace Deploy
