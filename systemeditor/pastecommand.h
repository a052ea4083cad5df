// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QCoreApplication>
#include <QUndoCommand>

namespace SystemEditor {

/// Copied components: their records, RTC profiles and the connectors among them.
struct ComponentClipboard
{
    QList<Profile::RtsComponent> components;
    QHash<QString, Profile::RtcProfile> rtcProfiles; ///< by the copied instance names
    QList<Profile::RtsDataPortConnector> dataConnectors; ///< both ends among `components`
    QList<Profile::RtsServicePortConnector> serviceConnectors;

    /// Copies the named components (unknown names are skipped) and their inner connectors.
    static ComponentClipboard copy(const SystemModel &model, const QStringList &instanceNames);
    bool isEmpty() const { return components.isEmpty(); }
};

/**
 * Pastes copied components as one step: each gets a new unique instance name (`<Type>N`) and
 * its position moved by `offset`; connectors between copied components are kept, with new ids
 * and their ends renamed. Connectors to components that were not copied are not pasted.
 */
class PasteComponentsCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(PasteComponentsCommand)

public:
    PasteComponentsCommand(SystemModel *model, const ComponentClipboard &clipboard,
                           const QPointF &offset = QPointF(20, 20),
                           QUndoCommand *parent = nullptr);

    /// The instance names the pasted components get, in clipboard order.
    QStringList pastedNames() const { return m_names; }

private:
    QStringList m_names;
};

} // namespace SystemEditor
