// SPDX-License-Identifier: MIT
#include "serviceporttreemodel.h"

#include "componentrules.h"

#include <QColor>

namespace Builder {

namespace {

// internalId: 0 for a port row, port + 1 for an interface row of that port.
quintptr portId(int port)
{
    return quintptr(port) + 1;
}

} // namespace

ServicePortTreeModel::ServicePortTreeModel(ComponentModel *model, QObject *parent)
    : QAbstractItemModel(parent)
    , m_model(model)
{
    rememberShape();
    // Structural changes reset the tree: interfaces are edited inside a port's value, so a
    // change does not say which interface came or went.
    const auto reset = [this](Part part) {
        if (part != Part::ServicePort)
            return;
        beginResetModel();
        rememberShape();
        endResetModel();
    };
    connect(model, &ComponentModel::itemInserted, this, reset);
    connect(model, &ComponentModel::itemRemoved, this, reset);
    connect(model, &ComponentModel::itemMoved, this, reset);
    connect(model, &ComponentModel::itemChanged, this,
            [this](Part part, int index) { onItemChanged(part, index); });
    connect(model, &ComponentModel::profileAboutToBeReset, this, [this] { beginResetModel(); });
    connect(model, &ComponentModel::profileReset, this, [this] {
        rememberShape();
        endResetModel();
    });
    // Duplicates and variable names reach across parts: refresh the marks of every row.
    connect(model, &ComponentModel::changed, this, [this] {
        for (int p = 0; p < m_interfaceCounts.size(); ++p) {
            emit dataChanged(index(p, 0), index(p, ColumnCount - 1));
            if (m_interfaceCounts.at(p) > 0)
                emit dataChanged(index(0, 0, index(p, 0)),
                                 index(m_interfaceCounts.at(p) - 1, ColumnCount - 1, index(p, 0)));
        }
    });
}

void ServicePortTreeModel::rememberShape()
{
    m_interfaceCounts.clear();
    if (!m_model)
        return;
    for (const Profile::RtcServicePort &port : m_model->profile().servicePorts)
        m_interfaceCounts << int(port.interfaces.size());
}

void ServicePortTreeModel::onItemChanged(Part part, int index)
{
    if (part != Part::ServicePort)
        return;
    if (m_model->profile().servicePorts.at(index).interfaces.size()
        != m_interfaceCounts.value(index)) {
        beginResetModel();
        rememberShape();
        endResetModel();
        return;
    }
    emit dataChanged(this->index(index, 0), this->index(index, ColumnCount - 1));
}

QModelIndex ServicePortTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (!hasIndex(row, column, parent))
        return {};
    if (!parent.isValid())
        return createIndex(row, column, quintptr(0));
    return createIndex(row, column, portId(parent.row()));
}

QModelIndex ServicePortTreeModel::parent(const QModelIndex &child) const
{
    if (!child.isValid() || child.internalId() == 0)
        return {};
    return createIndex(int(child.internalId() - 1), 0, quintptr(0));
}

int ServicePortTreeModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return int(m_interfaceCounts.size());
    if (parent.internalId() != 0 || parent.column() != 0)
        return 0;
    return m_interfaceCounts.value(parent.row());
}

int ServicePortTreeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

QVariant ServicePortTreeModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || !m_model)
        return {};
    const Profile::RtcProfile &profile = m_model->profile();
    const int port = portOf(index);
    const int interface = interfaceOf(index);
    FieldProblems problems = interface < 0 ? itemProblems(profile, Part::ServicePort, port)
                                           : interfaceProblems(profile, port, interface);
    // All problems of the row, the name's first, in a stable order.
    QStringList keys = problems.keys();
    std::sort(keys.begin(), keys.end(), [](const QString &a, const QString &b) {
        return std::make_pair(a != QLatin1String("name"), a)
            < std::make_pair(b != QLatin1String("name"), b);
    });
    QStringList messages;
    for (const QString &key : std::as_const(keys))
        messages << problems.value(key);
    const QString problem = messages.join(QLatin1Char('\n'));
    if (role == Qt::BackgroundRole)
        return problem.isEmpty() ? QVariant() : QVariant(QColor(255, 228, 225));
    if (role == Qt::ToolTipRole)
        return problem.isEmpty() ? QVariant() : QVariant(problem);
    if (role != Qt::DisplayRole)
        return {};
    const Profile::RtcServicePort &p = profile.servicePorts.at(port);
    if (interface < 0)
        return index.column() == NameColumn ? p.name : p.position;
    const Profile::RtcServiceInterface &i = p.interfaces.at(interface);
    return index.column() == NameColumn ? i.name : QStringLiteral("%1 %2").arg(i.direction, i.type);
}

QVariant ServicePortTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole || orientation != Qt::Horizontal)
        return {};
    return section == NameColumn ? tr("Port / interface") : tr("Position / direction and type");
}

int ServicePortTreeModel::portOf(const QModelIndex &index)
{
    if (!index.isValid())
        return -1;
    return index.internalId() == 0 ? index.row() : int(index.internalId() - 1);
}

int ServicePortTreeModel::interfaceOf(const QModelIndex &index)
{
    return index.isValid() && index.internalId() != 0 ? index.row() : -1;
}

QModelIndex ServicePortTreeModel::indexFor(int port, int interface) const
{
    const QModelIndex portIndex = index(port, 0);
    return interface < 0 ? portIndex : index(interface, 0, portIndex);
}

} // namespace Builder
