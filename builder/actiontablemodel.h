// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QAbstractTableModel>
#include <QPointer>

class QUndoStack;

namespace Builder {

/**
 * The twelve callbacks RTC Builder edits (onInitialize … onRateChanged; onAction and
 * onModeChanged stay as the file has them) as a table: the callback with an ON/OFF check box and
 * its description. Checking pushes a SetActionCommand; onInitialize is always on.
 */
class ActionTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { CallbackColumn, DescriptionColumn, ColumnCount };

    ActionTableModel(ComponentModel *model, QUndoStack *undoStack, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    /// The action of a row.
    static Profile::RtcAction action(int row);
    /// The callbacks the page edits, in RTC Builder's order.
    static const QList<Profile::RtcAction> &editedActions();

private:
    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
};

/// The action's status with `implemented` set (a missing entry is created).
Profile::RtcActionStatus withImplemented(const std::optional<Profile::RtcActionStatus> &status,
                                         bool on);

} // namespace Builder
