// SPDX-License-Identifier: MIT
#pragma once

#include "onlinecalls.h"
#include "onlineservice.h"

#include <QSet>
#include <QWidget>

class QLabel;
class QLineEdit;
class QMenu;
class QSettings;
class QSortFilterProxyModel;
class QTimer;
class QTreeView;

namespace SystemEditor {

class NameServiceModel;
class OnlineSession;

/**
 * The Name Service view: name servers (added as `host[:port]`, remembered in QSettings), their
 * contexts, components, managers and zombies with state icons; refresh, filter, delete zombies,
 * show IOR and the component/manager context menu. Every remote call goes through the
 * OnlineSession; the view only listens to the results.
 */
class NameServiceView : public QWidget
{
    Q_OBJECT

public:
    /// `settings` (may be null) stores the server list under `online/nameServers`.
    NameServiceView(OnlineSession *session, QSettings *settings, QWidget *parent = nullptr);

    NameServiceModel *model() const { return m_model; }
    QSortFilterProxyModel *filterModel() const { return m_filter; }
    QTreeView *treeView() const { return m_tree; }

    /// Adds a server, stores the list and refreshes it; false for a bad or duplicate address.
    bool addServer(const QString &address);
    void removeServer(const QString &server);
    /// Re-reads every server (or one) through the worker layer.
    void refresh();
    void refreshServer(const QString &server);
    void setFilterText(const QString &text);

    /// The actions the context menu shows for `sourceIndex` (an index of model()).
    QList<QAction *> contextActions(const QModelIndex &sourceIndex);
    /// Runs `action` on the item at `sourceIndex`, then refreshes its server.
    void perform(RemoteAction action, const QModelIndex &sourceIndex);
    /// Unbinds every zombie of `server` (all servers when empty).
    void deleteZombies(const QString &server = QString());
    /// Opens a window showing the IOR of the item; returns it (also for tests).
    QWidget *showIor(const QModelIndex &sourceIndex);
    /// The last message shown in the status line.
    QString statusText() const;
    /// Interval of the background state poll (QSettings `online/pollInterval`, default 1000 ms).
    int pollInterval() const;
    /// Asks every component in the tree for its state now (grouped by serving process; a process
    /// whose previous poll has not answered yet is skipped).
    void pollStates();

protected:
    /// The first time the view is shown, the servers it remembers are read (their trees, or
    /// that they do not answer).
    void showEvent(QShowEvent *event) override;

signals:
    /// A background state poll answered and the model was updated.
    void statesPolled();
    /// A server's names were read (only the name server was asked) and the model shows them.
    void serverListed(const QString &server);
    /// A server was read, its objects checked and their states taken, and the model updated.
    void serverRefreshed(const QString &server);
    /// A remote action finished; `error` is empty on success.
    void actionFinished(const QString &path, const QString &error);
    /// A host stopped answering (once per outage) or a call failed.
    void problemReported(const QString &message);

private:
    void buildUi();
    void saveServers() const;
    void showContextMenu(const QPoint &position);
    void onReachability(const QString &host, bool reachable, const QString &message);
    void report(const QString &message);
    QModelIndex currentSourceIndex() const;
    void applyPolledStates(const QHash<QString, Corba::LifeCycleState> &states);
    /// Second step of a refresh: checks the objects below `server` and takes their states.
    void checkServer(const QString &server);
    /// Shows a read of `server` (or reports why there is none); true when it was read.
    bool showServer(const QString &server, const OnlineResult &result);

    OnlineSession *m_session;
    QSettings *m_settings;
    NameServiceModel *m_model;
    QSortFilterProxyModel *m_filter;
    QTreeView *m_tree = nullptr;
    QLineEdit *m_serverEdit = nullptr;
    QLineEdit *m_filterEdit = nullptr;
    QLabel *m_status = nullptr;
    QTimer *m_pollTimer = nullptr;
    QSet<QString> m_polling; ///< endpoints with a state poll under way
    bool m_readOnFirstShow = true; ///< the remembered servers are still to be read
};

} // namespace SystemEditor
