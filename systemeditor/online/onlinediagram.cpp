// SPDX-License-Identifier: MIT
#include "onlinediagram.h"

#include "componentitem.h"
#include "componentproxy.h"
#include "concurrent.h"
#include "connectionrules.h"
#include "connectoritem.h"
#include "corbaerror.h"
#include "iorendpoint.h"
#include "livesystembuilder.h"
#include "namingbrowser.h"
#include "nameservicemodel.h"
#include "onlinecalls.h"
#include "onlineicons.h"
#include "onlinesession.h"
#include "portitem.h"
#include "rtpath.h"
#include "systemmodel.h"
#include "systemscene.h"

#include <algorithm>
#include <vector>

#include <QDragEnterEvent>
#include <QGraphicsView>
#include <QLabel>
#include <QHBoxLayout>
#include <QMenu>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollBar>
#include <QSettings>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

Q_DECLARE_METATYPE(Corba::ComponentInfo)

namespace SystemEditor {

namespace {

const QString PollIntervalKey = QStringLiteral("online/pollInterval");

void run(const Corba::ComponentProxy &proxy, OnlineDiagram::Action action)
{
    using A = OnlineDiagram::Action;
    switch (action) {
    case A::Activate:
        return proxy.activate();
    case A::Deactivate:
        return proxy.deactivate();
    case A::Reset:
        return proxy.reset();
    case A::Exit:
        return proxy.exit();
    case A::Start:
        return proxy.startContext();
    case A::Stop:
        return proxy.stopContext();
    }
}

} // namespace

OnlineDiagram::OnlineDiagram(OnlineSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_undoStack(new QUndoStack(this))
    , m_model(new SystemModel(this))
    , m_scene(new SystemScene(m_model, m_undoStack, this))
    , m_timer(new QTimer(this))
{
    qRegisterMetaType<LiveComponentPoll>();
    buildUi();
    m_timer->setInterval(QSettings().value(PollIntervalKey, 1000).toInt());
    connect(m_timer, &QTimer::timeout, this, &OnlineDiagram::poll);
    // Dragging from port to port connects live (after the dialog), never only in the model.
    connect(m_scene, &SystemScene::connectRequested, this, &OnlineDiagram::requestConnection);
    m_timer->start();
    // The scene rebuilds items from the model; the state colours go back on afterwards.
    connect(m_model, &SystemModel::componentChanged, this, &OnlineDiagram::applyColours,
            Qt::QueuedConnection);
    connect(m_model, &SystemModel::componentAdded, this, &OnlineDiagram::applyColours,
            Qt::QueuedConnection);
    // Connected after the scene, so its items are already there to fit or scroll to.
    connect(m_model, &SystemModel::componentAdded, this, &OnlineDiagram::revealComponent);
    connect(m_model, &SystemModel::componentChanged, this, &OnlineDiagram::keepDiagramInView);
    connect(m_model, &SystemModel::connectorAdded, this, &OnlineDiagram::keepDiagramInView);
    connect(m_model, &SystemModel::connectorRemoved, this, &OnlineDiagram::keepDiagramInView);
}

OnlineDiagram::~OnlineDiagram()
{
    // A plan still waiting (a SYNC wait may have no timeout) ends with its tab instead of holding
    // the deployment worker; the calls of a batch of single actions are still made.
    if (m_batch.plan)
        *m_batch.cancelled = true;
}

void OnlineDiagram::buildUi()
{
    m_view = new QGraphicsView(m_scene, this);
    m_view->setObjectName(QStringLiteral("onlineView"));
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setAcceptDrops(true);
    m_view->viewport()->installEventFilter(this);
    m_view->installEventFilter(this);
    // Scrolling by the bars (drag, arrows, wheel over them) is the user navigating too.
    for (QScrollBar *bar : {m_view->horizontalScrollBar(), m_view->verticalScrollBar()})
        connect(bar, &QScrollBar::actionTriggered, this, [this] { m_keepFitted = false; });
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_view, &QGraphicsView::customContextMenuRequested, this,
            &OnlineDiagram::showContextMenu);
    auto *toolbar = new QToolBar(this);
    const std::pair<const char *, Action> all[]
        = {{QT_TR_NOOP("Activate All"), Action::Activate},
           {QT_TR_NOOP("Deactivate All"), Action::Deactivate},
           {QT_TR_NOOP("Reset All"), Action::Reset},
           {QT_TR_NOOP("Start All"), Action::Start},
           {QT_TR_NOOP("Stop All"), Action::Stop},
           {QT_TR_NOOP("Exit All"), Action::Exit}};
    for (const auto &[text, action] : all) {
        const Action what = action;
        QAction *a = toolbar->addAction(tr(text), this, [this, what] { performAll(what); });
        a->setObjectName(QStringLiteral("action")
                         + QString::fromLatin1(text).remove(QLatin1Char(' ')));
    }
    toolbar->addSeparator();
    m_healAction = toolbar->addAction(tr("Keep Running"));
    m_healAction->setObjectName(QStringLiteral("actionKeepRunning"));
    m_healAction->setCheckable(true);
    m_healAction->setEnabled(false);
    m_healAction->setToolTip(tr("Open a saved system online to keep it running when a node dies"));
    connect(m_healAction, &QAction::toggled, this, [this](bool on) { setHealing(on); });
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("statusLabel"));
    // An action on every component: how far it got, and Cancel for the calls not yet made.
    m_batchBar = new QProgressBar(this);
    m_batchBar->setObjectName(QStringLiteral("batchProgress"));
    m_batchBar->setFormat(tr("%v of %m"));
    m_batchCancel = new QPushButton(tr("Cancel"), this);
    m_batchCancel->setObjectName(QStringLiteral("batchCancel"));
    connect(m_batchCancel, &QPushButton::clicked, this, &OnlineDiagram::cancelAll);
    auto *batchRow = new QHBoxLayout;
    batchRow->addWidget(m_batchBar, 1);
    batchRow->addWidget(m_batchCancel);
    m_batchBar->hide();
    m_batchCancel->hide();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(toolbar);
    layout->addWidget(m_view, 1);
    layout->addLayout(batchRow);
    layout->addWidget(m_status);
}

QString OnlineDiagram::hostOf(const Live &live) const
{
    const QString endpoint = Corba::iorEndpoint(live.ior);
    return endpoint.isEmpty() ? live.path : endpoint;
}

void OnlineDiagram::addComponent(const QString &path, const QString &ior, const QPointF &position)
{
    const Corba::ComponentProxy proxy(ior, path);
    Live probe {path, ior, {}, {}, true};
    m_session->submit(
        hostOf(probe), [proxy] { return QVariant::fromValue(proxy.profile()); }, this,
        [this, path, ior, position](const OnlineResult &result) {
            if (!result.ok) {
                m_status->setText(result.error);
                return;
            }
            const auto info = result.value.value<Corba::ComponentInfo>();
            if (m_model->hasComponent(info.instanceName))
                return;
            LiveComponentRecord record = LiveSystemBuilder::component(info, path, ior);
            Profile::RtsLocation location;
            location.x = QString::number(int(position.x()));
            location.y = QString::number(int(position.y()));
            location.width = location.height = QStringLiteral("-1");
            location.direction = QStringLiteral("RIGHT");
            record.component.layout = location;
            const int stagger = int(m_live.size()) % portRefreshRounds();
            m_live.insert(
                info.instanceName,
                {path, ior, Corba::LifeCycleState::Unknown, info.ports, true, stagger, false});
            m_model->addComponent(record.component, record.rtc);
            emit componentAdded(info.instanceName);
            poll();
        });
}

Corba::LifeCycleState OnlineDiagram::state(const QString &instanceName) const
{
    return m_live.value(instanceName).state;
}

QColor OnlineDiagram::bodyColor(const QString &instanceName) const
{
    const ComponentItem *item = m_scene->componentItem(instanceName);
    return item ? item->appearance().bodyColor : QColor();
}

void OnlineDiagram::setPollInterval(int milliseconds)
{
    m_timer->setInterval(std::max(50, milliseconds));
    QSettings().setValue(PollIntervalKey, m_timer->interval());
}

int OnlineDiagram::pollInterval() const
{
    return m_timer->interval();
}

void OnlineDiagram::poll()
{
    if (m_pendingPolls > 0 || m_live.isEmpty())
        return;
    ++m_round;
    // One call per host for all its components: one worker wake-up and one result per round
    // instead of one per component.
    QHash<QString, QList<PollRequest>> byHost;
    for (auto it = m_live.begin(); it != m_live.end(); ++it) {
        // The state is what changes from round to round; ports and connectors change rarely and
        // cost more calls, so they are read in one round of portRefreshRounds() (one call: the
        // component profile carries every port profile).
        const bool readPorts = it->portsStale || (m_round + it->stagger) % portRefreshRounds() == 0;
        it->portsStale = false;
        if (readPorts)
            ++m_portReads;
        byHost[hostOf(*it)].append({it.key(), Corba::ComponentProxy(it->ior, it->path), readPorts});
    }
    for (auto host = byHost.cbegin(); host != byHost.cend(); ++host) {
        const QList<PollRequest> requests = host.value();
        ++m_pendingPolls;
        m_session->submit(
            host.key(), [requests] { return QVariant::fromValue(pollComponents(requests)); }, this,
            [this](const OnlineResult &result) {
                applyPoll(result.value.value<QHash<QString, LiveComponentPoll>>());
                if (--m_pendingPolls == 0)
                    finishRound();
            });
    }
}

QHash<QString, LiveComponentPoll> OnlineDiagram::pollComponents(const QList<PollRequest> &requests)
{
    // States of all at once (one call each, references kept between rounds), then the ports of
    // those whose turn it is, several at once.
    QHash<QString, QString> iorsByPath;
    for (const PollRequest &request : requests)
        iorsByPath.insert(request.proxy.path(), request.proxy.ior());
    const QHash<QString, Corba::LifeCycleState> states = OnlineCalls::fetchStates(iorsByPath);
    std::vector<LiveComponentPoll> polled(std::size_t(requests.size()));
    Corba::forEachConcurrently(polled.size(), [&](std::size_t i) {
        const PollRequest &request = requests.at(qsizetype(i));
        LiveComponentPoll &result = polled[i];
        result.state = states.value(request.proxy.path(), Corba::LifeCycleState::Unknown);
        result.answered = result.state != Corba::LifeCycleState::Unknown;
        try {
            if (result.answered) {
                if (request.readPorts) {
                    result.ports = request.proxy.profile().ports;
                    result.portsRead = true;
                }
                return;
            }
        } catch (const Corba::Error &) {
            // Not answering is shown by the colour and the unreachable list, not as an error.
            result.answered = false;
        }
        // A component whose process was restarted answers under a new reference: ask the name
        // server for the one its name has now.
        try {
            const std::optional<Corba::RtPath> path = Corba::RtPath::parse(request.proxy.path());
            if (!path || path->isDirect() || path->names().isEmpty())
                return;
            const QString ior = Corba::NamingBrowser::resolve(*path);
            if (ior.isEmpty() || ior == request.proxy.ior())
                return;
            const Corba::ComponentProxy renewed(ior, request.proxy.path());
            result.state = renewed.state();
            result.ports = renewed.profile().ports;
            result.portsRead = true;
            result.answered = true;
            result.newIor = ior;
        } catch (const Corba::Error &) {
        }
    });
    QHash<QString, LiveComponentPoll> results;
    for (qsizetype i = 0; i < requests.size(); ++i)
        results.insert(requests.at(i).instance, polled[std::size_t(i)]);
    return results;
}

void OnlineDiagram::applyPoll(const QHash<QString, LiveComponentPoll> &results)
{
    for (auto polled = results.cbegin(); polled != results.cend(); ++polled) {
        auto live = m_live.find(polled.key());
        if (live == m_live.end())
            continue; // removed while the round ran
        // A component that does not answer is drawn as Unknown; its ports are read again as
        // soon as it answers.
        const bool ok = polled->answered;
        live->state = ok ? polled->state : Corba::LifeCycleState::Unknown;
        live->portsStale = live->portsStale || !ok;
        live->reachable = ok;
        if (!polled->newIor.isEmpty())
            live->ior = polled->newIor;
        if (polled->portsRead)
            live->ports = polled->ports;
    }
}

void OnlineDiagram::markPortsStale()
{
    for (Live &live : m_live)
        live.portsStale = true;
}

void OnlineDiagram::finishRound()
{
    syncConnectors();
    applyColours();
    const QStringList unreachable = unreachableComponents();
    if (!unreachable.isEmpty())
        m_status->setText(tr("Unreachable: %1").arg(unreachable.join(QStringLiteral(", "))));
    else if (m_status->text().startsWith(tr("Unreachable: ")))
        m_status->clear();
    emit polled();
}

QStringList OnlineDiagram::unreachableComponents() const
{
    QStringList names;
    for (auto it = m_live.cbegin(); it != m_live.cend(); ++it) {
        if (!it->reachable)
            names.append(it.key());
    }
    names.sort();
    return names;
}

void OnlineDiagram::syncConnectors()
{
    std::vector<Corba::PortInfo> ports;
    for (const Live &live : std::as_const(m_live))
        ports.insert(ports.end(), live.ports.begin(), live.ports.end());
    const QStringList instances = m_live.keys();
    QSet<QString> liveIds;
    for (const auto &c : LiveSystemBuilder::dataConnectors(ports, instances)) {
        liveIds.insert(c.connectorId);
        if (!m_model->connector(c.connectorId))
            m_model->addDataConnector(c);
    }
    for (const auto &c : LiveSystemBuilder::serviceConnectors(ports, instances)) {
        liveIds.insert(c.connectorId);
        if (!m_model->connector(c.connectorId))
            m_model->addServiceConnector(c);
    }
    // Connectors that no port reports any more were disconnected elsewhere.
    for (const QString &id : m_model->connectorIds()) {
        if (!liveIds.contains(id))
            m_model->removeConnector(id);
    }
}

void OnlineDiagram::applyColours()
{
    for (auto it = m_live.cbegin(); it != m_live.cend(); ++it)
        m_scene->setBodyColor(it.key(), OnlineIcons::stateColor(it->state));
}

void OnlineDiagram::perform(Action action, const QString &instanceName)
{
    submitAction(action, instanceName, nullptr);
}

void OnlineDiagram::submitAction(Action action, const QString &instanceName,
                                 const std::shared_ptr<std::atomic_bool> &cancelled)
{
    const auto live = m_live.constFind(instanceName);
    if (live == m_live.cend())
        return;
    const Corba::ComponentProxy proxy(live->ior, live->path);
    m_session->submit(
        hostOf(*live),
        [proxy, action, cancelled] {
            // A cancelled batch leaves the calls still queued unmade.
            if (cancelled && *cancelled)
                return QVariant(false);
            run(proxy, action);
            return QVariant(true);
        },
        this,
        [this, instanceName, cancelled](const OnlineResult &result) {
            if (!result.ok)
                m_status->setText(result.error);
            emit actionFinished(instanceName, result.ok ? QString() : result.error);
            if (cancelled)
                batchStepDone(result.ok, result.ok && !result.value.toBool());
            poll();
        });
}

void OnlineDiagram::performAll(Action action)
{
    if (m_batch.running())
        return;
    if (m_system && (action == Action::Start || action == Action::Stop)) {
        runSystemPlan(action);
        return;
    }
    static const char *const doing[] = {QT_TR_NOOP("Activating"), QT_TR_NOOP("Deactivating"),
                                        QT_TR_NOOP("Resetting"), QT_TR_NOOP("Exiting"),
                                        QT_TR_NOOP("Starting"), QT_TR_NOOP("Stopping")};
    const QStringList instances = m_live.keys();
    if (instances.isEmpty())
        return;
    startBatch(int(instances.size()), tr(doing[int(action)]));
    m_status->setText(tr("%1 %n component(s)…", nullptr, m_batch.total).arg(m_batch.doing));
    for (const QString &instance : instances)
        submitAction(action, instance, m_batch.cancelled);
}

void OnlineDiagram::startBatch(int total, const QString &doing)
{
    m_batch = Batch();
    m_batch.total = total;
    m_batch.doing = doing;
    m_batch.cancelled = std::make_shared<std::atomic_bool>(false);
    m_batchBar->setRange(0, m_batch.total);
    m_batchBar->setValue(0);
    m_batchBar->show();
    m_batchCancel->setEnabled(true);
    m_batchCancel->show();
}

void OnlineDiagram::endBatch(const QString &summary)
{
    m_batchBar->hide();
    m_batchCancel->hide();
    m_batch = Batch();
    emit allFinished(summary);
}

void OnlineDiagram::cancelAll()
{
    if (!m_batch.running())
        return;
    *m_batch.cancelled = true;
    m_batchCancel->setEnabled(false);
    m_status->setText(m_batch.plan
                          ? tr("Cancelling: the waits end, the actions not yet sent are not made…")
                          : tr("Cancelling: the calls under way finish, the others are not made…"));
}

void OnlineDiagram::batchStepDone(bool ok, bool skipped)
{
    if (!m_batch.running() || m_batch.plan)
        return;
    ++m_batch.done;
    m_batch.failed += ok ? 0 : 1;
    m_batch.skipped += skipped ? 1 : 0;
    m_batchBar->setValue(m_batch.done);
    if (m_batch.done < m_batch.total)
        return;
    const int made = m_batch.total - m_batch.skipped;
    QString summary = tr("%1: %2 of %n component(s) done", nullptr, m_batch.total)
                          .arg(m_batch.doing)
                          .arg(made - m_batch.failed);
    if (m_batch.failed > 0)
        summary += tr(", %n failed", nullptr, m_batch.failed);
    if (m_batch.skipped > 0)
        summary += tr(", %n cancelled", nullptr, m_batch.skipped);
    if (m_batch.failed == 0)
        m_status->setText(summary + QLatin1Char('.'));
    endBatch(summary);
}

void OnlineDiagram::monitorPort(const QString &instanceName, const QString &portName)
{
    const auto it = m_live.constFind(instanceName);
    if (it == m_live.constEnd())
        return;
    for (const Corba::PortInfo &port : it->ports) {
        if (port.shortName() == portName || port.name == portName) {
            emit m_session->portMonitorRequested(it->path, port);
            return;
        }
    }
}

void OnlineDiagram::showContextMenu(const QPoint &position)
{
    QGraphicsItem *hit = m_view->itemAt(position);
    while (hit && hit->type() != ComponentItem::Type && hit->type() != ConnectorItem::Type
           && hit->type() != PortItem::Type)
        hit = hit->parentItem();
    if (!hit)
        return;
    QMenu menu(this);
    if (hit->type() == PortItem::Type) {
        const auto *port = static_cast<PortItem *>(hit);
        const QString instance = port->instanceName();
        const QString name = port->port().name;
        QAction *monitor = menu.addAction(tr("&Monitor Port"), this,
                                          [this, instance, name] { monitorPort(instance, name); });
        monitor->setEnabled(port->port().kind == PortKind::DataOut);
        menu.exec(m_view->viewport()->mapToGlobal(position));
        return;
    }
    if (hit->type() == ConnectorItem::Type) {
        const QString id = static_cast<ConnectorItem *>(hit)->connectorId();
        menu.addAction(tr("Disconnect"), this, [this, id] { disconnectLive(id); });
        menu.exec(m_view->viewport()->mapToGlobal(position));
        return;
    }
    const QString instance = static_cast<ComponentItem *>(hit)->instanceName();
    const std::pair<QString, Action> actions[]
        = {{tr("Activate"), Action::Activate}, {tr("Deactivate"), Action::Deactivate},
           {tr("Reset"), Action::Reset},       {tr("Start"), Action::Start},
           {tr("Stop"), Action::Stop},         {tr("Exit"), Action::Exit}};
    for (const auto &[text, action] : actions) {
        const Action what = action;
        menu.addAction(text, this, [this, what, instance] { perform(what, instance); });
    }
    menu.exec(m_view->viewport()->mapToGlobal(position));
}

bool OnlineDiagram::dropComponents(const QByteArray &data, const QPointF &scenePos)
{
    QPointF position = scenePos;
    for (const QString &line :
         QString::fromUtf8(data).split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QString path = line.section(QLatin1Char('\t'), 0, 0);
        const QString ior = line.section(QLatin1Char('\t'), 1);
        if (ior.isEmpty())
            continue;
        addComponent(path, ior, position);
        position += QPointF(40, 160);
    }
    return true;
}

bool OnlineDiagram::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_view) {
        if (event->type() == QEvent::KeyPress)
            m_keepFitted = false; // arrow and page keys scroll the view
        return QWidget::eventFilter(watched, event);
    }
    if (watched != m_view->viewport())
        return QWidget::eventFilter(watched, event);
    if (filterViewEvent(event))
        return true;
    const QString mime = NameServiceModel::componentMimeType();
    switch (event->type()) {
    case QEvent::DragEnter:
    case QEvent::DragMove: {
        auto *drag = static_cast<QDragMoveEvent *>(event);
        if (!drag->mimeData()->hasFormat(mime))
            return false;
        drag->acceptProposedAction();
        return true;
    }
    case QEvent::Drop: {
        auto *drop = static_cast<QDropEvent *>(event);
        if (!drop->mimeData()->hasFormat(mime))
            return false;
        dropComponents(drop->mimeData()->data(mime),
                       m_view->mapToScene(drop->position().toPoint()));
        drop->acceptProposedAction();
        return true;
    }
    default:
        return QWidget::eventFilter(watched, event);
    }
}

bool OnlineDiagram::filterViewEvent(QEvent *event)
{
    switch (event->type()) {
    case QEvent::Wheel:
    case QEvent::MouseButtonPress:
        m_keepFitted = false; // the user navigates now; never move the view under them
        break;
    case QEvent::Resize:
    case QEvent::Show:
        // The tab settles into its size after the first components arrive.
        keepDiagramInView();
        break;
    default:
        break;
    }
    return false;
}

void OnlineDiagram::keepDiagramInView()
{
    if (m_keepFitted && m_view->isVisible())
        fitFreshDiagram();
}

void OnlineDiagram::revealComponent(const QString &instanceName)
{
    if (m_keepFitted) {
        keepDiagramInView();
        return;
    }
    growSceneRect();
    if (const ComponentItem *item = m_scene->componentItem(instanceName))
        m_view->ensureVisible(item);
}

void OnlineDiagram::growSceneRect()
{
    // Room around the diagram: the view can centre it, scroll a new component in with a margin
    // and let one be dragged past the edge; it only grows, so the view never jumps.
    const QRectF wanted = m_scene->diagramRect().adjusted(-400, -300, 400, 300);
    if (!m_view->sceneRect().contains(wanted))
        m_view->setSceneRect(m_view->sceneRect().united(wanted));
}

void OnlineDiagram::fitFreshDiagram()
{
    const QRectF diagram = m_scene->diagramRect();
    if (diagram.isEmpty())
        return;
    growSceneRect();
    // The whole diagram, centred, as the offline canvas opens a system; never magnified.
    const QRectF viewport = m_view->viewport()->rect();
    const qreal factor
        = std::min({viewport.width() / diagram.width(), viewport.height() / diagram.height(), 1.0});
    m_view->setTransform(QTransform::fromScale(factor, factor));
    m_view->centerOn(diagram.center());
}

} // namespace SystemEditor
