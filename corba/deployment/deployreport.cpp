// SPDX-License-Identifier: MIT
#include "deployreport.h"

namespace Deploy {

namespace {

// The actions of the engine's steps; they stay English in DeployStep::action, which callers
// compare, and are translated only where a step is shown.
struct ActionName
{
    const char *source;
    const char *comment;
};
const ActionName actionNames[] = {
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "find", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "create", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "connect", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "disconnect", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "configure", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "rate", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "install", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "uninstall", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "exit", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "plan", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "activate", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "deactivate", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "start", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "stop", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "wait", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "cancel", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "node back", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "node lost", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "replan", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "list", "step action"),
    QT_TRANSLATE_NOOP3("Deploy::DeployStep", "save", "step action"),
};

QString actionText(const QString &action)
{
    for (const ActionName &name : actionNames) {
        if (action == QLatin1String(name.source))
            return DeployStep::tr(name.source, name.comment);
    }
    return action;
}

QString statusText(StepStatus status)
{
    switch (status) {
    case StepStatus::Planned:
        return DeployStep::tr("planned", "step status");
    case StepStatus::Running:
        return DeployStep::tr("running", "step status");
    case StepStatus::Done:
        return DeployStep::tr("done", "step status");
    case StepStatus::Skipped:
        return DeployStep::tr("skipped", "step status");
    case StepStatus::Failed:
        return DeployStep::tr("failed", "step status");
    case StepStatus::RolledBack:
        break;
    }
    return DeployStep::tr("rolled back", "step status");
}

} // namespace

QString stepStatusName(StepStatus status)
{
    switch (status) {
    case StepStatus::Planned:
        return QStringLiteral("planned");
    case StepStatus::Running:
        return QStringLiteral("running");
    case StepStatus::Done:
        return QStringLiteral("done");
    case StepStatus::Skipped:
        return QStringLiteral("skipped");
    case StepStatus::Failed:
        return QStringLiteral("failed");
    case StepStatus::RolledBack:
        break;
    }
    return QStringLiteral("rolled back");
}

QString DeployStep::heading() const
{
    return tr("%1 %2", "step: action, subject").arg(actionText(action), subject);
}

QString DeployStep::summary() const
{
    if (message.isEmpty())
        return heading();
    return tr("%1 %2: %3", "step: action, subject, message")
        .arg(actionText(action), subject, message);
}

QString DeployStep::toString() const
{
    return tr("%1 %2", "step line: status, then the step's summary")
        .arg(statusText(status), summary());
}

QList<DeployStep> DeployReport::stepsWith(StepStatus status) const
{
    QList<DeployStep> result;
    for (const DeployStep &step : steps) {
        if (step.status == status)
            result.append(step);
    }
    return result;
}

QString DeployReport::toText() const
{
    QString text;
    for (const DeployStep &step : steps)
        text += step.toString() + QLatin1Char('\n');
    if (cancelled)
        text += cancelledError() + QLatin1Char('\n');
    else if (!ok)
        text += tr("failed: %1").arg(error) + QLatin1Char('\n');
    return text;
}

QString DeployReport::cancelledError()
{
    return tr("cancelled");
}

} // namespace Deploy
