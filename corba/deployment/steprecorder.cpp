// SPDX-License-Identifier: MIT
#include "steprecorder.h"

namespace Deploy {

StepRecorder::StepRecorder(DeployControl control)
    : m_control(std::move(control))
{
    m_timer.start();
}

int StepRecorder::begin(const QString &action, const QString &subject, bool required)
{
    return add(action, subject, StepStatus::Running, QString(), required);
}

int StepRecorder::add(const QString &action, const QString &subject, StepStatus status,
                      const QString &message, bool required)
{
    DeployStep step;
    step.action = action;
    step.subject = subject;
    step.status = status;
    step.message = message;
    step.required = required;
    step.elapsedMs = m_timer.elapsed();
    QMutexLocker lock(&m_mutex);
    m_report.steps.append(step);
    const int index = int(m_report.steps.size()) - 1;
    announce(index);
    return index;
}

void StepRecorder::finish(int index, StepStatus status, const QString &message)
{
    QMutexLocker lock(&m_mutex);
    DeployStep &step = m_report.steps[index];
    step.status = status;
    if (!message.isEmpty())
        step.message = message;
    step.elapsedMs = m_timer.elapsed();
    announce(index);
}

void StepRecorder::fail(int index, const QString &message)
{
    finish(index, StepStatus::Failed, message);
    QMutexLocker lock(&m_mutex);
    const DeployStep &step = m_report.steps.at(index);
    if (step.required && m_report.ok) {
        m_report.ok = false;
        m_report.error = step.summary();
    }
}

bool StepRecorder::checkCancelled()
{
    if (!m_control.cancelled())
        return false;
    QMutexLocker lock(&m_mutex);
    if (!m_report.cancelled) {
        m_report.cancelled = true;
        if (m_report.ok) {
            m_report.ok = false;
            m_report.error = DeployReport::cancelledError();
        }
    }
    return true;
}

DeployStep StepRecorder::step(int index) const
{
    QMutexLocker lock(&m_mutex);
    return m_report.steps.at(index);
}

bool StepRecorder::ok() const
{
    QMutexLocker lock(&m_mutex);
    return m_report.ok;
}

DeployReport StepRecorder::report() const
{
    QMutexLocker lock(&m_mutex);
    return m_report;
}

// Called with m_mutex held: callbacks come one at a time, in the order of the changes.
void StepRecorder::announce(int index)
{
    if (m_control.progress)
        m_control.progress(m_report.steps.at(index));
}

} // namespace Deploy
