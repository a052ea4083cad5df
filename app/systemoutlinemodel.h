// SPDX-License-Identifier: MIT
#pragma once

#include <QAbstractItemModel>
#include <QIcon>
#include <QPointer>

#include <vector>

namespace Studio {

class RtsDocument;

/**
 * The outline of a system: a "Components" branch (each component with its data and service
 * ports) and a "Connectors" branch (each connector with its source and target end).
 *
 * Two columns: name and details. Items carry the stable ids of what they show (instance name,
 * port name, connector id) in custom roles, so that other views can find the same object.
 * Nothing edits the structure of a system yet, so the outline is built once from the document.
 */
class SystemOutlineModel : public QAbstractItemModel
{
    Q_OBJECT

public:
    enum class NodeKind {
        ComponentGroup,
        Component,
        DataPort,
        ServicePort,
        ConnectorGroup,
        DataConnector,
        ServiceConnector,
        ConnectorSource,
        ConnectorTarget,
    };
    Q_ENUM(NodeKind)

    enum Role {
        NodeKindRole = Qt::UserRole + 1, ///< NodeKind as int
        InstanceNameRole, ///< component (or connector end) instance name
        PortNameRole, ///< port name (ports and connector ends)
        ConnectorIdRole, ///< connector id (connectors and their ends)
    };

    enum Column { NameColumn, DetailsColumn, ColumnCount };

    explicit SystemOutlineModel(RtsDocument *document, QObject *parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    /// The item of the component with this instance name (column 0), or invalid.
    QModelIndex componentIndex(const QString &instanceName) const;
    /// The item of the connector with this id (column 0), or invalid.
    QModelIndex connectorIndex(const QString &connectorId) const;

private:
    struct Node
    {
        explicit Node(NodeKind nodeKind = NodeKind::ComponentGroup)
            : kind(nodeKind)
        { }

        NodeKind kind;
        int parent = -1;
        int row = 0;
        std::vector<int> children;
        QString name;
        QString details;
        QString toolTip;
        QString instanceName;
        QString portName;
        QString connectorId;
    };

    void build();
    int addNode(int parent, Node node);
    void addComponents();
    void addConnectors();
    int nodeOf(const QModelIndex &index) const;
    QModelIndex indexOfNode(int node, int column = 0) const;
    QIcon iconFor(NodeKind kind) const;

    QPointer<RtsDocument> m_document;
    std::vector<Node> m_nodes; ///< m_nodes[0] is the invisible root
    QIcon m_componentIcon;
    QIcon m_dataPortIcon;
    QIcon m_servicePortIcon;
    QIcon m_connectorIcon;
};

} // namespace Studio
