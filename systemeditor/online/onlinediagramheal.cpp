// SPDX-License-Identifier: MIT
// Keep Running on a diagram that shows a saved system: the deployment engine's healer, one round
// at a time off the GUI thread, and the diagram pointed at where moved components run now.
#include "onlinediagram.h"

#include "healer.h"
#include "onlinesession.h"

#include <QAction>
#include <QCoreApplication>
#include <QLabel>
#include <QPointer>
#include <QTimer>

namespace SystemEditor {

namespace {

/// What one round of the healer did, and where the components it moved are now.
struct HealRound
{
    Deploy::DeployReport report;
    QHash<QString, QString> moved; ///< instance → node
    QHash<QString, std::pair<QString, QString>> found; ///< instance → (path, IOR) now
};

} // namespace

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::HealRound)

namespace SystemEditor {

bool OnlineDiagram::isHealing() const
{
    return m_healTimer && m_healTimer->isActive();
}

void OnlineDiagram::setHealing(bool on, int intervalMs)
{
    if (!m_system)
        return;
    {
        const QSignalBlocker blocker(m_healAction);
        m_healAction->setChecked(on);
    }
    if (!on) {
        if (m_healTimer)
            m_healTimer->stop();
        m_status->setText(tr("Keep Running is off."));
        return;
    }
    Deploy::WatchOptions options;
    options.deploy.target = m_system->options;
    options.deploy.repository = m_healRepository;
    m_healer = std::make_shared<Deploy::SystemHealer>(m_system->profile, options);
    m_healStarted = false;
    if (!m_healTimer) {
        m_healTimer = new QTimer(this);
        connect(m_healTimer, &QTimer::timeout, this, &OnlineDiagram::healRound);
    }
    m_healTimer->start(intervalMs);
    m_status->setText(tr("Keep Running: watching the system's nodes."));
    healRound();
}

void OnlineDiagram::healRound()
{
    // One round at a time: a heal that installs may take longer than the interval.
    if (m_healBusy || !m_healer)
        return;
    m_healBusy = true;
    const std::shared_ptr<Deploy::SystemHealer> healer = m_healer;
    const Deploy::TargetOptions target = m_system->options;
    const bool first = !m_healStarted;
    m_healStarted = true;
    const QPointer<OnlineDiagram> self(this);
    Deploy::DeployControl control;
    control.progress = [self](const Deploy::DeployStep &step) {
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [self, step] {
                if (self && step.status != Deploy::StepStatus::Running)
                    emit self->healStep(step);
            },
            Qt::QueuedConnection);
    };
    m_session->submit(
        OnlineSession::deploymentHost(),
        [healer, target, first, control] {
            if (first)
                healer->start();
            const QHash<QString, QString> before = healer->placement();
            HealRound round;
            round.report = healer->check(control);
            for (auto it = healer->placement().cbegin(); it != healer->placement().cend(); ++it) {
                if (before.value(it.key()) != it.value())
                    round.moved.insert(it.key(), it.value());
            }
            if (!round.moved.isEmpty()) {
                // Where the moved components are now, as the diagram names them.
                const Deploy::RestorePlan plan = Deploy::planRestore(healer->system(), target);
                for (const Deploy::ComponentMapping &c : plan.components) {
                    if (round.moved.contains(c.instanceName) && c.kind == Deploy::MappingKind::Existing)
                        round.found.insert(c.instanceName, {c.path, c.ior});
                }
            }
            return QVariant::fromValue(round);
        },
        this, [this](const OnlineResult &result) { finishHealRound(result); });
}

void OnlineDiagram::finishHealRound(const OnlineResult &result)
{
    m_healBusy = false;
    if (!result.ok) {
        m_status->setText(tr("Keep Running: %1").arg(result.error));
        return;
    }
    const HealRound round = result.value.value<HealRound>();
    if (!round.report.ok)
        m_status->setText(tr("Keep Running could not heal the system: %1").arg(round.report.error));
    if (round.moved.isEmpty())
        return;
    QStringList moves;
    for (auto it = round.moved.cbegin(); it != round.moved.cend(); ++it) {
        moves << tr("%1 to %2").arg(it.key(), it.value());
        const auto found = round.found.constFind(it.key());
        auto live = m_live.find(it.key());
        if (found == round.found.constEnd() || live == m_live.end())
            continue;
        live->path = found->first;
        live->ior = found->second;
        live->reachable = true;
        live->portsStale = true;
    }
    moves.sort();
    m_status->setText(tr("Keep Running moved %1.").arg(moves.join(QStringLiteral(", "))));
    emit healed(round.moved);
    poll();
}

} // namespace SystemEditor
