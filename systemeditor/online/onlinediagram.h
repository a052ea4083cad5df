// SPDX-License-Identifier: MIT
#pragma once

#include "componentmapper.h"
#include "componentproxy.h"
#include "connectordialog.h"
#include "connectorsettings.h"
#include "corbatypes.h"
#include "deployreport.h"
#include "rtsprofile.h"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

#include <QHash>
#include <QMetaType>
#include <QPointF>
#include <QWidget>

namespace Deploy {
class SystemHealer;
}

class QAction;
class QGraphicsView;
class QLabel;
class QProgressBar;
class QPushButton;
class QTimer;
class QUndoStack;

namespace SystemEditor {

class OnlineSession;
struct OnlineResult;
class SystemModel;
class SystemScene;
struct ConnectionCheck;

/// What one poll of a live component returned.
struct LiveComponentPoll
{
    Corba::LifeCycleState state = Corba::LifeCycleState::Unknown;
    bool answered = false; ///< the component answered; state and ports are valid only then
    bool portsRead = false; ///< this poll also read the port profiles (with their connectors)
    std::vector<Corba::PortInfo> ports;
    /// Set when the component answered only under the reference its name now resolves to (its
    /// process was restarted); the diagram uses it from then on.
    QString newIor;
};

/**
 * The online diagram: live components dropped from the Name Service view, drawn by the offline
 * canvas over a System Editor model built from their profiles, filled with their state colour
 * (Created white, Inactive blue, Active green, Error red, Unknown/unreachable black) and joined
 * by the connectors their ports report. A background poller (interval in QSettings
 * `online/pollInterval`, default 1000 ms) refreshes states through the worker layer every round
 * and each component's ports and connectors every portRefreshRounds() rounds (staggered, and at
 * once after this diagram connects or disconnects or the component answers again); components
 * that stop answering turn black instead of raising errors.
 *
 * Like the offline canvas, the view keeps the whole diagram fitted (centred, never above 100 %)
 * as components and connectors arrive and the tab settles, until the user zooms, scrolls or
 * clicks; after that a newly added component is scrolled into view instead.
 */
class OnlineDiagram : public QWidget
{
    Q_OBJECT

public:
    enum class Action { Activate, Deactivate, Reset, Exit, Start, Stop };

    explicit OnlineDiagram(OnlineSession *session, QWidget *parent = nullptr);
    ~OnlineDiagram() override;

    SystemModel *model() const { return m_model; }
    SystemScene *scene() const { return m_scene; }
    QGraphicsView *view() const { return m_view; }

    /// Reads the component's profile and adds it at `position` (scene coordinates).
    void addComponent(const QString &path, const QString &ior, const QPointF &position);
    Corba::LifeCycleState state(const QString &instanceName) const;
    /// The body colour the canvas currently draws for the component.
    QColor bodyColor(const QString &instanceName) const;

    /// The components whose last poll went unanswered (drawn black), sorted.
    QStringList unreachableComponents() const;

    void setPollInterval(int milliseconds);
    int pollInterval() const;
    /// Starts one poll round now (skipped while the previous one is still running).
    void poll();
    /// A component's ports and connectors are read in one of this many poll rounds, so a
    /// connector made elsewhere appears within this many rounds: 3, or more on a diagram of more
    /// than 300 components, so that a round reads the ports of about 100 at most.
    int portRefreshRounds() const { return portRefreshRounds(int(m_live.size())); }
    static constexpr int portRefreshRounds(int components)
    {
        return components > 300 ? (components + 99) / 100 : 3;
    }
    /// Remote reads of port profiles since the diagram was made (one per component and refresh).
    int portReads() const { return m_portReads; }

    void perform(Action action, const QString &instanceName);
    /**
     * `action` on every component of the diagram, with a progress bar and Cancel (the calls not
     * yet made are skipped); allFinished() says how it went. On a diagram that shows a saved
     * system (setSystem()), Start and Stop run that system's plan instead (see setSystem()).
     */
    void performAll(Action action);
    void cancelAll();

    /**
     * The saved system this diagram shows (Online → Open System Online). From then on Start All
     * and Stop All run its plan with the deployment engine, as `rtctl start` / `rtctl stop` do:
     * the StartUp and Activation (Deactivation and ShutDown) blocks in their order, with their
     * WaitTime and Preceding conditions, the profile's components mapped onto the live system
     * under `options` when the plan starts. The plan runs off the GUI thread; planStep() reports
     * its steps, Cancel ends its waits and the actions not yet sent, and allFinished() carries
     * the engine's message when it failed. Without a system, Start and Stop All start and stop
     * every component's contexts one by one.
     */
    void setSystem(const Profile::RtsProfile &profile, const Deploy::TargetOptions &options);
    /// True when Start All and Stop All run a saved system's plan.
    bool hasSystemPlan() const { return m_system.has_value(); }

    /**
     * Keep Running (a diagram with a saved system only): while on, the nodes the system runs on
     * are checked every @p intervalMs off the GUI thread, and when one stops answering its
     * components are planned anew on the others, installed from the heal repository where
     * needed, created, connected and started (Deploy::SystemHealer, as `rtctl deploy --watch`).
     * The diagram then shows them where they run now; healStep() reports every step and
     * healed() what moved where.
     */
    void setHealing(bool on, int intervalMs = 500);
    bool isHealing() const;
    /// The component repository a heal installs from (empty: moved types must be loadable).
    void setHealRepository(const QString &repository) { m_healRepository = repository; }

    /// Asks for the settings of a new data connector (default: the ConnectorDialog, modal).
    using ConnectorEditor = std::function<std::optional<ConnectorSettings>(
        const ConnectorSettings &proposed, const ConnectorDialog::Choices &choices)>;
    void setConnectorEditor(const ConnectorEditor &editor) { m_connectorEditor = editor; }
    /// What both live ports allow (interface, dataflow and subscription types), for the dialog.
    ConnectorDialog::Choices choicesFor(const QString &outPort, const QString &inPort) const;
    /// Connects two live ports (full names `Instance.port`, output first for data ports) with
    /// `settings` (data) or the name in `settings` (service).
    void connectLive(const QString &sourcePort, const QString &targetPort,
                     const ConnectorSettings &settings);
    /// Disconnects the live connector `connectorId`.
    void disconnectLive(const QString &connectorId);
    /// Asks the Port Monitor (through the session) to watch a port of a component on the diagram.
    void monitorPort(const QString &instanceName, const QString &portName);

    /// The rtshell paths of the live components on the diagram, by instance name.
    QHash<QString, QString> livePaths() const;
    /**
     * Saves the live components on the diagram as an RTS profile at `path` (format by extension):
     * rtcryo reads them off the GUI thread (ids, paths, every configuration set, active set,
     * owned contexts, ports, connectors minus IOR keys), then the diagram adds where it draws
     * them (`rtsExt:Location`). liveSystemSaved() follows.
     */
    void saveLiveSystem(const QString &path);
    /// `saved` with the location the diagram draws each of its components at.
    Profile::RtsProfile withDiagramLayout(Profile::RtsProfile saved) const;

signals:
    void componentAdded(const QString &instanceName);
    /// A poll round finished and states and connectors are up to date.
    void polled();
    void actionFinished(const QString &instanceName, const QString &error);
    /// A performAll() ended: how many components were done, failed or skipped by Cancel.
    void allFinished(const QString &summary);
    /// A step of a running start / stop plan changed (delivered in the GUI thread, in order).
    void planStep(const Deploy::DeployStep &step);
    /// A step of Keep Running changed (delivered in the GUI thread, in order).
    void healStep(const Deploy::DeployStep &step);
    /// Keep Running moved components: instance name → the node it runs on now.
    void healed(const QHash<QString, QString> &moved);
    /// A live connect or disconnect finished; `error` is empty on success.
    void connectionFinished(const QString &error);
    /// saveLiveSystem() finished: `error` is empty when the file was written; `warnings` name
    /// components that could not be read and were left out.
    void liveSystemSaved(const QString &path, const QString &error, const QStringList &warnings);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Live
    {
        QString path;
        QString ior;
        Corba::LifeCycleState state = Corba::LifeCycleState::Unknown;
        std::vector<Corba::PortInfo> ports;
        bool reachable = true; ///< the last poll was answered
        int stagger = 0; ///< spreads the port reads of the components over the rounds
        bool portsStale = false; ///< read the ports in the next round, whatever its number
    };

    /// One performAll(): the components done so far, and its cancel flag for the queued calls.
    struct Batch
    {
        int total = 0;
        int done = 0;
        int failed = 0;
        int skipped = 0;
        QString doing;
        std::shared_ptr<std::atomic_bool> cancelled;
        bool plan = false; ///< a saved system's start / stop plan, not one call per component
        QStringList waiting; ///< the plan's components waiting for time or for others
        bool running() const { return total > 0; }
    };

    /// What setSystem() gave: the saved system and where its components are looked up.
    struct SystemPlan
    {
        Profile::RtsProfile profile;
        Deploy::TargetOptions options;
    };

    void buildUi();
    void submitAction(Action action, const QString &instanceName,
                      const std::shared_ptr<std::atomic_bool> &cancelled);
    void batchStepDone(bool ok, bool skipped);
    void startBatch(int total, const QString &doing);
    void endBatch(const QString &summary);
    void runSystemPlan(Action action);
    void showPlanStep(const Deploy::DeployStep &step);
    void finishSystemPlan(const OnlineResult &result);
    void healRound();
    void finishHealRound(const OnlineResult &result);
    QString hostOf(const Live &live) const;
    struct PollRequest
    {
        QString instance;
        Corba::ComponentProxy proxy;
        bool readPorts = false;
    };
    /// Runs in a worker: the state (and ports when asked) of each component of one host.
    static QHash<QString, LiveComponentPoll> pollComponents(const QList<PollRequest> &requests);
    void applyPoll(const QHash<QString, LiveComponentPoll> &results);
    void finishRound();
    void markPortsStale();
    void syncConnectors();
    void applyColours();
    void showContextMenu(const QPoint &position);
    bool dropComponents(const QByteArray &data, const QPointF &scenePos);
    void requestConnection(const ConnectionCheck &check);
    std::optional<Corba::PortInfo> livePort(const QString &portName) const;
    void submitConnection(const QString &host, const std::function<void()> &call);
    void writeLiveSystem(const QString &path, const OnlineResult &result);
    void keepDiagramInView();
    void revealComponent(const QString &instanceName);
    void fitFreshDiagram();
    void growSceneRect();
    bool filterViewEvent(QEvent *event);

    OnlineSession *m_session;
    std::optional<SystemPlan> m_system;
    QAction *m_healAction = nullptr;
    QTimer *m_healTimer = nullptr;
    std::shared_ptr<Deploy::SystemHealer> m_healer;
    bool m_healStarted = false;
    bool m_healBusy = false;
    QString m_healRepository;
    Batch m_batch;
    QProgressBar *m_batchBar = nullptr;
    QPushButton *m_batchCancel = nullptr;
    QUndoStack *m_undoStack;
    SystemModel *m_model;
    SystemScene *m_scene;
    QGraphicsView *m_view = nullptr;
    QLabel *m_status = nullptr;
    QTimer *m_timer;
    QHash<QString, Live> m_live; ///< by instance name
    int m_pendingPolls = 0;
    int m_round = 0;
    int m_portReads = 0;
    ConnectorEditor m_connectorEditor;
    /// True until the user zooms, scrolls or clicks in the view: until then the whole diagram
    /// is kept fitted into it.
    bool m_keepFitted = true;
};

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::LiveComponentPoll)
Q_DECLARE_METATYPE(Deploy::DeployStep)
