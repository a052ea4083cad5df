// SPDX-License-Identifier: MIT
// Start All / Stop All on a diagram that shows a saved system: the system's start / stop plan,
// run by the deployment engine as rtctl start / stop run it.
#include "onlinediagram.h"

#include "onlinesession.h"
#include "restoreplan.h"
#include "sequencerunner.h"

#include <QAction>
#include <QCoreApplication>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>

Q_DECLARE_METATYPE(Deploy::DeployReport)

namespace SystemEditor {

namespace {

bool isPlanAction(const Deploy::DeployStep &step)
{
    return step.action != QLatin1String("wait") && step.action != QLatin1String("cancel");
}

} // namespace

void OnlineDiagram::setSystem(const Profile::RtsProfile &profile,
                              const Deploy::TargetOptions &options)
{
    qRegisterMetaType<Deploy::DeployStep>();
    qRegisterMetaType<Deploy::DeployReport>();
    m_system = SystemPlan {profile, options};
    const std::pair<const char *, QString> tips[]
        = {{"actionStartAll", tr("Runs the system's StartUp and Activation plan (as rtctl start)")},
           {"actionStopAll", tr("Runs the system's Deactivation and ShutDown plan (as rtctl stop)")}};
    for (const auto &[name, tip] : tips) {
        if (auto *action = findChild<QAction *>(QLatin1String(name)))
            action->setToolTip(tip);
    }
    m_healAction->setEnabled(true);
    m_healAction->setToolTip(tr("When a node of the system stops answering, move its components to the "
                                "others and start them there (as rtctl deploy --watch)"));
}

void OnlineDiagram::runSystemPlan(Action action)
{
    const bool start = action == Action::Start;
    startBatch(1, start ? tr("Starting the system") : tr("Stopping the system"));
    m_batch.plan = true;
    // The plan waits for time and for other components as much as it calls them: no count of
    // components to show, only that it runs and what it does (showPlanStep()).
    m_batchBar->setRange(0, 0);
    m_status->setText(tr("%1: finding its components…").arg(m_batch.doing));
    const Profile::RtsProfile profile = m_system->profile;
    const Deploy::TargetOptions options = m_system->options;
    const std::shared_ptr<std::atomic_bool> cancelled = m_batch.cancelled;
    const QPointer<OnlineDiagram> self(this);
    Deploy::DeployControl control;
    control.cancel = cancelled.get();
    // Reported in the engine's threads; shown in the GUI thread, in the order they happened.
    control.progress = [self](const Deploy::DeployStep &step) {
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [self, step] {
                if (self)
                    self->showPlanStep(step);
            },
            Qt::QueuedConnection);
    };
    m_session->submit(
        OnlineSession::deploymentHost(),
        [profile, options, control, cancelled, start] {
            // Mapped when the plan runs, as rtctl does: a component restarted since the tab
            // opened is found under its new reference.
            const Deploy::RestorePlan plan = Deploy::planRestore(profile, options);
            const Deploy::DeployReport report = start
                ? Deploy::startSystem(profile, plan, control)
                : Deploy::stopSystem(profile, plan, control);
            return QVariant::fromValue(report);
        },
        this, [this](const OnlineResult &result) { finishSystemPlan(result); });
}

void OnlineDiagram::showPlanStep(const Deploy::DeployStep &step)
{
    if (!m_batch.plan)
        return;
    emit planStep(step);
    if (step.action == QLatin1String("wait")) {
        m_batch.waiting.removeAll(step.subject);
        if (step.status == Deploy::StepStatus::Running)
            m_batch.waiting.append(step.subject);
    } else if (isPlanAction(step) && step.status != Deploy::StepStatus::Running) {
        ++m_batch.done;
        m_batch.failed += step.status == Deploy::StepStatus::Failed ? 1 : 0;
    }
    if (m_batch.cancelled && *m_batch.cancelled)
        return; // the label says that it is being cancelled
    QString text = tr("%1: %n action(s) done", nullptr, m_batch.done).arg(m_batch.doing);
    if (!m_batch.waiting.isEmpty())
        text += tr(", waiting: %1").arg(m_batch.waiting.join(QStringLiteral(", ")));
    m_status->setText(text + QStringLiteral("…"));
}

void OnlineDiagram::finishSystemPlan(const OnlineResult &result)
{
    Deploy::DeployReport report;
    if (result.ok) {
        report = result.value.value<Deploy::DeployReport>();
    } else {
        report.ok = false;
        report.error = result.error;
    }
    int done = 0;
    QStringList failures;
    for (const Deploy::DeployStep &step : std::as_const(report.steps)) {
        done += isPlanAction(step) && step.status == Deploy::StepStatus::Done ? 1 : 0;
        // A wait ended by the failure or by Cancel is not a failure of its own.
        // The first required failure is the summary's error already.
        if (step.status == Deploy::StepStatus::Failed
            && step.message != Deploy::DeployReport::cancelledError()
            && step.summary() != report.error)
            failures.append(step.toString());
    }
    QString summary;
    if (report.cancelled)
        summary = tr("%1: cancelled after %n action(s)", nullptr, done).arg(m_batch.doing);
    else if (!report.ok)
        summary = tr("%1 failed: %2").arg(m_batch.doing, report.error);
    else
        summary = tr("%1: %n action(s) done", nullptr, done).arg(m_batch.doing);
    if (report.ok && !failures.isEmpty())
        summary += tr(", %n optional failed", nullptr, int(failures.size()));
    //: The finished status line as a sentence (its full stop).
    m_status->setText(failures.isEmpty() ? tr("%1.").arg(summary)
                                         : summary + QLatin1Char('\n') + failures.join(QLatin1Char('\n')));
    endBatch(summary);
    poll();
}

} // namespace SystemEditor
