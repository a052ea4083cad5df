// SPDX-License-Identifier: MIT
#include "itemtablemodel.h"

#include "componentrules.h"
#include "itemcommands.h"

#include <QColor>
#include <QUndoStack>

namespace Builder {

ItemTableModel::ItemTableModel(ComponentModel *model, QUndoStack *undoStack, Part part,
                               QList<ItemField> columns, Filter filter, QObject *parent)
    : QAbstractTableModel(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_part(part)
    , m_columns(std::move(columns))
    , m_filter(std::move(filter))
{
    rebuild();
    connect(model, &ComponentModel::itemInserted, this,
            [this](Part p, int index) { onInserted(p, index); });
    connect(model, &ComponentModel::itemAboutToBeRemoved, this,
            [this](Part p, int index) { onAboutToBeRemoved(p, index); });
    connect(model, &ComponentModel::itemRemoved, this,
            [this](Part p, int index) { onRemoved(p, index); });
    connect(model, &ComponentModel::itemChanged, this,
            [this](Part p, int index) { onChanged(p, index); });
    connect(model, &ComponentModel::itemMoved, this,
            [this](Part p, int from, int to) { onMoved(p, from, to); });
    connect(model, &ComponentModel::profileAboutToBeReset, this, [this] { beginResetModel(); });
    connect(model, &ComponentModel::profileReset, this, [this] {
        rebuild();
        endResetModel();
    });
    // A rename elsewhere can create or resolve a duplicate here: refresh the problem marks.
    connect(model, &ComponentModel::changed, this, [this] {
        if (!m_rows.isEmpty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1),
                             {Qt::BackgroundRole, Qt::ToolTipRole, ProblemRole});
    });
}

int ItemTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int ItemTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_columns.size());
}

QVariant ItemTableModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || !m_model)
        return {};
    const int item = m_rows.at(index.row());
    const ItemField &field = m_columns.at(index.column());
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return field.get(m_model->item(m_part, item));
    case Qt::BackgroundRole:
    case Qt::ToolTipRole:
    case ProblemRole: {
        const QString problem = itemProblems(m_model->profile(), m_part, item).value(field.key);
        if (problem.isEmpty())
            return {};
        if (role == Qt::BackgroundRole)
            return QColor(255, 228, 225);
        return problem;
    }
    default:
        break;
    }
    return {};
}

bool ItemTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid) || !m_model)
        return false;
    const int item = m_rows.at(index.row());
    const ItemField &field = m_columns.at(index.column());
    if (field.check && !field.check(value.toString()).isEmpty())
        return false;
    PartItem edited = m_model->item(m_part, item);
    field.set(edited, value.toString());
    if (edited == m_model->item(m_part, item))
        return false;
    m_undoStack->push(new EditItemCommand(
        m_model, m_part, item, edited, field.key,
        tr("Change %1 of %2").arg(field.label.toLower(), m_model->itemName(m_part, item))));
    return true;
}

Qt::ItemFlags ItemTableModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    return Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable;
}

QVariant ItemTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole)
        return {};
    if (orientation == Qt::Vertical)
        return section + 1;
    return section >= 0 && section < m_columns.size() ? m_columns.at(section).label : QVariant();
}

int ItemTableModel::columnOf(const QString &key) const
{
    for (int i = 0; i < m_columns.size(); ++i) {
        if (m_columns.at(i).key == key)
            return i;
    }
    return -1;
}

void ItemTableModel::rebuild()
{
    m_rows.clear();
    if (!m_model)
        return;
    for (int i = 0; i < m_model->itemCount(m_part); ++i) {
        if (accepts(i))
            m_rows.append(i);
    }
}

bool ItemTableModel::accepts(int index) const
{
    return !m_filter || m_filter(m_model->item(m_part, index));
}

void ItemTableModel::shift(int from, int delta)
{
    for (int &row : m_rows) {
        if (row >= from)
            row += delta;
    }
}

void ItemTableModel::onInserted(Part part, int index)
{
    if (part != m_part)
        return;
    shift(index, 1);
    if (!accepts(index))
        return;
    const int row
        = int(std::count_if(m_rows.cbegin(), m_rows.cend(), [index](int r) { return r < index; }));
    beginInsertRows({}, row, row);
    m_rows.insert(row, index);
    endInsertRows();
}

void ItemTableModel::onAboutToBeRemoved(Part part, int index)
{
    // Views read the rows being removed while the element is still there.
    m_removingRow = part == m_part ? int(m_rows.indexOf(index)) : -1;
    if (m_removingRow >= 0)
        beginRemoveRows({}, m_removingRow, m_removingRow);
}

void ItemTableModel::onRemoved(Part part, int index)
{
    if (part != m_part)
        return;
    const int row = m_removingRow;
    m_removingRow = -1;
    if (row >= 0)
        m_rows.removeAt(row);
    shift(index + 1, -1);
    if (row >= 0)
        endRemoveRows();
}

void ItemTableModel::onChanged(Part part, int index)
{
    if (part != m_part)
        return;
    const int row = int(m_rows.indexOf(index));
    const bool shown = accepts(index);
    if (row >= 0 && shown) {
        emit dataChanged(this->index(row, 0), this->index(row, columnCount() - 1));
    } else if (row >= 0) {
        beginRemoveRows({}, row, row);
        m_rows.removeAt(row);
        endRemoveRows();
    } else if (shown) {
        const int at = int(
            std::count_if(m_rows.cbegin(), m_rows.cend(), [index](int r) { return r < index; }));
        beginInsertRows({}, at, at);
        m_rows.insert(at, index);
        endInsertRows();
    }
}

void ItemTableModel::onMoved(Part part, int from, int to)
{
    if (part != m_part)
        return;
    // A layout change, not a reset, so that selections and the current row follow the element.
    const auto moved = [from, to](int position) {
        if (position == from)
            return to;
        if (from < position && position <= to)
            return position - 1;
        if (to <= position && position < from)
            return position + 1;
        return position;
    };
    emit layoutAboutToBeChanged();
    const QModelIndexList before = persistentIndexList();
    QList<int> items;
    for (const QModelIndex &index : before)
        items << m_rows.value(index.row(), -1);
    rebuild();
    QModelIndexList after;
    for (int i = 0; i < before.size(); ++i) {
        const int row = int(m_rows.indexOf(moved(items.at(i))));
        after << (row >= 0 ? index(row, before.at(i).column()) : QModelIndex());
    }
    changePersistentIndexList(before, after);
    emit layoutChanged();
}

} // namespace Builder
