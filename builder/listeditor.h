// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QWidget>

#include <functional>

class QTableView;
class QPushButton;
class QUndoStack;

namespace Builder {

class ItemTableModel;

/**
 * A titled table of one part's elements with Add, Remove, Up and Down buttons; each button
 * pushes the matching command. Used for InPorts, OutPorts and configuration parameters.
 */
class ListEditor : public QWidget
{
    Q_OBJECT

public:
    /// Makes the element the Add button inserts (given the names in use).
    using Factory = std::function<PartItem()>;

    ListEditor(ComponentModel *model, QUndoStack *undoStack, ItemTableModel *table,
               const QString &title, Factory factory, QWidget *parent = nullptr);

    QTableView *view() const { return m_view; }
    ItemTableModel *table() const { return m_table; }
    /// The element of the current row (position in the part's list); -1 when none.
    int currentItem() const;
    /// Makes the row of an element current.
    void selectItem(int itemIndex);

    void addItem();
    void removeCurrent();
    void moveCurrent(int delta);

signals:
    /// The current element changed (position in the part's list, or -1).
    void currentItemChanged(int itemIndex);

private:
    void updateButtons();

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    ItemTableModel *m_table;
    Factory m_factory;
    QTableView *m_view;
    QPushButton *m_remove;
    QPushButton *m_up;
    QPushButton *m_down;
};

/// `base`, or `base` followed by the first number that makes it unused in `used`.
QString uniqueName(const QString &base, const QStringList &used);
/// The names of all data and service ports.
QStringList portNames(const Profile::RtcProfile &profile);

} // namespace Builder
