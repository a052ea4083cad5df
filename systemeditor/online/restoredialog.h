// SPDX-License-Identifier: MIT
#pragma once

#include "componentmapper.h"
#include "deployreport.h"
#include "restoreplan.h"
#include "rtsprofile.h"

#include <QDialog>

#include <atomic>
#include <memory>

class QCheckBox;
class QComboBox;
class QLabel;
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
 * back.
 */
class RestoreDialog : public QDialog
{
    Q_OBJECT

public:
    RestoreDialog(OnlineSession *session, Profile::RtsProfile profile,
                  Deploy::TargetOptions options, QWidget *parent = nullptr);
    ~RestoreDialog() override;

    /// Columns of componentTable().
    enum ComponentColumn {
        NameColumn,
        TypeColumn,
        MappingColumn,
        PathColumn,
        ManagerColumn, ///< `manager_address` a created component is placed at (editable)
        RestoreColumn,
        ActivateColumn
    };

    /// Maps the live system (asynchronously; planned() follows).
    void plan();
    /// Offers `managers` (rtshell paths or corbalocs) for creating missing components.
    void setManagers(const QStringList &managers);
    /// Plans missing components as created through `manager` (or not, with `create` false) and
    /// maps again.
    void setCreateMissing(bool create, const QString &manager);
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

    OnlineSession *m_session;
    Profile::RtsProfile m_profile;
    Deploy::TargetOptions m_options;
    Deploy::RestorePlan m_plan;
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
};

} // namespace SystemEditor
