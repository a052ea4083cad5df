// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QCoreApplication>
#include <QHash>
#include <QPointer>
#include <QUndoCommand>

namespace SystemEditor {

/**
 * Adds a component instance. When the record's instance name is empty or taken, the command
 * gives it the first free `<TypeName>0`, `<TypeName>1`, … (see instanceName()); its `<old>.`
 * port names follow.
 */
class AddComponentCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(AddComponentCommand)

public:
    AddComponentCommand(SystemModel *model, const Profile::RtsComponent &component,
                        const std::optional<Profile::RtcProfile> &rtc = std::nullopt,
                        QUndoCommand *parent = nullptr);

    QString instanceName() const { return m_component.instanceName; }
    void redo() override;
    void undo() override;

private:
    QPointer<SystemModel> m_model;
    Profile::RtsComponent m_component;
    std::optional<Profile::RtcProfile> m_rtc;
};

/// Renames a component record and its `<old>.` ports without touching a model.
Profile::RtsComponent renamedComponent(Profile::RtsComponent component, const QString &newName);

/**
 * Removes components as one step: first every connector touching them (children
 * DisconnectCommand), then the components, restored in their places on undo.
 */
class RemoveComponentsCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RemoveComponentsCommand)

public:
    RemoveComponentsCommand(SystemModel *model, const QStringList &instanceNames,
                            QUndoCommand *parent = nullptr);
};

/**
 * Moves components to new positions (Location x/y). Successive moves of the same set of
 * components merge into one step (dragging, keyboard nudges); `text` names other uses (align,
 * auto-layout), which never merge.
 */
class MoveComponentsCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(MoveComponentsCommand)

public:
    MoveComponentsCommand(SystemModel *model, const QHash<QString, QPointF> &positions,
                          const QString &text = {}, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<SystemModel> m_model;
    QHash<QString, std::optional<Profile::RtsLocation>> m_before;
    QHash<QString, QPointF> m_after;
    bool m_mergeable = true;
};

/// How AlignComponents lines components up.
enum class Alignment { Left, Right, Top, Bottom, HorizontalCenter, VerticalCenter };

/// New positions that align `instanceNames` (on the first one's edge or centre).
QHash<QString, QPointF> alignedPositions(const SystemModel &model,
                                         const QStringList &instanceNames, Alignment alignment);
/// A MoveComponentsCommand that aligns; null when fewer than two components are given.
MoveComponentsCommand *alignComponentsCommand(SystemModel *model,
                                              const QStringList &instanceNames,
                                              Alignment alignment);

/// Resizes a component (a negative width/height returns to the default size); merges.
class ResizeComponentCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(ResizeComponentCommand)

public:
    ResizeComponentCommand(SystemModel *model, const QString &instanceName, const QSizeF &size,
                           QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<SystemModel> m_model;
    QString m_name;
    std::optional<Profile::RtsLocation> m_before;
    QSizeF m_after;
};

/// Renames a component instance; connectors and references follow (SystemModel::renameComponent).
class RenameComponentCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RenameComponentCommand)

public:
    RenameComponentCommand(SystemModel *model, const QString &oldName, const QString &newName,
                           QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    QPointer<SystemModel> m_model;
    QString m_old;
    QString m_new;
    bool m_applied = false; ///< a refused rename (name taken) must not be "undone"
    bool m_topLevel = true; ///< only a top-level command may be dropped by the stack
};

/// Turns a component (Location direction).
class SetDirectionCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetDirectionCommand)

public:
    SetDirectionCommand(SystemModel *model, const QString &instanceName, Direction direction,
                        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    QPointer<SystemModel> m_model;
    QString m_name;
    std::optional<Profile::RtsLocation> m_before;
    Direction m_after;
};

/// Replaces a component's configuration sets and active set.
class SetConfigurationSetsCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetConfigurationSetsCommand)

public:
    SetConfigurationSetsCommand(SystemModel *model, const QString &instanceName,
                                const QList<Profile::RtsConfigurationSet> &sets,
                                const std::optional<QString> &activeSet,
                                QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    QPointer<SystemModel> m_model;
    QString m_name;
    QList<Profile::RtsConfigurationSet> m_beforeSets, m_afterSets;
    std::optional<QString> m_beforeActive, m_afterActive;
};

} // namespace SystemEditor
