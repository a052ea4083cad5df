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
    m_report.steps.append(step);
    const int index = int(m_report.steps.size()) - 1;
    announce(index);
    return index;
}

void StepRecorder::finish(int index, StepStatus status, const QString &message)
{
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
    const DeployStep &step = m_report.steps.at(index);
    if (step.required && m_report.ok) {
        m_report.ok = false;
        m_report.error = QStringLiteral("%1 %2: %3").arg(step.action, step.subject, message);
    }
}

bool StepRecorder::checkCancelled()
{
    if (!m_control.cancelled())
        return false;
    if (!m_report.cancelled) {
        m_report.cancelled = true;
        if (m_report.ok) {
            m_report.ok = false;
            m_report.error = QStringLiteral("cancelled");
        }
    }
    return true;
}

void StepRecorder::announce(int index)
{
    if (m_control.progress)
        m_control.progress(m_report.steps.at(index));
}

} // namespace Deploy
