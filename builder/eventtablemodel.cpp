// SPDX-License-Identifier: MIT
#include "eventtablemodel.h"

#include "itemcommands.h"
#include "listeditor.h"

#include <QColor>
#include <QUndoStack>

namespace Builder {

namespace {

using Profile::RtcEvent;

QString cellText(const RtcEvent &event, int column)
{
    switch (column) {
    case EventTableModel::Name:
        return event.name;
    case EventTableModel::DataType:
        return event.type.value_or(QString());
    case EventTableModel::Source:
        return event.source;
    case EventTableModel::Target:
        return event.target;
    case EventTableModel::Condition:
        return event.condition.value_or(QString());
    case EventTableModel::Description:
        return event.doc ? event.doc->description.value_or(QString()) : QString();
    default:
        break;
    }
    return {};
}

/// Stores `text`; an optional attribute that was absent stays absent when cleared.
void setOptional(std::optional<QString> &member, const QString &text)
{
    if (text.isEmpty() && !member)
        return;
    member = text;
}

void setCellText(RtcEvent &event, int column, const QString &text)
{
    switch (column) {
    case EventTableModel::Name:
        event.name = text;
        break;
    case EventTableModel::DataType:
        setOptional(event.type, text);
        break;
    case EventTableModel::Source:
        event.source = text;
        break;
    case EventTableModel::Target:
        event.target = text;
        break;
    case EventTableModel::Condition:
        setOptional(event.condition, text);
        break;
    case EventTableModel::Description:
        if (text.isEmpty() && (!event.doc || !event.doc->description))
            break;
        if (!event.doc)
            event.doc = Profile::RtcEventDoc();
        event.doc->description = text;
        break;
    default:
        break;
    }
}

const char *const MergeKeys[] = {"name", "type", "source", "target", "condition", "description"};

} // namespace

EventTableModel::EventTableModel(ComponentModel *model, QUndoStack *undoStack, QObject *parent)
    : QAbstractTableModel(parent)
    , m_model(model)
    , m_undoStack(undoStack)
{
    connect(model, &ComponentModel::changed, this, &EventTableModel::sync);
    connect(model, &ComponentModel::itemInserted, this,
            [this](Part part, int index) { followInsert(part, index); });
    connect(model, &ComponentModel::itemRemoved, this,
            [this](Part part, int index) { followRemove(part, index); });
    connect(model, &ComponentModel::itemMoved, this,
            [this](Part part, int from, int to) { followMove(part, from, to); });
    connect(model, &ComponentModel::profileReset, this, [this] { setPortIndex(-1); });
}

void EventTableModel::setPortIndex(int index)
{
    beginResetModel();
    m_portIndex = index;
    m_rows = int(events().size());
    endResetModel();
}

QList<RtcEvent> EventTableModel::events() const
{
    if (!m_model || m_portIndex < 0 || m_portIndex >= m_model->itemCount(Part::DataPort))
        return {};
    return std::get<Profile::RtcDataPort>(m_model->item(Part::DataPort, m_portIndex)).events;
}

void EventTableModel::sync()
{
    const int rows = int(events().size());
    if (rows != m_rows) {
        // Events come and go only at the end or by one; a reset keeps it simple and correct.
        beginResetModel();
        m_rows = rows;
        endResetModel();
    } else if (rows > 0) {
        emit dataChanged(index(0, 0), index(rows - 1, ColumnCount - 1));
    }
}

void EventTableModel::followInsert(Part part, int index)
{
    if (part == Part::DataPort && m_portIndex >= 0 && index <= m_portIndex)
        ++m_portIndex;
}

void EventTableModel::followRemove(Part part, int index)
{
    if (part != Part::DataPort || m_portIndex < 0)
        return;
    if (index == m_portIndex)
        setPortIndex(-1);
    else if (index < m_portIndex)
        --m_portIndex;
}

void EventTableModel::followMove(Part part, int from, int to)
{
    if (part != Part::DataPort || m_portIndex < 0)
        return;
    if (from == m_portIndex)
        m_portIndex = to;
    else if (from < m_portIndex && to >= m_portIndex)
        --m_portIndex;
    else if (from > m_portIndex && to <= m_portIndex)
        ++m_portIndex;
}

bool EventTableModel::addEvent()
{
    if (!m_model || m_portIndex < 0)
        return false;
    QStringList used;
    for (const RtcEvent &event : events())
        used << event.name;
    RtcEvent event;
    event.name = uniqueName(QStringLiteral("event"), used);
    m_undoStack->push(makeAddEventCommand(m_model, m_portIndex, event));
    return true;
}

void EventTableModel::removeEvent(int row)
{
    if (m_model && row >= 0 && row < m_rows)
        m_undoStack->push(makeRemoveEventCommand(m_model, m_portIndex, row));
}

QString EventTableModel::problem(int row, int column) const
{
    const QList<RtcEvent> all = events();
    if (row < 0 || row >= all.size())
        return {};
    const RtcEvent &event = all.at(row);
    if (column == Name) {
        if (event.name.trimmed().isEmpty())
            return tr("An event needs a name.");
        for (int i = 0; i < all.size(); ++i) {
            if (i != row && all.at(i).name == event.name)
                return tr("The event name '%1' is already used by event #%2.")
                    .arg(event.name)
                    .arg(i + 1);
        }
    }
    if (column == Source && event.source.trimmed().isEmpty())
        return tr("An event needs the state it leaves.");
    if (column == Target && event.target.trimmed().isEmpty())
        return tr("An event needs the state it enters.");
    return {};
}

int EventTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_rows;
}

int EventTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant EventTableModel::data(const QModelIndex &index, int role) const
{
    const QList<RtcEvent> all = events();
    if (!index.isValid() || index.row() >= all.size())
        return {};
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return cellText(all.at(index.row()), index.column());
    case Qt::ToolTipRole:
    case ProblemRole: {
        const QString text = problem(index.row(), index.column());
        return text.isEmpty() ? QVariant() : QVariant(text);
    }
    case Qt::BackgroundRole:
        return problem(index.row(), index.column()).isEmpty() ? QVariant()
                                                              : QVariant(QColor(255, 228, 225));
    default:
        break;
    }
    return {};
}

QVariant EventTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    const QStringList titles {tr("Name"),         tr("Data type"), tr("Source state"),
                              tr("Target state"), tr("Condition"), tr("Description")};
    return titles.value(section);
}

Qt::ItemFlags EventTableModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return QAbstractTableModel::flags(index);
    return QAbstractTableModel::flags(index) | Qt::ItemIsEditable;
}

bool EventTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!m_model || role != Qt::EditRole || !index.isValid() || index.row() >= m_rows)
        return false;
    RtcEvent event = events().at(index.row());
    setCellText(event, index.column(), value.toString());
    if (event == events().at(index.row()))
        return false;
    m_undoStack->push(makeEditEventCommand(m_model, m_portIndex, index.row(), event,
                                           QLatin1String(MergeKeys[index.column()])));
    return true;
}

} // namespace Builder
