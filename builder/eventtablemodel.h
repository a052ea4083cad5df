// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QAbstractTableModel>
#include <QPointer>

class QUndoStack;

namespace Builder {

/**
 * The FSM events of one EventPort as a table: name, data type, source state, target state,
 * condition and description (`rtc:Event` with its `rtcDoc:Doc`). Every edit is an undo command
 * replacing the port (makeEditEventCommand()); the table follows the component model, including
 * undo. A name that is empty or used twice in the port, and an empty source or target state, are
 * marked with a reddish background and the reason as tool tip and ProblemRole.
 */
class EventTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { Name, DataType, Source, Target, Condition, Description, ColumnCount };
    enum Role { ProblemRole = Qt::UserRole + 1 };

    EventTableModel(ComponentModel *model, QUndoStack *undoStack, QObject *parent = nullptr);

    /// The data port whose events are shown (position in the model's list); -1: none.
    void setPortIndex(int index);
    int portIndex() const { return m_portIndex; }

    /// Appends an event with a fresh name; false when no EventPort is shown.
    bool addEvent();
    /// Removes the event in `row`.
    void removeEvent(int row);
    /// The problem of a cell; empty when there is none.
    QString problem(int row, int column) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

private:
    QList<Profile::RtcEvent> events() const;
    void sync();
    void followInsert(Part part, int index);
    void followRemove(Part part, int index);
    void followMove(Part part, int from, int to);

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    int m_portIndex = -1;
    int m_rows = 0;
};

} // namespace Builder
