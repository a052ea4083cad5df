// SPDX-License-Identifier: MIT
#pragma once

#include "instancecommands.h"

#include <QRectF>

namespace SystemEditor {

/// The composite kinds the editor creates (RtsComponent::compositeType).
QStringList compositeKinds(); ///< PeriodicECShared, PeriodicStateShared, Grouping

/**
 * A composite component record and the RTC profile describing its exported ports: type
 * `compositeType`, members as participants, one port per exported member port (named as the
 * member's port, e.g. `ConsoleIn0.out`, with the member's kind and data type), placed around
 * its members: around `membersBounds` when given (the canvas knows the drawn sizes), else around
 * the members' saved positions and sizes.
 */
std::pair<Profile::RtsComponent, Profile::RtcProfile>
makeComposite(const SystemModel &model, const QString &instanceName, const QString &compositeType,
              const QStringList &members, const QList<ConnectorEnd> &exportedPorts,
              const QRectF &membersBounds = {});

/// Groups components into a new composite component (members stay in the system).
class CreateCompositeCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(CreateCompositeCommand)

public:
    /// An empty `instanceName` becomes the first free `<compositeType>N`.
    CreateCompositeCommand(SystemModel *model, const QString &compositeType,
                           const QStringList &members, const QList<ConnectorEnd> &exportedPorts,
                           const QString &instanceName = {}, QUndoCommand *parent = nullptr,
                           const QRectF &membersBounds = {});

    QString instanceName() const { return m_name; }

private:
    QString m_name;
};

/// Dissolves a composite: removes the composite component and its connectors; members stay.
class DecomposeCommand : public RemoveComponentsCommand
{
    Q_DECLARE_TR_FUNCTIONS(DecomposeCommand)

public:
    DecomposeCommand(SystemModel *model, const QString &compositeName,
                     QUndoCommand *parent = nullptr);
};

} // namespace SystemEditor
