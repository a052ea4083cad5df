// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QObject>

class QAction;
class QDockWidget;
class QMainWindow;
class QSettings;

namespace Profile {
struct RtsProfile;
}

namespace SystemEditor {
class ConfigurationView;
class ExecutionContextView;
class ManagerView;
class OnlineDiagram;
class RestoreDialog;
class NameServiceView;
class OnlineSession;
} // namespace SystemEditor

namespace Studio {

/**
 * The online views of the System Editor as docks of the main window: Name Service (left),
 * Configuration, Execution Contexts and Manager (bottom, tabbed). Choosing a component in the Name
 * Service tree shows it in the first two, choosing a manager in the Manager view; double-clicking
 * a component (or dragging it) puts it on the Online Diagram dock. One OnlineSession
 * runs the remote calls of all of them.
 */
class OnlineDocks : public QObject
{
    Q_OBJECT

public:
    /// Creates the docks in `window`, hidden; `settings` keeps the name-server list.
    OnlineDocks(QMainWindow *window, QSettings *settings);

    SystemEditor::OnlineSession *session() const { return m_session; }
    SystemEditor::NameServiceView *nameService() const { return m_nameService; }
    SystemEditor::ConfigurationView *configuration() const { return m_configuration; }
    SystemEditor::ExecutionContextView *executionContexts() const { return m_contexts; }
    SystemEditor::ManagerView *manager() const { return m_manager; }
    SystemEditor::OnlineDiagram *diagram() const { return m_diagram; }
    QList<QDockWidget *> docks() const { return m_docks; }
    /// The docks' show/hide actions, for the View menu.
    QList<QAction *> toggleActions() const;
    /**
     * Opens the Restore dialog for `profile` (non-modal, deleted on close), mapping it onto the
     * name servers of the Name Service view, and starts planning.
     */
    SystemEditor::RestoreDialog *openRestore(const Profile::RtsProfile &profile);
    /// Shows the docks with the System Editor perspective and hides them with the Builder.
    void setPerspectiveActive(bool systemEditor);

private:
    QDockWidget *addDock(QMainWindow *window, QWidget *view, const QString &title,
                         const QString &name, Qt::DockWidgetArea area);
    void showItem(const QModelIndex &index);
    void addToDiagram(const QModelIndex &index);

    SystemEditor::OnlineSession *m_session;
    SystemEditor::NameServiceView *m_nameService;
    SystemEditor::ConfigurationView *m_configuration;
    SystemEditor::ExecutionContextView *m_contexts;
    SystemEditor::ManagerView *m_manager;
    SystemEditor::OnlineDiagram *m_diagram;
    QList<QDockWidget *> m_docks;
    bool m_shownOnce = false;
};

} // namespace Studio
