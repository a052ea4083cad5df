// SPDX-License-Identifier: MIT
#pragma once

#include "nodefacts.h"
#include "plan.h"
#include "planrepository.h"

#include <QList>
#include <QWidget>

class QAction;
class QGraphicsView;
class QLabel;
class QListWidget;
class QProgressBar;
class QTabWidget;
class QThread;
class QUndoStack;

namespace SystemEditor {

class PlanScene;
class SystemModel;

/**
 * The Plan view of one system: where the planner puts each component, one lane per node.
 *
 * The nodes come from a facts file (openFactsFile(), as `rtctl plan --facts` reads it) or from
 * live managers (readFactsFromManagers(): a worker thread, every remote call under a timeout; the
 * GUI thread never calls a manager); a component repository (openRepository()) offers packages
 * to install. Re-plan runs the planner on a worker thread with a busy bar
 * and Cancel; lanes show the components placed on each node, what gets installed there, and in
 * red the requirements no node meets with the planner's explanation (also listed below the
 * lanes). Dragging a component to another lane pins it there: an undoable command on the
 * system's undo stack writing `deploy.pin` into the RTS profile. Dry Run lists what would be
 * installed and created where. Deploy emits deployRequested() for the deploy transaction; it
 * stays disabled until setDeployAvailable(true).
 */
class PlanView : public QWidget
{
    Q_OBJECT

public:
    PlanView(SystemModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);
    ~PlanView() override;

    /// Reads the nodes from a facts file; false (and the reason in the status) when it cannot.
    bool openFactsFile(const QString &path);
    /// Reads the nodes' facts from the managers at @p addresses, off the GUI thread.
    void readFactsFromManagers(const QStringList &addresses);
    /**
     * Plans with the component repository folder @p folder (read off the GUI thread): its packages
     * can be installed on the nodes, and their RTC profiles give their types' requirements.
     */
    void openRepository(const QString &folder);
    /// Re-plans the system on the current nodes, off the GUI thread.
    void replan();
    /// Stops waiting for the running planning or reading; its result is dropped.
    void cancel();
    /// Lists what deploying the plan would install and create, and where.
    void dryRun();
    /// Whether a deploy transaction listens to deployRequested().
    void setDeployAvailable(bool available);

    bool isBusy() const { return m_busy; }
    /// Worker threads not finished yet (a cancelled one runs on until its work ends).
    int runningWorkers() const { return int(m_threads.size()); }
    /// The plan shown (empty before the first planning).
    const Planner::Plan &plan() const { return m_plan; }
    const QList<Planner::NodeFacts> &facts() const { return m_facts; }
    /// The system changed since the plan was made.
    bool isOutOfDate() const { return m_outOfDate; }
    QString statusText() const;

    PlanScene *scene() const { return m_scene; }
    QGraphicsView *graphicsView() const { return m_view; }
    QListWidget *unmetList() const { return m_unmetList; }
    QListWidget *dryRunList() const { return m_dryRunList; }
    QAction *deployAction() const { return m_deploy; }
    /// The component repository planned with (empty when none was opened).
    QString repositoryFolder() const { return m_repositoryFolder; }

signals:
    /// The user asked to deploy @p plan (what the deploy transaction connects to).
    void deployRequested(const Planner::Plan &plan);
    void factsChanged();
    void planChanged();
    void busyChanged(bool busy);

private:
    void buildUi();
    QWidget *buildToolBar();
    QWidget *buildDetails();
    void askFactsFile();
    void askManagers();
    void askRepository();
    void setFacts(const QList<Planner::NodeFacts> &facts, const QStringList &errors);
    void setPlan(const Planner::Plan &plan);
    void systemChanged();
    void pin(const QString &instanceName, const QString &node);
    void refresh();
    void showUnmet();
    QString planSummary() const;
    void setBusy(bool busy, const QString &what);
    void updateActions();
    template<typename Result, typename Work, typename Done>
    void runInBackground(const QString &what, Work work, Done done);

    SystemModel *m_model;
    QUndoStack *m_undoStack;
    PlanScene *m_scene;
    QGraphicsView *m_view = nullptr;
    QLabel *m_status = nullptr;
    QProgressBar *m_progress = nullptr;
    QTabWidget *m_details = nullptr;
    QListWidget *m_unmetList = nullptr;
    QListWidget *m_dryRunList = nullptr;
    QAction *m_openFacts = nullptr;
    QAction *m_readManagers = nullptr;
    QAction *m_openRepository = nullptr;
    QAction *m_replan = nullptr;
    QAction *m_cancel = nullptr;
    QAction *m_dryRun = nullptr;
    QAction *m_deploy = nullptr;
    QList<Planner::NodeFacts> m_facts;
    QStringList m_factErrors; ///< managers that did not answer
    Deploy::PlanRepository m_repository;
    QString m_repositoryFolder;
    Planner::Plan m_plan;
    bool m_planned = false;
    bool m_outOfDate = false;
    bool m_busy = false;
    bool m_deployAvailable = false;
    QString m_message; ///< the last thing that went wrong or happened
    quint64 m_generation = 0; ///< a worker's result counts only while this is unchanged
    QList<QThread *> m_threads;
};

} // namespace SystemEditor
