// SPDX-License-Identifier: MIT
#pragma once

#include "componentmapper.h"
#include "deployer.h"
#include "deployreport.h"
#include "restoreplan.h"
#include "rtsprofile.h"

#include <QDialog>

#include <atomic>
#include <memory>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace SystemEditor {

class OnlineSession;

/**
 * The Restore dialog of the System Editor: plans the restore of a saved system with the
 * deployment engine (off the GUI thread), shows the mapping (per component: found / create /
 * missing, live path, target manager, restore, activate; per connector: connect) for the user
 * to adjust, shows the chosen plan as a dry run, then restores with a progress list and the
 * engine's final report. "Create missing components through a manager" plans the components
 * that are not running as created through the chosen manager (the engine's create path). A
 * failed restore is rolled back by the engine; the report says what failed and what was rolled
 * back. "Install missing component types from repository" (and a system whose components are pinned
 * to nodes, as the Plan view's Deploy gives it) plans it as a deploy: the component
 * types a creating manager cannot load are installed there from the repository first (the
 * Install column and the dry run say which package on which node), and a failure uninstalls them
 * again.
 */
class RestoreDialog : public QDialog
{
    Q_OBJECT

public:
    RestoreDialog(OnlineSession *session, Profile::RtsProfile profile,
                  Deploy::TargetOptions options, QWidget *parent = nullptr);
    ~RestoreDialog() override;

    /// The settings key of the component repository last installed from (Keep Running uses it too).
    static inline const QString RepositorySettingKey = QStringLiteral("deploy/repository");

    /// Columns of componentTable().
    enum ComponentColumn {
        NameColumn,
        TypeColumn,
        MappingColumn,
        PathColumn,
        ManagerColumn, ///< `manager_address` a created component is placed at (editable)
        RestoreColumn,
        ActivateColumn,
        InstallColumn ///< the package installed for it first, when installing from a repository
    };

    /// Maps the live system (asynchronously; planned() follows).
    void plan();
    /// Offers `managers` (rtshell paths or corbalocs) for creating missing components.
    void setManagers(const QStringList &managers);
    /// Plans missing components as created through `manager` (or not, with `create` false) and
    /// maps again.
    void setCreateMissing(bool create, const QString &manager);
    /// Installs what the creating managers cannot load from @p repository (a URL or folder; empty:
    /// installs nothing) and maps again.
    void setInstallFrom(const QString &repository);
    /// The installs of the current plan (empty unless installing from a repository).
    const Deploy::DeployPlan &currentDeployPlan() const { return m_deployPlan; }
    /// Lists what the restore would do with the choices made, without doing it.
    void dryRun();
    const Deploy::RestorePlan &currentPlan() const { return m_plan; }
    QTableWidget *componentTable() const { return m_components; }
    QTableWidget *connectorTable() const { return m_connectors; }
    QListWidget *progressList() const { return m_progress; }
    /// Restores with the choices made in the tables (asynchronously; restored() follows).
    void restore();
    /// Asks a running restore to stop (it then rolls back).
    void cancelRestore();
    const Deploy::DeployReport &report() const { return m_report; }

signals:
    void planned();
    void restored(bool ok);

private:
    void buildUi();
    void showPlan();
    Deploy::RestorePlan chosenPlan() const;
    void addProgress(const Deploy::DeployStep &step);
    void showReport();
    void createChanged();
    bool installing() const;
    /// The system pins components to nodes (deploy.pin): they are created there.
    bool hasPins() const;
    void takePlan(const QVariant &value);
    QString installFor(const Deploy::ComponentMapping &mapping) const;

    OnlineSession *m_session;
    Profile::RtsProfile m_profile;
    Deploy::TargetOptions m_options;
    Deploy::RestorePlan m_plan;
    Deploy::DeployPlan m_deployPlan;
    bool m_deploying = false; ///< planned as a deploy (installs or pins), restored as one
    Deploy::DeployReport m_report;
    std::shared_ptr<std::atomic_bool> m_cancel;
    QTableWidget *m_components = nullptr;
    QTableWidget *m_connectors = nullptr;
    QListWidget *m_progress = nullptr;
    QLabel *m_summary = nullptr;
    QPushButton *m_restore = nullptr;
    QPushButton *m_stop = nullptr;
    QProgressBar *m_busy = nullptr;
    QPushButton *m_dryRun = nullptr;
    QCheckBox *m_create = nullptr;
    QComboBox *m_manager = nullptr;
    QCheckBox *m_install = nullptr;
    QLineEdit *m_repository = nullptr;
};

} // namespace SystemEditor
