// SPDX-License-Identifier: MIT
#include "actiontablemodel.h"

#include "componentcommands.h"

#include <QUndoStack>

namespace Builder {

using Profile::RtcAction;

ActionTableModel::ActionTableModel(ComponentModel *model, QUndoStack *undoStack, QObject *parent)
    : QAbstractTableModel(parent)
    , m_model(model)
    , m_undoStack(undoStack)
{
    connect(model, &ComponentModel::actionChanged, this, [this](RtcAction action) {
        const int row = int(editedActions().indexOf(action));
        if (row >= 0)
            emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    });
    connect(model, &ComponentModel::profileAboutToBeReset, this, [this] { beginResetModel(); });
    connect(model, &ComponentModel::profileReset, this, [this] { endResetModel(); });
}

const QList<RtcAction> &ActionTableModel::editedActions()
{
    static const QList<RtcAction> actions {
        RtcAction::OnInitialize, RtcAction::OnFinalize,    RtcAction::OnStartup,
        RtcAction::OnShutdown,   RtcAction::OnActivated,   RtcAction::OnDeactivated,
        RtcAction::OnAborting,   RtcAction::OnError,       RtcAction::OnReset,
        RtcAction::OnExecute,    RtcAction::OnStateUpdate, RtcAction::OnRateChanged,
    };
    return actions;
}

RtcAction ActionTableModel::action(int row)
{
    return editedActions().at(row);
}

int ActionTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(editedActions().size());
}

int ActionTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ActionTableModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || !m_model)
        return {};
    const RtcAction action = this->action(index.row());
    const auto status = m_model->action(action);
    const bool on = action == RtcAction::OnInitialize || (status && status->isImplemented());
    if (index.column() == CallbackColumn) {
        if (role == Qt::DisplayRole)
            return Profile::rtcActionKey(action);
        if (role == Qt::CheckStateRole)
            return on ? Qt::Checked : Qt::Unchecked;
        if (role == Qt::ToolTipRole && action == RtcAction::OnInitialize)
            return tr("onInitialize is always implemented.");
        return {};
    }
    if (role == Qt::DisplayRole || role == Qt::EditRole)
        return status && status->doc ? status->doc->description.value_or(QString()) : QString();
    return {};
}

bool ActionTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || !m_model)
        return false;
    const RtcAction action = this->action(index.row());
    const auto status = m_model->action(action);
    if (index.column() == CallbackColumn && role == Qt::CheckStateRole) {
        const bool on = value.toInt() == Qt::Checked;
        if (action == RtcAction::OnInitialize || (status && status->isImplemented() == on))
            return false;
        m_undoStack->push(new SetActionCommand(m_model, action, withImplemented(status, on)));
        return true;
    }
    if (index.column() == DescriptionColumn && role == Qt::EditRole) {
        Profile::RtcActionStatus edited = status.value_or(Profile::RtcActionStatus());
        if (!edited.doc)
            edited.doc = Profile::RtcActionDoc();
        edited.doc->description = value.toString();
        if (status == edited)
            return false;
        m_undoStack->push(
            new SetActionCommand(m_model, action, edited, QStringLiteral("description")));
        return true;
    }
    return false;
}

Qt::ItemFlags ActionTableModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags flags = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    if (index.column() == DescriptionColumn)
        flags |= Qt::ItemIsEditable;
    else if (action(index.row()) != RtcAction::OnInitialize)
        flags |= Qt::ItemIsUserCheckable;
    return flags;
}

QVariant ActionTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole || orientation != Qt::Horizontal)
        return {};
    return section == CallbackColumn ? tr("Callback") : tr("Description");
}

Profile::RtcActionStatus withImplemented(const std::optional<Profile::RtcActionStatus> &status,
                                         bool on)
{
    Profile::RtcActionStatus result = status.value_or(Profile::RtcActionStatus());
    result.setImplemented(on);
    return result;
}

} // namespace Builder
