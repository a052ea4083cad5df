// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

namespace Builder {

/// Adds a data port, service port or configuration parameter at a position.
class InsertItemCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(InsertItemCommand)

public:
    InsertItemCommand(ComponentModel *model, Part part, int index, const PartItem &item,
                      QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;

private:
    QPointer<ComponentModel> m_model;
    Part m_part;
    int m_index;
    PartItem m_item;
};

/// Removes an element; undo puts the same value back at the same position.
class RemoveItemCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RemoveItemCommand)

public:
    RemoveItemCommand(ComponentModel *model, Part part, int index, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;

private:
    QPointer<ComponentModel> m_model;
    Part m_part;
    int m_index;
    PartItem m_item;
};

/// Moves an element within its list (Up/Down buttons).
class MoveItemCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(MoveItemCommand)

public:
    MoveItemCommand(ComponentModel *model, Part part, int from, int to,
                    QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;

private:
    QPointer<ComponentModel> m_model;
    Part m_part;
    int m_from;
    int m_to;
};

/**
 * Replaces an element by an edited value: a field, a rename, a constraint, an interface added to
 * or removed from a service port. `mergeKey` names the field being typed into ("name", "type" …):
 * consecutive edits of the same element and key merge into one step; an empty key never merges.
 */
class EditItemCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(EditItemCommand)

public:
    EditItemCommand(ComponentModel *model, Part part, int index, const PartItem &item,
                    const QString &mergeKey, const QString &text, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<ComponentModel> m_model;
    Part m_part;
    int m_index;
    QString m_mergeKey;
    PartItem m_before;
    PartItem m_after;
};

/// A command that adds `interface` to the service port at `portIndex`.
QUndoCommand *makeAddInterfaceCommand(ComponentModel *model, int portIndex,
                                      const Profile::RtcServiceInterface &interface);
/// A command that removes interface `interfaceIndex` of the service port at `portIndex`.
QUndoCommand *makeRemoveInterfaceCommand(ComponentModel *model, int portIndex, int interfaceIndex);
/// A command that replaces interface `interfaceIndex` of the service port at `portIndex`.
QUndoCommand *makeEditInterfaceCommand(ComponentModel *model, int portIndex, int interfaceIndex,
                                       const Profile::RtcServiceInterface &interface,
                                       const QString &mergeKey);

/// A command that appends `event` to the events of the EventPort at `portIndex`.
QUndoCommand *makeAddEventCommand(ComponentModel *model, int portIndex,
                                  const Profile::RtcEvent &event);
/// A command that removes event `eventIndex` of the EventPort at `portIndex`.
QUndoCommand *makeRemoveEventCommand(ComponentModel *model, int portIndex, int eventIndex);
/// A command that replaces event `eventIndex` of the EventPort at `portIndex`; consecutive edits
/// of the same event and `mergeKey` merge.
QUndoCommand *makeEditEventCommand(ComponentModel *model, int portIndex, int eventIndex,
                                   const Profile::RtcEvent &event, const QString &mergeKey);

} // namespace Builder
