// SPDX-License-Identifier: MIT
// Saving the live system shown on the online diagram (rtcryo plus the diagram's layout).
#include "onlinediagram.h"

#include "cryo.h"
#include "onlinesession.h"
#include "profileio.h"
#include "systemmodel.h"

#include <QFileInfo>
#include <QLabel>

namespace SystemEditor {

namespace {

struct LiveSnapshot
{
    Profile::RtsProfile profile;
    Deploy::DeployReport report;
};

} // namespace

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::LiveSnapshot)

namespace SystemEditor {

QHash<QString, QString> OnlineDiagram::livePaths() const
{
    QHash<QString, QString> paths;
    for (auto it = m_live.cbegin(); it != m_live.cend(); ++it)
        paths.insert(it.key(), it->path);
    return paths;
}

Profile::RtsProfile OnlineDiagram::withDiagramLayout(Profile::RtsProfile saved) const
{
    for (Profile::RtsComponent &component : saved.components) {
        if (const Profile::RtsComponent *drawn = m_model->component(component.instanceName))
            component.layout = drawn->layout;
    }
    return saved;
}

void OnlineDiagram::saveLiveSystem(const QString &path)
{
    Deploy::CryoOptions options;
    options.name = QFileInfo(path).completeBaseName();
    QStringList paths = livePaths().values();
    paths.sort();
    options.paths = paths;
    m_status->setText(tr("Reading the live system…"));
    m_session->submit(
        OnlineSession::deploymentHost(),
        [options] {
            LiveSnapshot snapshot;
            snapshot.profile = Deploy::cryoSystem(options, &snapshot.report);
            return QVariant::fromValue(snapshot);
        },
        this, [this, path](const OnlineResult &result) { writeLiveSystem(path, result); });
}

void OnlineDiagram::writeLiveSystem(const QString &path, const OnlineResult &result)
{
    QStringList warnings;
    if (!result.ok) {
        m_status->setText(result.error);
        emit liveSystemSaved(path, result.error, warnings);
        return;
    }
    const auto snapshot = result.value.value<LiveSnapshot>();
    for (const Deploy::DeployStep &step : snapshot.report.stepsWith(Deploy::StepStatus::Failed))
        warnings.append(step.toString());
    // Nothing answered: writing an empty system would only replace a good file with nothing.
    if (snapshot.profile.components.isEmpty() && !m_live.isEmpty()) {
        const QString error = tr("None of the components on the diagram answered.");
        m_status->setText(error);
        emit liveSystemSaved(path, error, warnings);
        return;
    }
    Profile::Diagnostics diagnostics;
    if (!Profile::saveRtsProfileFile(withDiagramLayout(snapshot.profile), path, &diagnostics)) {
        QStringList reasons;
        for (const Profile::Diagnostic &d : diagnostics)
            reasons.append(d.toString());
        const QString error = reasons.isEmpty() ? tr("%1 could not be written.").arg(path)
                                                : reasons.join(QLatin1Char('\n'));
        m_status->setText(error);
        emit liveSystemSaved(path, error, warnings);
        return;
    }
    m_status->setText(
        warnings.isEmpty()
            ? tr("Saved %1").arg(path)
            : tr("Saved %1 without: %2").arg(path, warnings.join(QStringLiteral("; "))));
    emit liveSystemSaved(path, QString(), warnings);
}

} // namespace SystemEditor
