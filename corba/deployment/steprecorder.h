// SPDX-License-Identifier: MIT
#pragma once

#include "deployreport.h"

#include <QElapsedTimer>

namespace Deploy {

/**
 * Records the steps of one operation into a DeployReport and tells the caller's progress callback
 * about each change. Internal to the deployment library.
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

    const DeployStep &step(int index) const { return m_report.steps.at(index); }
    bool ok() const { return m_report.ok; }
    DeployReport report() const { return m_report; }
    const DeployControl &control() const { return m_control; }
    qint64 elapsed() const { return m_timer.elapsed(); }

private:
    void announce(int index);

    DeployControl m_control;
    DeployReport m_report;
    QElapsedTimer m_timer;
};

} // namespace Deploy
