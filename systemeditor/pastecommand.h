// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <optional>

class QMimeData;

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

    /// The MIME type of the copied part of a system: an RTS profile (XML) with the copied
    /// components and the connectors among them.
    static inline const QString MimeType = QStringLiteral("application/x-rtstudio-rts+xml");
    /// The MIME type of the components' RTC profiles: for each, its instance name and RTC.xml.
    static inline const QString RtcMimeType
        = QStringLiteral("application/x-rtstudio-rtc-profiles");

    /// Clipboard data: the RTS XML under MimeType and as text, the RTC profiles under
    /// RtcMimeType.
    QMimeData *toMimeData() const;
    /// Whether `mime` carries copied components (it may still be malformed).
    static bool canRead(const QMimeData *mime);
    /**
     * Reads what toMimeData() wrote, from this or another window or process. Nothing, with a
     * message in `error`, when the data is not a readable RTS profile with components.
     */
    static std::optional<ComponentClipboard> fromMimeData(const QMimeData *mime, QString *error);
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
