// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QAbstractTableModel>

#include <vector>

namespace SystemEditor {

/**
 * The execution contexts of one live component as the worker last read them, owned ones first
 * (rtshell's indexing): index, owned/participating, kind, running, rate, the component's state in
 * the context, the owning component and the other participants.
 */
class ExecutionContextModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        IndexColumn,
        RelationColumn,
        KindColumn,
        RunningColumn,
        RateColumn,
        StateColumn,
        OwnerColumn,
        ParticipantsColumn
    };

    using QAbstractTableModel::QAbstractTableModel;

    void setContexts(const std::vector<Corba::ExecutionContextInfo> &contexts);
    const std::vector<Corba::ExecutionContextInfo> &contexts() const { return m_contexts; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    /// How a member is shown: its instance name, or that it did not answer.
    static QString memberName(const Corba::ContextMember &member);

private:
    std::vector<Corba::ExecutionContextInfo> m_contexts;
};

} // namespace SystemEditor
