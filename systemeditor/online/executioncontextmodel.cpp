// SPDX-License-Identifier: MIT
#include "executioncontextmodel.h"

#include "onlineicons.h"

namespace SystemEditor {

void ExecutionContextModel::setContexts(const std::vector<Corba::ExecutionContextInfo> &contexts)
{
    // Same rows: update in place so selection and editors survive a poll.
    if (contexts.size() == m_contexts.size()) {
        m_contexts = contexts;
        if (!m_contexts.empty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
        return;
    }
    beginResetModel();
    m_contexts = contexts;
    endResetModel();
}

int ExecutionContextModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_contexts.size());
}

int ExecutionContextModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ParticipantsColumn + 1;
}

QVariant ExecutionContextModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Corba::ExecutionContextInfo &ec = m_contexts[size_t(index.row())];
    if (role == Qt::DecorationRole && index.column() == StateColumn)
        return OnlineIcons::component(ec.state);
    if (role != Qt::DisplayRole)
        return {};
    switch (Column(index.column())) {
    case IndexColumn:
        return index.row();
    case RelationColumn:
        return ec.owned ? tr("owned") : tr("participating");
    case KindColumn:
        return ec.kind;
    case RunningColumn:
        return ec.running ? tr("Running") : tr("Stopped");
    case RateColumn:
        return ec.rate;
    case StateColumn:
        return OnlineIcons::stateLabel(ec.state);
    case OwnerColumn:
        return ec.owner.ior.isEmpty() ? QString() : memberName(ec.owner);
    case ParticipantsColumn: {
        QStringList names;
        for (const Corba::ContextMember &member : ec.participants)
            names.append(memberName(member));
        return names.join(QLatin1String(", "));
    }
    }
    return {};
}

QString ExecutionContextModel::memberName(const Corba::ContextMember &member)
{
    return member.name.isEmpty() ? tr("(not answering)") : member.name;
}

QVariant ExecutionContextModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    static const char *const titles[]
        = {QT_TR_NOOP("Id"),      QT_TR_NOOP("Relation"),    QT_TR_NOOP("Kind"),
           QT_TR_NOOP("Running"), QT_TR_NOOP("Rate (Hz)"),   QT_TR_NOOP("Component State"),
           QT_TR_NOOP("Owner"),   QT_TR_NOOP("Participants")};
    return section >= 0 && section <= ParticipantsColumn ? tr(titles[section]) : QVariant();
}

} // namespace SystemEditor
