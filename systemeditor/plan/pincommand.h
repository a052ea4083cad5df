// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

#include <optional>

namespace SystemEditor {

/**
 * Pins a component to a node, or frees it: the component property `deploy.pin` of the RTS
 * profile (Planner::Key::Pin), which the planner reads and saving keeps. An empty node removes
 * the property.
 */
class PinComponentCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(PinComponentCommand)

public:
    PinComponentCommand(SystemModel *model, const QString &instanceName, const QString &node,
                        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    void apply(const std::optional<QString> &pin);

    QPointer<SystemModel> m_model;
    QString m_instance;
    std::optional<QString> m_before;
    std::optional<QString> m_after;
};

/// The node @p instanceName is pinned to in @p model; empty when it is free.
QString pinnedNode(const SystemModel &model, const QString &instanceName);

} // namespace SystemEditor
