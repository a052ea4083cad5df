// SPDX-License-Identifier: MIT
#include "systemoutlinemodel.h"

#include "rtsdocument.h"
#include "rtstudioresources.h"

namespace Studio {

namespace {

constexpr int RootNode = 0;

QString endText(const Profile::RtsTargetPort &end)
{
    return QStringLiteral("%1 · %2").arg(end.instanceName, end.portName);
}

} // namespace

SystemOutlineModel::SystemOutlineModel(RtsDocument *document, QObject *parent)
    : QAbstractItemModel(parent)
    , m_document(document)
    , m_componentIcon(Resources::iconPath(QStringLiteral("component")))
    , m_dataPortIcon(Resources::iconPath(QStringLiteral("port-data")))
    , m_servicePortIcon(Resources::iconPath(QStringLiteral("port-service")))
    , m_connectorIcon(Resources::iconPath(QStringLiteral("connector")))
{
    build();
    // The outline is small; rebuilding it on every change of the system keeps it simple and right.
    if (document) {
        connect(document, &RtsDocument::systemChanged, this, [this] {
            beginResetModel();
            build();
            endResetModel();
        });
    }
}

QModelIndex SystemOutlineModel::index(int row, int column, const QModelIndex &parent) const
{
    if (column < 0 || column >= ColumnCount || row < 0)
        return {};
    const int parentNode = nodeOf(parent);
    if (parentNode < 0)
        return {};
    const std::vector<int> &children = m_nodes[std::size_t(parentNode)].children;
    if (std::size_t(row) >= children.size())
        return {};
    return createIndex(row, column, quintptr(children[std::size_t(row)]));
}

QModelIndex SystemOutlineModel::parent(const QModelIndex &child) const
{
    const int node = nodeOf(child);
    if (node <= RootNode)
        return {};
    return indexOfNode(m_nodes[std::size_t(node)].parent);
}

int SystemOutlineModel::rowCount(const QModelIndex &parent) const
{
    // Only the first column has children, as QTreeView and the model tester expect.
    if (parent.isValid() && parent.column() != NameColumn)
        return 0;
    const int node = nodeOf(parent);
    return node < 0 ? 0 : int(m_nodes[std::size_t(node)].children.size());
}

int SystemOutlineModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

QVariant SystemOutlineModel::data(const QModelIndex &index, int role) const
{
    const int nodeIndex = nodeOf(index);
    if (nodeIndex <= RootNode)
        return {};
    const Node &node = m_nodes[std::size_t(nodeIndex)];
    switch (role) {
    case Qt::DisplayRole:
        return index.column() == NameColumn ? node.name : node.details;
    case Qt::ToolTipRole:
        return node.toolTip.isEmpty() ? QVariant() : QVariant(node.toolTip);
    case Qt::DecorationRole:
        return index.column() == NameColumn ? QVariant(iconFor(node.kind)) : QVariant();
    case NodeKindRole:
        return int(node.kind);
    case InstanceNameRole:
        return node.instanceName.isEmpty() ? QVariant() : QVariant(node.instanceName);
    case PortNameRole:
        return node.portName.isEmpty() ? QVariant() : QVariant(node.portName);
    case ConnectorIdRole:
        return node.connectorId.isEmpty() ? QVariant() : QVariant(node.connectorId);
    default:
        break;
    }
    return {};
}

QVariant SystemOutlineModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn:
        return tr("Name");
    case DetailsColumn:
        return tr("Details");
    default:
        break;
    }
    return {};
}

QModelIndex SystemOutlineModel::componentIndex(const QString &instanceName) const
{
    for (std::size_t i = 1; i < m_nodes.size(); ++i) {
        if (m_nodes[i].kind == NodeKind::Component && m_nodes[i].instanceName == instanceName)
            return indexOfNode(int(i));
    }
    return {};
}

QModelIndex SystemOutlineModel::connectorIndex(const QString &connectorId) const
{
    for (std::size_t i = 1; i < m_nodes.size(); ++i) {
        const NodeKind kind = m_nodes[i].kind;
        if ((kind == NodeKind::DataConnector || kind == NodeKind::ServiceConnector)
            && m_nodes[i].connectorId == connectorId) {
            return indexOfNode(int(i));
        }
    }
    return {};
}

void SystemOutlineModel::build()
{
    m_nodes.clear();
    m_nodes.emplace_back(); // the invisible root
    if (!m_document)
        return;
    addComponents();
    addConnectors();
}

int SystemOutlineModel::addNode(int parent, Node node)
{
    const int index = int(m_nodes.size());
    node.parent = parent;
    node.row = int(m_nodes[std::size_t(parent)].children.size());
    m_nodes[std::size_t(parent)].children.push_back(index);
    m_nodes.push_back(std::move(node));
    return index;
}

void SystemOutlineModel::addComponents()
{
    const Profile::RtsProfile &profile = m_document->profile();
    Node group(NodeKind::ComponentGroup);
    group.name = tr("Components");
    group.details = tr("%n component(s)", nullptr, int(profile.components.size()));
    const int groupNode = addNode(RootNode, group);
    for (const Profile::RtsComponent &component : profile.components) {
        Node item(NodeKind::Component);
        item.name = component.instanceName;
        item.details = component.id;
        // The id is often cut off in the details column; the tool tip shows it whole.
        item.toolTip = component.id + QLatin1Char('\n') + component.pathUri;
        item.instanceName = component.instanceName;
        const int componentNode = addNode(groupNode, item);
        for (const Profile::RtsPort &port : component.dataPorts) {
            Node portItem(NodeKind::DataPort);
            portItem.name = port.name;
            portItem.details = tr("data port");
            portItem.instanceName = component.instanceName;
            portItem.portName = port.name;
            addNode(componentNode, portItem);
        }
        for (const Profile::RtsPort &port : component.servicePorts) {
            Node portItem(NodeKind::ServicePort);
            portItem.name = port.name;
            portItem.details = tr("service port");
            portItem.instanceName = component.instanceName;
            portItem.portName = port.name;
            addNode(componentNode, portItem);
        }
    }
}

void SystemOutlineModel::addConnectors()
{
    const Profile::RtsProfile &profile = m_document->profile();
    Node group(NodeKind::ConnectorGroup);
    group.name = tr("Connectors");
    const int count = int(profile.dataPortConnectors.size() + profile.servicePortConnectors.size());
    group.details = tr("%n connector(s)", nullptr, count);
    const int groupNode = addNode(RootNode, group);

    const auto addConnector
        = [&](const Profile::RtsPortConnector &connector, NodeKind kind, const QString &details) {
              Node item(kind);
              item.name = connector.name.isEmpty() ? connector.connectorId : connector.name;
              item.details = details;
              item.toolTip = tr("Connector id: %1").arg(connector.connectorId);
              item.connectorId = connector.connectorId;
              const int connectorNode = addNode(groupNode, item);
              const std::pair<NodeKind, const Profile::RtsTargetPort *> ends[] = {
                  {NodeKind::ConnectorSource, &connector.source},
                  {NodeKind::ConnectorTarget, &connector.target},
              };
              for (const auto &[endKind, end] : ends) {
                  Node endItem(endKind);
                  endItem.name = endKind == NodeKind::ConnectorSource ? tr("source") : tr("target");
                  endItem.details = endText(*end);
                  endItem.toolTip = end->componentId;
                  endItem.instanceName = end->instanceName;
                  endItem.portName = end->portName;
                  endItem.connectorId = connector.connectorId;
                  addNode(connectorNode, endItem);
              }
          };
    for (const Profile::RtsDataPortConnector &connector : profile.dataPortConnectors) {
        addConnector(
            connector, NodeKind::DataConnector,
            tr("data, %1")
                .arg(connector.dataType.isEmpty() ? tr("no data type") : connector.dataType));
    }
    for (const Profile::RtsServicePortConnector &connector : profile.servicePortConnectors)
        addConnector(connector, NodeKind::ServiceConnector, tr("service"));
}

int SystemOutlineModel::nodeOf(const QModelIndex &index) const
{
    if (!index.isValid())
        return RootNode;
    if (index.model() != this || index.internalId() >= m_nodes.size())
        return -1;
    return int(index.internalId());
}

QModelIndex SystemOutlineModel::indexOfNode(int node, int column) const
{
    if (node <= RootNode || std::size_t(node) >= m_nodes.size())
        return {};
    return createIndex(m_nodes[std::size_t(node)].row, column, quintptr(node));
}

QIcon SystemOutlineModel::iconFor(NodeKind kind) const
{
    switch (kind) {
    case NodeKind::ComponentGroup:
    case NodeKind::Component:
        return m_componentIcon;
    case NodeKind::DataPort:
        return m_dataPortIcon;
    case NodeKind::ServicePort:
        return m_servicePortIcon;
    case NodeKind::ConnectorGroup:
    case NodeKind::DataConnector:
    case NodeKind::ServiceConnector:
        return m_connectorIcon;
    case NodeKind::ConnectorSource:
    case NodeKind::ConnectorTarget:
        break;
    }
    return {};
}

} // namespace Studio
