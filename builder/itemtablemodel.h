// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "itemcolumn.h"

#include <QAbstractTableModel>
#include <QPointer>

class QUndoStack;

namespace Builder {

/**
 * A table of one part's elements (all of them, or those a filter accepts, e.g. only InPorts).
 * Rows follow the ComponentModel's signals; editing a cell pushes an EditItemCommand. Cells with
 * a problem (componentrules.h) get a reddish background and the reason as tool tip and
 * ProblemRole.
 */
class ItemTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Role { ProblemRole = Qt::UserRole + 1 };
    using Filter = std::function<bool(const PartItem &)>;

    ItemTableModel(ComponentModel *model, QUndoStack *undoStack, Part part,
                   QList<ItemField> columns, Filter filter = {}, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    Part part() const { return m_part; }
    const ItemField &column(int column) const { return m_columns.at(column); }
    /// The column of a field key; -1 when there is none.
    int columnOf(const QString &key) const;
    /// The position in the profile's list of a row, and back (-1 when not shown).
    int itemIndex(int row) const { return m_rows.value(row, -1); }
    int rowOf(int itemIndex) const { return m_rows.indexOf(itemIndex); }

private:
    void rebuild();
    void onInserted(Part part, int index);
    void onAboutToBeRemoved(Part part, int index);
    void onRemoved(Part part, int index);
    void onChanged(Part part, int index);
    void onMoved(Part part, int from, int to);
    void shift(int from, int delta);
    bool accepts(int index) const;

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    Part m_part;
    QList<ItemField> m_columns;
    Filter m_filter;
    QList<int> m_rows; ///< positions in the profile's list, in list order
    int m_removingRow = -1; ///< the row between itemAboutToBeRemoved and itemRemoved
};

} // namespace Builder
