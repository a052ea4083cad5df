// SPDX-License-Identifier: MIT
#include "itemcommands.h"

#include "buildercommandids.h"

namespace Builder {

InsertItemCommand::InsertItemCommand(ComponentModel *model, Part part, int index,
                                     const PartItem &item, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_part(part)
    , m_index(qBound(0, index, model->itemCount(part)))
    , m_item(item)
{
    setText(tr("Add %1").arg(partLabel(part)));
}

void InsertItemCommand::undo()
{
    if (m_model)
        m_model->removeItem(m_part, m_index);
}

void InsertItemCommand::redo()
{
    if (m_model)
        m_model->insertItem(m_part, m_index, m_item);
}

RemoveItemCommand::RemoveItemCommand(ComponentModel *model, Part part, int index,
                                     QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_part(part)
    , m_index(index)
    , m_item(model->item(part, index))
{
    setText(tr("Remove %1 %2").arg(partLabel(part), model->itemName(part, index)));
}

void RemoveItemCommand::undo()
{
    if (m_model)
        m_model->insertItem(m_part, m_index, m_item);
}

void RemoveItemCommand::redo()
{
    if (m_model)
        m_model->removeItem(m_part, m_index);
}

MoveItemCommand::MoveItemCommand(ComponentModel *model, Part part, int from, int to,
                                 QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_part(part)
    , m_from(from)
    , m_to(to)
{
    setText(tr("Move %1 %2").arg(partLabel(part), model->itemName(part, from)));
}

void MoveItemCommand::undo()
{
    if (m_model)
        m_model->moveItem(m_part, m_to, m_from);
}

void MoveItemCommand::redo()
{
    if (m_model)
        m_model->moveItem(m_part, m_from, m_to);
}

EditItemCommand::EditItemCommand(ComponentModel *model, Part part, int index, const PartItem &item,
                                 const QString &mergeKey, const QString &text, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_part(part)
    , m_index(index)
    , m_mergeKey(mergeKey)
    , m_before(model->item(part, index))
    , m_after(item)
{
    setText(text);
}

void EditItemCommand::undo()
{
    if (m_model)
        m_model->setItem(m_part, m_index, m_before);
}

void EditItemCommand::redo()
{
    if (m_model)
        m_model->setItem(m_part, m_index, m_after);
}

int EditItemCommand::id() const
{
    return EditItemCommandId;
}

bool EditItemCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const EditItemCommand *>(other);
    if (edit->m_model != m_model || edit->m_part != m_part || edit->m_index != m_index
        || m_mergeKey.isEmpty() || edit->m_mergeKey != m_mergeKey)
        return false;
    m_after = edit->m_after;
    setObsolete(m_after == m_before);
    return true;
}

namespace {

Profile::RtcServicePort servicePort(ComponentModel *model, int portIndex)
{
    return std::get<Profile::RtcServicePort>(model->item(Part::ServicePort, portIndex));
}

Profile::RtcDataPort dataPort(ComponentModel *model, int portIndex)
{
    return std::get<Profile::RtcDataPort>(model->item(Part::DataPort, portIndex));
}

} // namespace

QUndoCommand *makeAddInterfaceCommand(ComponentModel *model, int portIndex,
                                      const Profile::RtcServiceInterface &interface)
{
    Profile::RtcServicePort port = servicePort(model, portIndex);
    port.interfaces.append(interface);
    return new EditItemCommand(
        model, Part::ServicePort, portIndex, port, QString(),
        QCoreApplication::translate("Builder::EditItemCommand", "Add interface %1 to %2")
            .arg(interface.name, port.name));
}

QUndoCommand *makeRemoveInterfaceCommand(ComponentModel *model, int portIndex, int interfaceIndex)
{
    Profile::RtcServicePort port = servicePort(model, portIndex);
    const QString name = port.interfaces.value(interfaceIndex).name;
    port.interfaces.removeAt(interfaceIndex);
    return new EditItemCommand(
        model, Part::ServicePort, portIndex, port, QString(),
        QCoreApplication::translate("Builder::EditItemCommand", "Remove interface %1 from %2")
            .arg(name, port.name));
}

QUndoCommand *makeEditInterfaceCommand(ComponentModel *model, int portIndex, int interfaceIndex,
                                       const Profile::RtcServiceInterface &interface,
                                       const QString &mergeKey)
{
    Profile::RtcServicePort port = servicePort(model, portIndex);
    port.interfaces[interfaceIndex] = interface;
    return new EditItemCommand(
        model, Part::ServicePort, portIndex, port,
        QStringLiteral("interface%1.%2").arg(interfaceIndex).arg(mergeKey),
        QCoreApplication::translate("Builder::EditItemCommand", "Change interface %1")
            .arg(interface.name));
}

QUndoCommand *makeAddEventCommand(ComponentModel *model, int portIndex,
                                  const Profile::RtcEvent &event)
{
    Profile::RtcDataPort port = dataPort(model, portIndex);
    port.events.append(event);
    return new EditItemCommand(
        model, Part::DataPort, portIndex, port, QString(),
        QCoreApplication::translate("Builder::EditItemCommand", "Add event %1 to %2")
            .arg(event.name, port.name));
}

QUndoCommand *makeRemoveEventCommand(ComponentModel *model, int portIndex, int eventIndex)
{
    Profile::RtcDataPort port = dataPort(model, portIndex);
    const QString name = port.events.value(eventIndex).name;
    port.events.removeAt(eventIndex);
    return new EditItemCommand(
        model, Part::DataPort, portIndex, port, QString(),
        QCoreApplication::translate("Builder::EditItemCommand", "Remove event %1 from %2")
            .arg(name, port.name));
}

QUndoCommand *makeEditEventCommand(ComponentModel *model, int portIndex, int eventIndex,
                                   const Profile::RtcEvent &event, const QString &mergeKey)
{
    Profile::RtcDataPort port = dataPort(model, portIndex);
    port.events[eventIndex] = event;
    return new EditItemCommand(
        model, Part::DataPort, portIndex, port,
        QStringLiteral("event%1.%2").arg(eventIndex).arg(mergeKey),
        QCoreApplication::translate("Builder::EditItemCommand", "Change event %1").arg(event.name));
}

} // namespace Builder
