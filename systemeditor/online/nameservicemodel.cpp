// SPDX-License-Identifier: MIT
#include "nameservicemodel.h"

#include "iorendpoint.h"
#include "orb.h"
#include "onlineicons.h"

#include <QMimeData>

namespace SystemEditor {

using Corba::LifeCycleState;
using Corba::NamingNode;
using Corba::NodeType;

struct NameServiceModel::Item
{
    NamingNode node; // without children: those live in `children`
    QString server;
    QString endpoint;
    Item *parent = nullptr;
    std::vector<std::unique_ptr<Item>> children;

    int row() const
    {
        if (!parent)
            return 0;
        for (size_t i = 0; i < parent->children.size(); ++i) {
            if (parent->children[i].get() == this)
                return int(i);
        }
        return 0;
    }
};

NameServiceModel::NameServiceModel(QObject *parent)
    : QAbstractItemModel(parent)
    , m_root(std::make_unique<Item>())
{
    m_root->node.type = NodeType::Root;
    m_root->node.path = QStringLiteral("/");
}

NameServiceModel::~NameServiceModel() = default;

QString NameServiceModel::normaliseServer(const QString &address)
{
    const QString text = address.trimmed();
    if (text.isEmpty() || text.contains(QLatin1Char('/')) || text.contains(QLatin1Char(' ')))
        return {};
    const int colon = text.lastIndexOf(QLatin1Char(':'));
    if (colon < 0)
        return text + QStringLiteral(":2809");
    bool ok = false;
    const int port = text.mid(colon + 1).toInt(&ok);
    if (!ok || port <= 0 || port > 65535 || colon == 0)
        return {};
    return text;
}

bool NameServiceModel::addServer(const QString &address)
{
    const QString server = normaliseServer(address);
    if (server.isEmpty() || serverItem(server))
        return false;
    auto item = std::make_unique<Item>();
    item->node.name = server;
    item->node.type = NodeType::Server;
    item->node.path = QLatin1Char('/') + server;
    item->server = server;
    item->parent = m_root.get();
    const int row = int(m_root->children.size());
    beginInsertRows({}, row, row);
    m_root->children.push_back(std::move(item));
    endInsertRows();
    return true;
}

bool NameServiceModel::removeServer(const QString &server)
{
    Item *item = serverItem(server);
    if (!item)
        return false;
    const int row = item->row();
    beginRemoveRows({}, row, row);
    m_root->children.erase(m_root->children.begin() + row);
    endRemoveRows();
    m_unreachable.remove(server);
    return true;
}

QStringList NameServiceModel::servers() const
{
    QStringList result;
    for (const auto &child : m_root->children)
        result.append(child->server);
    return result;
}

NameServiceModel::Item *NameServiceModel::serverItem(const QString &server) const
{
    for (const auto &child : m_root->children) {
        if (child->server == server)
            return child.get();
    }
    return nullptr;
}

void NameServiceModel::appendChildren(Item *parent, const NamingNode &node)
{
    for (const NamingNode &childNode : node.children) {
        auto child = std::make_unique<Item>();
        child->node = childNode;
        child->node.children.clear();
        child->server = parent->server;
        child->endpoint = Corba::iorEndpoint(childNode.ior);
        child->parent = parent;
        appendChildren(child.get(), childNode);
        parent->children.push_back(std::move(child));
    }
}

void NameServiceModel::setServerTree(const QString &server, const NamingNode &tree,
                                     const QHash<QString, LifeCycleState> &states)
{
    Item *item = serverItem(server);
    if (!item)
        return;
    const QModelIndex serverIndex = indexOf(item);
    // Replacing the subtree wholesale keeps the model simple; views keep their expansion by path.
    if (!item->children.empty()) {
        beginRemoveRows(serverIndex, 0, int(item->children.size()) - 1);
        item->children.clear();
        endRemoveRows();
    }
    for (auto it = states.begin(); it != states.end(); ++it)
        m_states.insert(it.key(), it.value());
    Item fresh;
    fresh.server = server;
    appendChildren(&fresh, tree);
    if (fresh.children.empty())
        return;
    beginInsertRows(serverIndex, 0, int(fresh.children.size()) - 1);
    item->children = std::move(fresh.children);
    for (auto &child : item->children)
        child->parent = item;
    endInsertRows();
}

void NameServiceModel::setStates(const QHash<QString, LifeCycleState> &states)
{
    for (auto it = states.begin(); it != states.end(); ++it) {
        if (m_states.value(it.key(), LifeCycleState::Unknown) == it.value()
            && m_states.contains(it.key()))
            continue;
        m_states.insert(it.key(), it.value());
        const QModelIndex index = indexOfPath(it.key());
        if (index.isValid())
            emit dataChanged(index, index.siblingAtColumn(columnCount() - 1));
    }
}

void NameServiceModel::setHostReachable(const QString &host, bool reachable, const QString &message)
{
    if (reachable == !m_unreachable.contains(host))
        return;
    if (reachable)
        m_unreachable.remove(host);
    else
        m_unreachable.insert(host, message);
    // Flags and colours of any item may depend on the host, so the whole tree is announced.
    touchSubtree(m_root.get());
}

void NameServiceModel::touchSubtree(Item *parent)
{
    if (parent->children.empty())
        return;
    const QModelIndex parentIndex = indexOf(parent);
    emit dataChanged(index(0, 0, parentIndex),
                     index(int(parent->children.size()) - 1, columnCount() - 1, parentIndex));
    for (auto &child : parent->children)
        touchSubtree(child.get());
}

bool NameServiceModel::isHostReachable(const QString &host) const
{
    return !m_unreachable.contains(host);
}

bool NameServiceModel::unreachable(const Item *item) const
{
    return !item->node.answering || m_unreachable.contains(item->server)
        || (!item->endpoint.isEmpty() && m_unreachable.contains(item->endpoint));
}

LifeCycleState NameServiceModel::stateOf(const Item *item) const
{
    // A component whose process does not answer has no known state, whatever it was before.
    if (unreachable(item))
        return LifeCycleState::Unknown;
    return m_states.value(item->node.path, LifeCycleState::Unknown);
}

bool NameServiceModel::isUnreachable(const QModelIndex &index) const
{
    return index.isValid() && unreachable(itemOf(index));
}

QModelIndex NameServiceModel::indexOfPath(const QString &path) const
{
    std::function<const Item *(const Item *)> find = [&](const Item *item) -> const Item * {
        if (item->node.path == path && item != m_root.get())
            return item;
        for (const auto &child : item->children) {
            if (const Item *found = find(child.get()))
                return found;
        }
        return nullptr;
    };
    const Item *found = find(m_root.get());
    return found ? indexOf(found) : QModelIndex();
}

QStringList NameServiceModel::zombiePaths(const QString &server) const
{
    QStringList result;
    std::function<void(const Item *)> collect = [&](const Item *item) {
        if (item->node.type == NodeType::Zombie && (server.isEmpty() || item->server == server))
            result.append(item->node.path);
        for (const auto &child : item->children)
            collect(child.get());
    };
    collect(m_root.get());
    return result;
}

NameServiceModel::Item *NameServiceModel::itemOf(const QModelIndex &index) const
{
    return index.isValid() ? static_cast<Item *>(index.internalPointer()) : m_root.get();
}

QModelIndex NameServiceModel::indexOf(const Item *item) const
{
    if (!item || item == m_root.get())
        return {};
    return createIndex(item->row(), 0, const_cast<Item *>(item));
}

QModelIndex NameServiceModel::index(int row, int column, const QModelIndex &parent) const
{
    if (!hasIndex(row, column, parent))
        return {};
    Item *parentItem = itemOf(parent);
    return createIndex(row, column, parentItem->children[size_t(row)].get());
}

QModelIndex NameServiceModel::parent(const QModelIndex &child) const
{
    if (!child.isValid())
        return {};
    return indexOf(itemOf(child)->parent);
}

int NameServiceModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid() && parent.column() != 0)
        return 0;
    return int(itemOf(parent)->children.size());
}

int NameServiceModel::columnCount(const QModelIndex &) const
{
    return 2;
}

QVariant NameServiceModel::displayData(const Item *item, int column) const
{
    if (column == 0)
        return item->node.name;
    if (!item->node.answering)
        return tr("not answering");
    switch (item->node.type) {
    case NodeType::Component:
        return OnlineIcons::stateLabel(stateOf(item));
    case NodeType::Zombie:
        return tr("zombie");
    case NodeType::Server:
        return unreachable(item) ? tr("unreachable") : tlsLabel(item);
    default:
        return OnlineIcons::nodeTypeLabel(item->node.type);
    }
}

QString NameServiceModel::serverIdentity(const Item *item) const
{
    // The identity is recorded by the numeric address the connection went to.
    const QString byEndpoint = Corba::Orb::peerIdentity(item->endpoint);
    if (!byEndpoint.isEmpty())
        return byEndpoint;
    QString server = item->server;
    if (server.startsWith(QLatin1String("localhost")))
        server.replace(0, int(qstrlen("localhost")), QStringLiteral("127.0.0.1"));
    if (!server.contains(QLatin1Char(':')))
        server += QStringLiteral(":2809");
    return Corba::Orb::peerIdentity(server);
}

QString NameServiceModel::tlsLabel(const Item *item) const
{
    if (!Corba::Orb::usesTls())
        return {};
    const QString identity = serverIdentity(item);
    return identity.isEmpty() ? tr("TLS") : tr("TLS: %1").arg(identity);
}

QString NameServiceModel::tlsToolTip(const Item *item) const
{
    const QString identity = serverIdentity(item);
    return identity.isEmpty()
        ? tr("%1\nEncrypted with TLS").arg(item->node.path)
        : tr("%1\nEncrypted with TLS; the server proved to be \"%2\" with a certificate of your authority")
              .arg(item->node.path, identity);
}

QVariant NameServiceModel::decoration(const Item *item) const
{
    const NodeType type = item->node.type;
    if (type == NodeType::Component)
        return OnlineIcons::component(stateOf(item));
    return OnlineIcons::node(type);
}

QVariant NameServiceModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Item *item = itemOf(index);
    switch (role) {
    case Qt::DisplayRole:
        return displayData(item, index.column());
    case Qt::DecorationRole:
        return index.column() == 0 ? decoration(item) : QVariant();
    case Qt::ToolTipRole:
        if (item->node.type == NodeType::Zombie || !item->node.answering)
            return item->node.reason;
        if (unreachable(item))
            return m_unreachable.value(item->server, m_unreachable.value(item->endpoint));
        if (item->node.type == NodeType::Server && Corba::Orb::usesTls())
            return tlsToolTip(item);
        return item->node.path;
    case PathRole:
        return item->node.path;
    case TypeRole:
        return int(item->node.type);
    case IorRole:
        return item->node.ior;
    case StateRole:
        return int(stateOf(item));
    case ServerRole:
        return item->server;
    case ReasonRole:
        return item->node.reason;
    case EndpointRole:
        return item->endpoint;
    default:
        return {};
    }
}

QVariant NameServiceModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return section == 0 ? tr("Name") : tr("State");
}

Qt::ItemFlags NameServiceModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    const Item *item = itemOf(index);
    // Greyed, yet selectable, so the user can still remove the server or read the reason.
    Qt::ItemFlags result = Qt::ItemIsSelectable;
    if (!unreachable(item))
        result |= Qt::ItemIsEnabled;
    if (item->node.type == NodeType::Component && !item->node.ior.isEmpty()
        && (result & Qt::ItemIsEnabled))
        result |= Qt::ItemIsDragEnabled;
    return result;
}

QString NameServiceModel::componentMimeType()
{
    return QStringLiteral("application/x-rtstudio-live-component");
}

QStringList NameServiceModel::mimeTypes() const
{
    return {componentMimeType()};
}

QMimeData *NameServiceModel::mimeData(const QModelIndexList &indexes) const
{
    QStringList lines;
    for (const QModelIndex &index : indexes) {
        const Item *item = itemOf(index);
        if (index.column() == 0 && item->node.type == NodeType::Component)
            lines.append(item->node.path + QLatin1Char('\t') + item->node.ior);
    }
    if (lines.isEmpty())
        return nullptr;
    auto *mime = new QMimeData;
    mime->setData(componentMimeType(), lines.join(QLatin1Char('\n')).toUtf8());
    mime->setText(lines.join(QLatin1Char('\n')));
    return mime;
}

} // namespace SystemEditor
