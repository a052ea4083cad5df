// SPDX-License-Identifier: MIT
#pragma once

#include "document.h"

#include <QPointer>

namespace SystemEditor {
class OnlineDiagram;
class OnlineSession;
} // namespace SystemEditor

namespace Studio {

/**
 * An online diagram open as a System Editor tab: live components drawn by the System Editor
 * canvas (SystemEditor::OnlineDiagram is its editor). It is never modified; saving it writes the
 * RTS profile of the live components with their positions on the diagram, asynchronously
 * (saveLive(), liveSaved()), because reading the live system takes remote calls.
 */
class OnlineDocument : public Document
{
    Q_OBJECT

public:
    explicit OnlineDocument(SystemEditor::OnlineSession *session, QObject *parent = nullptr);

    Profile::ProfileKind kind() const override { return Profile::ProfileKind::Rts; }
    SystemEditor::OnlineSession *session() const { return m_session; }

    /// The diagram widget showing this document (set when its tab is created).
    SystemEditor::OnlineDiagram *diagram() const;
    void setDiagram(SystemEditor::OnlineDiagram *diagram);

    /// What the diagram draws (components as read from their profiles, live connectors).
    QByteArray serialize(Profile::FileFormat format) const override;

    /// Starts saving the live system to `path`; liveSaved() follows. False without a diagram.
    bool saveLive(const QString &path);

signals:
    /// saveLive() finished; `error` is empty when the file was written.
    void liveSaved(const QString &path, const QString &error, const QStringList &warnings);

private:
    SystemEditor::OnlineSession *m_session;
    QPointer<QObject> m_diagram; ///< the OnlineDiagram; its tab may close first
};

} // namespace Studio
