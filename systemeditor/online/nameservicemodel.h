// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "namingbrowser.h"

#include <QAbstractItemModel>
#include <QHash>

#include <memory>
#include <vector>

namespace SystemEditor {

/**
 * The live-status model of the Name Service view: name servers at the top, then naming contexts,
 * components, managers, other objects and zombies as the last refresh found them. It holds only
 * values delivered by the worker layer (never an object reference it would call itself).
 * Items of a server that does not answer are shown disabled (greyed).
 */
class NameServiceModel : public QAbstractItemModel
{
    Q_OBJECT

public:
    enum Role {
        PathRole = Qt::UserRole + 1, ///< absolute rtshell path (QString)
        TypeRole, ///< Corba::NodeType as int
        IorRole, ///< object reference string, empty for contexts
        StateRole, ///< Corba::LifeCycleState as int, components only
        ServerRole, ///< the name server the item belongs to
        ReasonRole, ///< why a zombie is one
        EndpointRole ///< `host:port` serving the object (from its IOR), empty when unknown
    };

    explicit NameServiceModel(QObject *parent = nullptr);
    ~NameServiceModel() override;

    /// Adds a server (`host` or `host:port`, normalised to `host:2809` when no port); false if
    /// present.
    bool addServer(const QString &address);
    bool removeServer(const QString &server);
    QStringList servers() const;
    /// `host` → `host:2809`; `host:port` unchanged. Empty for text that is not an address.
    static QString normaliseServer(const QString &address);

    /// Replaces what is below `server` by the children of `tree`, with component states by path.
    void setServerTree(const QString &server, const Corba::NamingNode &tree,
                       const QHash<QString, Corba::LifeCycleState> &states);
    /// Updates component states without changing the tree.
    void setStates(const QHash<QString, Corba::LifeCycleState> &states);
    /**
     * Marks a host as answering or not. `host` is a name server (everything below it greys) or the
     * `host:port` endpoint of the process serving objects (its components and managers grey).
     */
    void setHostReachable(const QString &host, bool reachable, const QString &message = {});
    bool isHostReachable(const QString &host) const;
    /// True when the item is shown greyed: it, its server or its endpoint does not answer.
    bool isUnreachable(const QModelIndex &index) const;

    /// The index of the item at `path`, invalid when none.
    QModelIndex indexOfPath(const QString &path) const;
    /// Paths of every zombie below `server` (all servers when empty).
    QStringList zombiePaths(const QString &server = QString()) const;

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QStringList mimeTypes() const override;
    QMimeData *mimeData(const QModelIndexList &indexes) const override;

    /// MIME type of dragged live components: one `path\tior` line per component.
    static QString componentMimeType();

private:
    struct Item;

    Item *itemOf(const QModelIndex &index) const;
    QModelIndex indexOf(const Item *item) const;
    Item *serverItem(const QString &server) const;
    void appendChildren(Item *parent, const Corba::NamingNode &node);
    QVariant displayData(const Item *item, int column) const;
    QVariant decoration(const Item *item) const;
    /// A server's certificate name when this program reached it over TLS.
    QString serverIdentity(const Item *item) const;
    QString tlsLabel(const Item *item) const;
    QString tlsToolTip(const Item *item) const;
    bool unreachable(const Item *item) const;
    Corba::LifeCycleState stateOf(const Item *item) const;
    void touchSubtree(Item *parent);

    std::unique_ptr<Item> m_root;
    QHash<QString, Corba::LifeCycleState> m_states;
    QHash<QString, QString> m_unreachable; ///< server or endpoint → message
};

} // namespace SystemEditor
