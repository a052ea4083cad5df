// SPDX-License-Identifier: MIT
#pragma once

#include "localruntime.h"

#include <QList>
#include <QObject>
#include <QPointF>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>

class QAction;
class QDockWidget;
class QLabel;
class QMainWindow;
class QMenu;
class QSettings;

namespace Profile {
struct RtsProfile;
}

namespace Deploy {
struct DeployReport;
struct TargetOptions;
}

namespace SystemEditor {
class ConfigurationView;
class DriftView;
class ExecutionContextView;
class ManagerView;
class PortMonitor;
class OnlineDiagram;
class RestoreDialog;
class NameServiceView;
class OnlineSession;
struct OnlineResult;
} // namespace SystemEditor

namespace Studio {

class Document;
class DocumentController;
class OnlineDocument;

/**
 * The online views of the System Editor: Name Service (left), Configuration, Execution Contexts
 * and Manager (bottom, tabbed) as docks of the main window, and online diagrams as System Editor
 * tabs (OnlineDocument). Choosing a component in the Name Service tree shows it in the first two,
 * choosing a manager in the Manager view; double-clicking a component (or dragging it onto a tab)
 * puts it on the current online diagram. One OnlineSession runs the remote calls of all of them.
 */
class OnlineDocks : public QObject
{
    Q_OBJECT

public:
    /// Creates the docks in `window`, hidden; `settings` keeps the name-server list.
    OnlineDocks(QMainWindow *window, QSettings *settings);

    /// Asks for a system file to compare with; an empty string means cancelled.
    using FileQuestion = std::function<QString()>;
    /**
     * Lets the online views open online diagram tabs through `documents` and find the document
     * of the current tab through `activeDocument`; `askFile` asks for Compare with File.
     */
    void attach(DocumentController *documents, const std::function<Document *()> &activeDocument,
                const FileQuestion &askFile);

    SystemEditor::OnlineSession *session() const { return m_session; }
    SystemEditor::NameServiceView *nameService() const { return m_nameService; }
    SystemEditor::ConfigurationView *configuration() const { return m_configuration; }
    SystemEditor::ExecutionContextView *executionContexts() const { return m_contexts; }
    SystemEditor::ManagerView *manager() const { return m_manager; }
    SystemEditor::PortMonitor *portMonitor() const { return m_portMonitor; }
    QList<QDockWidget *> docks() const { return m_docks; }
    /// The docks' show/hide actions, for the View menu.
    QList<QAction *> toggleActions() const;
    /// Adds New Online Diagram, Open System Online, Save Live System, Compare with File and the
    /// whole-diagram actions to the Online menu.
    void fillMenu(QMenu *menu);

    /// Opens a new, empty online diagram tab.
    OnlineDocument *newDiagram();
    /// The online diagram of the current tab, else the last one opened; null when there is none.
    OnlineDocument *currentDiagram() const;
    /**
     * Opens `profile` online: a new online diagram tab showing the live components the system's
     * components map onto, at their saved positions. Components not found are listed in the
     * diagram's status line. The tab's Start All and Stop All run the system's start / stop plan
     * (OnlineDiagram::setSystem()).
     */
    OnlineDocument *openOnline(const Profile::RtsProfile &profile);
    /**
     * Opens the Restore dialog for `profile` (non-modal, deleted on close), mapping it onto the
     * name servers of the Name Service view, and starts planning.
     */
    SystemEditor::RestoreDialog *openRestore(const Profile::RtsProfile &profile);
    /// Opens the drift of the system file `path` against the live system; null (and a message
    /// on the status line) when it cannot be read as a system.
    SystemEditor::DriftView *compareWithFile(const QString &path);
    /// Shows the docks with the System Editor perspective and hides them with the Builder.
    void setPerspectiveActive(bool systemEditor);

    /**
     * Starts the local runtime (a name server and an rtmanager master, Deploy::LocalRuntime) off
     * the GUI thread, or finds the one running, adds its name server to the Name Service view and
     * shows it in the status bar; then calls `then` (in this thread) when it runs, or `failed`
     * with the reason when it does not start.
     */
    void startLocalRuntime(const std::function<void(const Deploy::LocalRuntimeState &)> &then = {},
                           const std::function<void(const QString &)> &failed = {});
    /**
     * As startLocalRuntime(), over TLS only with the runtime's own certificates, which RT Studio then
     * presents; possible while RT Studio has not yet talked to any server in plain TCP.
     */
    void startLocalRuntimeWithTls();
    void stopLocalRuntime();
    /**
     * Runs `profile` on the local runtime as a newcomer wants it: starts the runtime, restores the
     * system there (creating its components through the local manager), starts it, opens it online
     * and watches the first data connector's OutPort in the Port Monitor. `done` gets the error
     * (empty when it all worked).
     */
    void runLocally(const Profile::RtsProfile &profile,
                    const std::function<void(const QString &error)> &done = {});
    /**
     * The reverse of a deploy (as `rtctl undeploy`): stops the system, disconnects its connectors,
     * makes its components exit and, with @p uninstall, removes the packages of its component types
     * from the nodes that ran them; off the GUI thread, the outcome in the status bar and in `done`.
     */
    void undeploy(const Profile::RtsProfile &profile, bool uninstall,
                  const std::function<void(const Deploy::DeployReport &)> &done = {});
    /**
     * Writes (or with @p start false removes) the systemd user unit that starts an rtmanager with
     * @p configFile (none: rtc.conf's defaults) when the user's session starts, as `rtctl node
     * enable|disable` do, and enables it with systemctl; the unit folder of the setting
     * `node/unitDirectory` instead, when set, without systemctl. Runs off the GUI thread; @p done
     * gets the unit's path as value, or the reason.
     */
    void setManagerAtBoot(bool start, const QString &configFile,
                          const std::function<void(const SystemEditor::OnlineResult &)> &done);
    /// Called when the application quits: stops the local runtime this window started, unless
    /// the user asked to keep it running.
    void quitting();
    /// The local runtime as last seen.
    const Deploy::LocalRuntimeState &localRuntime() const { return m_localRuntime; }

signals:
    /// A one-line message for the status bar.
    void statusMessage(const QString &message);

private:
    QDockWidget *addDock(QMainWindow *window, QWidget *view, const QString &title,
                         const QString &name, Qt::DockWidgetArea area);
    void showItem(const QModelIndex &index);
    void addToDiagram(const QModelIndex &index);
    Deploy::TargetOptions targetOptions() const;
    QStringList knownManagers() const;
    void showLocalRuntime(const QString &failure = QString());
    void startLocalRuntime(const std::function<void(const Deploy::LocalRuntimeState &)> &then,
                           const std::function<void(const QString &)> &failed, bool tls);
    void watchFirstConnection(OnlineDocument *online, const Profile::RtsProfile &profile);
    void placeMapped(SystemEditor::OnlineDiagram *diagram, const Profile::RtsProfile &profile,
                     const QVariant &plan);
    static QPointF nextPosition(int count);

    SystemEditor::OnlineSession *m_session;
    SystemEditor::NameServiceView *m_nameService;
    SystemEditor::ConfigurationView *m_configuration;
    SystemEditor::ExecutionContextView *m_contexts;
    SystemEditor::ManagerView *m_manager;
    SystemEditor::PortMonitor *m_portMonitor;
    /// Whether this window started the running local runtime, shared with the worker that starts
    /// it: a quit while a start is under way still stops what that start brings up.
    struct LocalRuntimeOwnership
    {
        std::mutex mutex;
        bool started = false;
        bool quitting = false; ///< quitting() ran (and the runtime is not to be kept)
    };

    Deploy::LocalRuntimeState m_localRuntime;
    std::shared_ptr<LocalRuntimeOwnership> m_ownership = std::make_shared<LocalRuntimeOwnership>();
    QLabel *m_localRuntimeLabel = nullptr;
    QAction *m_keepLocalRuntime = nullptr;
    QList<QDockWidget *> m_docks;
    DocumentController *m_documents = nullptr;
    std::function<Document *()> m_activeDocument;
    FileQuestion m_askFile;
    bool m_shownOnce = false;
};

} // namespace Studio
