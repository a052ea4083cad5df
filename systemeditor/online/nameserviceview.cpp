// SPDX-License-Identifier: MIT
#include "nameserviceview.h"

#include "iorendpoint.h"
#include "nameservicemodel.h"
#include "onlinesession.h"

#include <QAction>
#include <QDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPlainTextEdit>
#include <QSettings>
#include <QShowEvent>
#include <QSortFilterProxyModel>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>

namespace SystemEditor {

using Corba::NodeType;

namespace {

const QString ServersKey = QStringLiteral("online/nameServers");

QToolButton *toolButton(const QString &text, const QString &name, QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setText(text);
    button->setObjectName(name);
    button->setAutoRaise(true);
    return button;
}

// The worker key of an item: the process serving the object when its IOR tells, else its server.
QString hostOf(const QModelIndex &index)
{
    const QString endpoint = index.data(NameServiceModel::EndpointRole).toString();
    return endpoint.isEmpty() ? index.data(NameServiceModel::ServerRole).toString() : endpoint;
}

} // namespace

NameServiceView::NameServiceView(OnlineSession *session, QSettings *settings, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_settings(settings)
    , m_model(new NameServiceModel(this))
    , m_filter(new QSortFilterProxyModel(this))
{
    m_filter->setSourceModel(m_model);
    m_filter->setRecursiveFilteringEnabled(true);
    m_filter->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_filter->setSortCaseSensitivity(Qt::CaseInsensitive);
    m_filter->sort(0);
    buildUi();
    connect(m_session, &OnlineSession::hostReachabilityChanged, this,
            &NameServiceView::onReachability);
    if (m_settings) {
        for (const QString &server : m_settings->value(ServersKey).toStringList())
            m_model->addServer(server);
    }
    m_pollTimer = new QTimer(this);
    m_pollTimer->setInterval(
        QSettings().value(QStringLiteral("online/pollInterval"), 1000).toInt());
    connect(m_pollTimer, &QTimer::timeout, this, [this] {
        if (isVisible())
            pollStates();
    });
    m_pollTimer->start();
}

int NameServiceView::pollInterval() const
{
    return m_pollTimer->interval();
}

void NameServiceView::pollStates()
{
    QHash<QString, QHash<QString, QString>> byEndpoint; // endpoint → path → IOR
    std::function<void(const QModelIndex &)> collect = [&](const QModelIndex &parent) {
        for (int row = 0; row < m_model->rowCount(parent); ++row) {
            const QModelIndex index = m_model->index(row, 0, parent);
            const QString ior = index.data(NameServiceModel::IorRole).toString();
            if (NodeType(index.data(NameServiceModel::TypeRole).toInt()) == NodeType::Component
                && !ior.isEmpty()) {
                byEndpoint[hostOf(index)].insert(index.data(NameServiceModel::PathRole).toString(),
                                                 ior);
            }
            collect(index);
        }
    };
    collect({});
    for (auto it = byEndpoint.begin(); it != byEndpoint.end(); ++it) {
        const QString endpoint = it.key();
        if (m_polling.contains(endpoint))
            continue;
        m_polling.insert(endpoint);
        const QHash<QString, QString> iors = it.value();
        m_session->submit(
            endpoint, [iors] { return QVariant::fromValue(OnlineCalls::fetchStates(iors)); }, this,
            [this, endpoint](const OnlineResult &result) {
                m_polling.remove(endpoint);
                if (result.ok)
                    applyPolledStates(result.value.value<ComponentStates>());
            });
    }
}

void NameServiceView::applyPolledStates(const QHash<QString, Corba::LifeCycleState> &states)
{
    // Components listed below their manager carry no reference; they follow the same name.
    QHash<QString, Corba::LifeCycleState> all = states;
    QHash<QString, Corba::LifeCycleState> byName;
    for (auto it = states.begin(); it != states.end(); ++it)
        byName.insert(it.key().section(QLatin1Char('/'), -1), it.value());
    std::function<void(const QModelIndex &)> follow = [&](const QModelIndex &parent) {
        for (int row = 0; row < m_model->rowCount(parent); ++row) {
            const QModelIndex index = m_model->index(row, 0, parent);
            const QString path = index.data(NameServiceModel::PathRole).toString();
            if (NodeType(index.data(NameServiceModel::TypeRole).toInt()) == NodeType::Component
                && index.data(NameServiceModel::IorRole).toString().isEmpty()
                && byName.contains(index.data().toString()))
                all.insert(path, OnlineCalls::managedState(path, states, byName));
            follow(index);
        }
    };
    follow({});
    m_model->setStates(all);
    emit statesPolled();
}

void NameServiceView::buildUi()
{
    m_serverEdit = new QLineEdit(this);
    m_serverEdit->setObjectName(QStringLiteral("nameServerEdit"));
    m_serverEdit->setPlaceholderText(tr("host[:port]"));
    auto *add = toolButton(tr("Add"), QStringLiteral("addNameServerButton"), this);
    add->setToolTip(tr("Add a name server (port 2809 when none is given)"));
    auto *refreshButton = toolButton(tr("Refresh"), QStringLiteral("refreshButton"), this);
    auto *zombies = toolButton(tr("Delete Zombies"), QStringLiteral("deleteZombiesButton"), this);
    zombies->setToolTip(tr("Remove every name whose object does not answer"));
    m_filterEdit = new QLineEdit(this);
    m_filterEdit->setObjectName(QStringLiteral("filterEdit"));
    m_filterEdit->setPlaceholderText(tr("Filter"));
    m_filterEdit->setClearButtonEnabled(true);

    m_tree = new QTreeView(this);
    m_tree->setObjectName(QStringLiteral("nameServiceTree"));
    m_tree->setModel(m_filter);
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
    m_tree->setDragEnabled(true);
    m_tree->setDragDropMode(QAbstractItemView::DragOnly);
    m_tree->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("statusLabel"));
    m_status->setWordWrap(true);

    auto *serverRow = new QHBoxLayout;
    serverRow->addWidget(m_serverEdit, 1);
    serverRow->addWidget(add);
    auto *toolRow = new QHBoxLayout;
    toolRow->addWidget(m_filterEdit, 1);
    toolRow->addWidget(refreshButton);
    toolRow->addWidget(zombies);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(serverRow);
    layout->addLayout(toolRow);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_status);

    auto addFromEdit = [this] {
        if (addServer(m_serverEdit->text()))
            m_serverEdit->clear();
        else
            report(tr("'%1' is not a new name server address").arg(m_serverEdit->text()));
    };
    connect(add, &QToolButton::clicked, this, addFromEdit);
    connect(m_serverEdit, &QLineEdit::returnPressed, this, addFromEdit);
    connect(refreshButton, &QToolButton::clicked, this, &NameServiceView::refresh);
    connect(zombies, &QToolButton::clicked, this, [this] { deleteZombies(); });
    connect(m_filterEdit, &QLineEdit::textChanged, this, &NameServiceView::setFilterText);
    connect(m_tree, &QTreeView::customContextMenuRequested, this,
            &NameServiceView::showContextMenu);
}

bool NameServiceView::addServer(const QString &address)
{
    if (!m_model->addServer(address))
        return false;
    saveServers();
    refreshServer(NameServiceModel::normaliseServer(address));
    return true;
}

void NameServiceView::removeServer(const QString &server)
{
    if (m_model->removeServer(server))
        saveServers();
}

void NameServiceView::saveServers() const
{
    if (m_settings)
        m_settings->setValue(ServersKey, m_model->servers());
}

void NameServiceView::refresh()
{
    for (const QString &server : m_model->servers())
        refreshServer(server);
}

void NameServiceView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (!m_readOnFirstShow)
        return;
    m_readOnFirstShow = false;
    refresh();
}

void NameServiceView::refreshServer(const QString &server)
{
    // First the names, which only the name server is asked for: the tree shows at once, whatever
    // the objects do. Then the objects themselves, which take up to a call timeout when some hang.
    m_session->submit(
        server,
        [server] {
            return QVariant::fromValue(
                OnlineCalls::fetchServer(server, Corba::NamingBrowser::Check::NamesOnly));
        },
        this, [this, server](const OnlineResult &result) {
            if (!showServer(server, result))
                return;
            emit serverListed(server);
            checkServer(server);
        });
}

void NameServiceView::checkServer(const QString &server)
{
    m_session->submit(
        server,
        [server] {
            return QVariant::fromValue(
                OnlineCalls::fetchServer(server, Corba::NamingBrowser::Check::Objects));
        },
        this, [this, server](const OnlineResult &result) {
            if (showServer(server, result))
                emit serverRefreshed(server);
        });
}

bool NameServiceView::showServer(const QString &server, const OnlineResult &result)
{
    if (!result.ok) {
        // An unreachable server is reported once through onReachability().
        if (!result.hostFailure)
            report(result.error);
        m_model->setServerTree(server, {}, {});
        return false;
    }
    const auto snapshot = result.value.value<ServerSnapshot>();
    m_model->setServerTree(server, snapshot.tree, snapshot.states);
    m_tree->expandAll();
    return true;
}

void NameServiceView::setFilterText(const QString &text)
{
    if (m_filterEdit->text() != text)
        m_filterEdit->setText(text);
    m_filter->setFilterFixedString(text);
    if (!text.isEmpty())
        m_tree->expandAll();
}

QList<QAction *> NameServiceView::contextActions(const QModelIndex &index)
{
    QList<QAction *> actions;
    auto add = [&](const QString &text, const QString &name, auto slot) {
        auto *action = new QAction(text, this);
        action->setObjectName(name);
        connect(action, &QAction::triggered, this, slot);
        actions.append(action);
    };
    const QPersistentModelIndex persistent(index);
    auto remote = [&](const QString &text, const QString &name, RemoteAction what) {
        add(text, name, [this, persistent, what] { perform(what, persistent); });
    };
    const auto type = NodeType(index.data(NameServiceModel::TypeRole).toInt());
    switch (type) {
    case NodeType::Component:
        // Components listed below a manager come without a reference: nothing to call.
        if (index.data(NameServiceModel::IorRole).toString().isEmpty())
            break;
        remote(tr("Activate"), QStringLiteral("actionActivate"), RemoteAction::Activate);
        remote(tr("Deactivate"), QStringLiteral("actionDeactivate"), RemoteAction::Deactivate);
        remote(tr("Reset"), QStringLiteral("actionReset"), RemoteAction::Reset);
        remote(tr("Exit"), QStringLiteral("actionExit"), RemoteAction::Exit);
        break;
    case NodeType::Manager:
        remote(tr("Shutdown"), QStringLiteral("actionShutdown"), RemoteAction::Shutdown);
        remote(tr("Restart"), QStringLiteral("actionRestart"), RemoteAction::Restart);
        break;
    case NodeType::Zombie:
        remote(tr("Delete Zombie"), QStringLiteral("actionDeleteZombie"), RemoteAction::Unbind);
        break;
    case NodeType::Server: {
        const QString server = index.data(NameServiceModel::ServerRole).toString();
        add(tr("Delete All Zombies"), QStringLiteral("actionDeleteAllZombies"),
            [this, server] { deleteZombies(server); });
        add(tr("Remove Name Server"), QStringLiteral("actionRemoveServer"),
            [this, server] { removeServer(server); });
        break;
    }
    default:
        break;
    }
    if (!index.data(NameServiceModel::IorRole).toString().isEmpty())
        add(tr("Show IOR"), QStringLiteral("actionShowIor"),
            [this, persistent] { showIor(persistent); });
    add(tr("Refresh"), QStringLiteral("actionRefresh"), &NameServiceView::refresh);
    return actions;
}

void NameServiceView::showContextMenu(const QPoint &position)
{
    const QModelIndex index = m_filter->mapToSource(m_tree->indexAt(position));
    if (!index.isValid())
        return;
    QMenu menu(this);
    const QList<QAction *> actions = contextActions(index.siblingAtColumn(0));
    menu.addActions(actions);
    menu.exec(m_tree->viewport()->mapToGlobal(position));
    qDeleteAll(actions);
}

void NameServiceView::perform(RemoteAction action, const QModelIndex &index)
{
    if (!index.isValid())
        return;
    const QString path = index.data(NameServiceModel::PathRole).toString();
    const QString ior = index.data(NameServiceModel::IorRole).toString();
    const QString server = index.data(NameServiceModel::ServerRole).toString();
    // Unbinding talks to the name server; everything else to the object's own process.
    const QString host = action == RemoteAction::Unbind ? server : hostOf(index);
    m_session->submit(
        host,
        [action, path, ior] {
            OnlineCalls::perform(action, path, ior);
            return QVariant();
        },
        this,
        [this, path, server](const OnlineResult &result) {
            if (!result.ok && !result.hostFailure)
                report(result.error);
            emit actionFinished(path, result.ok ? QString() : result.error);
            refreshServer(server);
        });
}

void NameServiceView::deleteZombies(const QString &server)
{
    for (const QString &path : m_model->zombiePaths(server))
        perform(RemoteAction::Unbind, m_model->indexOfPath(path));
}

QWidget *NameServiceView::showIor(const QModelIndex &index)
{
    auto *dialog = new QDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setObjectName(QStringLiteral("iorDialog"));
    dialog->setWindowTitle(tr("IOR of %1").arg(index.data(NameServiceModel::PathRole).toString()));
    auto *text = new QPlainTextEdit(index.data(NameServiceModel::IorRole).toString(), dialog);
    text->setReadOnly(true);
    text->setObjectName(QStringLiteral("iorText"));
    auto *layout = new QVBoxLayout(dialog);
    layout->addWidget(text);
    dialog->resize(520, 200);
    dialog->show();
    return dialog;
}

void NameServiceView::onReachability(const QString &host, bool reachable, const QString &message)
{
    m_model->setHostReachable(host, reachable, message);
    report(reachable ? tr("%1 answers again").arg(host)
                     : tr("%1 does not answer: %2").arg(host, message));
}

void NameServiceView::report(const QString &message)
{
    m_status->setText(message);
    emit problemReported(message);
}

QString NameServiceView::statusText() const
{
    return m_status->text();
}

QModelIndex NameServiceView::currentSourceIndex() const
{
    return m_filter->mapToSource(m_tree->currentIndex());
}

} // namespace SystemEditor
