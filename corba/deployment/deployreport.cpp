// SPDX-License-Identifier: MIT
#include "deployreport.h"

namespace Deploy {

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

QString DeployStep::toString() const
{
    QString line = QStringLiteral("%1 %2 %3").arg(stepStatusName(status), action, subject);
    if (!message.isEmpty())
        line += QStringLiteral(": ") + message;
    return line;
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
        text += QStringLiteral("cancelled\n");
    else if (!ok)
        text += QStringLiteral("failed: %1\n").arg(error);
    return text;
}

} // namespace Deploy
