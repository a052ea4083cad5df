// SPDX-License-Identifier: MIT
#pragma once

#include "componentappearance.h"
#include "connectionrules.h"
#include "connectorsettings.h"
#include "serviceconnectorsettings.h"
#include "systemmodel.h"

#include <QGraphicsScene>
#include <QHash>
#include <QPointer>
#include <QUndoStack>

class QUndoCommand;

namespace SystemEditor {

enum class Alignment; // instancecommands.h
class ComponentItem;
class ConnectorItem;
class PortItem;

/**
 * The canvas of one RT system. It keeps an id → item map (components by instance name,
 * connectors by connector id) that follows the SystemModel's signals; it never changes the
 * model itself. What the user does on it (moving, resizing, bending connectors, deleting,
 * pasting, renaming, turning, aligning, connecting) becomes one of the model's undo commands on
 * the undo stack.
 *
 * Dragging from a port to another port connects them: while dragging, the ports that may be
 * connected are highlighted and the others dimmed; dropping on a legal port emits
 * connectRequested() (the view asks the connector dialog), dropping on an illegal one emits
 * connectionRefused() with the reason.
 */
class SystemScene : public QGraphicsScene
{
    Q_OBJECT

public:
    /// `undoStack` may be null for a read-only scene (export).
    SystemScene(SystemModel *model, QUndoStack *undoStack, QObject *parent = nullptr);
    ~SystemScene() override;

    SystemModel *model() const { return m_model; }
    QUndoStack *undoStack() const { return m_undoStack; }

    ComponentItem *componentItem(const QString &instanceName) const;
    ConnectorItem *connectorItem(const QString &connectorId) const;
    PortItem *portItem(const ConnectorEnd &end) const;
    int componentItemCount() const { return int(m_components.size()); }
    /// Fills a component's body with @p colour (an online diagram's state colours); it stays
    /// through every redraw from the model (a move, a connection, undo) until set again.
    void setBodyColor(const QString &instanceName, const QColor &colour);
    int connectorItemCount() const { return int(m_connectors.size()); }

    /// Instance names / connector ids of the selected items, in model order.
    QStringList selectedComponents() const;
    QStringList selectedConnectors() const;
    void selectComponents(const QStringList &instanceNames);

    void setGridVisible(bool visible);
    bool isGridVisible() const { return m_gridVisible; }
    void setSnapToGrid(bool snap);
    bool snapsToGrid() const { return m_snapToGrid; }
    static constexpr qreal GridSize = 20;
    /// The area the diagram covers, with a margin.
    QRectF diagramRect() const;

    // ---- edits, each one step on the undo stack --------------------------------------------

    /// Deletes the selected components (with their connectors) and connectors.
    void deleteSelection();
    /// Copies the selected components and the connectors between them to the system clipboard
    /// (ComponentClipboard::toMimeData()), so that they can be pasted into another system, in
    /// this or another window.
    void copySelection();
    /// Pastes the clipboard's components, offset further on each paste, renamed where taken;
    /// false with a statusMessage() when the clipboard holds nothing readable.
    bool paste();
    static bool canPaste();
    /**
     * Groups the selected components into a new composite component of `compositeType`
     * (PeriodicECShared, PeriodicStateShared, Grouping) exporting `exportedPorts` of its
     * members; one undo step. Returns the composite's instance name, empty when nothing is
     * selected.
     */
    QString groupSelection(const QString &compositeType, const QList<ConnectorEnd> &exportedPorts);
    /// The selected composite components, in model order.
    QStringList selectedComposites() const;
    /// Dissolves the selected composites (their members stay); false when none is selected.
    bool decomposeSelection();
    void setDirectionOfSelection(Direction direction);
    void alignSelection(Alignment alignment);
    /// Renames an instance; false (and connectionRefused-like message) when the name is taken.
    bool renameComponent(const QString &oldName, const QString &newName);
    /// Adds an instance of `rtc` at `position` (named `<type>N`); its name, or empty.
    QString addComponent(const Profile::RtcProfile &rtc, const QString &pathUri,
                         const QPointF &position);
    /// Adds the data connector `check` describes with `settings`.
    void connectPorts(const ConnectionCheck &check, const ConnectorSettings &settings);
    /// Adds a service connector between the ends `check` describes.
    void connectServicePorts(const ConnectionCheck &check,
                             const ServiceConnectorSettings &settings);
    /// Applies dialog settings to an existing data connector.
    void editConnector(const QString &connectorId, const ConnectorSettings &settings);
    /// Edits a service connector's name and interface mapping (one undo step).
    void editServiceConnector(const QString &connectorId,
                              const ServiceConnectorSettings &settings);

    /// The reason the last connect attempt was refused (empty after a legal one).
    QString lastRefusal() const { return m_lastRefusal; }
    /// True while the user drags a new connector.
    bool isConnecting() const { return m_dragSource != nullptr; }

signals:
    /// A drop on a legal port: the view asks for the connector's settings.
    void connectRequested(const SystemEditor::ConnectionCheck &check);
    /// The user dropped a connector on a port it cannot connect to.
    void connectionRefused(const QString &reason);
    /// Double-click on a connector.
    void connectorEditRequested(const QString &connectorId);
    /// Double-click on a component.
    void componentActivated(const QString &instanceName);
    /// A short message for the status bar.
    void statusMessage(const QString &message);

protected:
    void drawBackground(QPainter *painter, const QRectF &rect) override;
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event) override;

private:
    void rebuild();
    void addComponentItem(const QString &instanceName);
    void removeComponentItem(const QString &instanceName);
    void refreshComponent(const QString &instanceName);
    /// The model's appearance of a component with the body colour set for it.
    ComponentAppearance appearanceOf(const QString &instanceName) const;
    void renameComponentItem(const QString &oldName, const QString &newName);
    void addConnectorItem(const QString &connectorId);
    void removeConnectorItem(const QString &connectorId);
    void refreshConnector(const QString &connectorId);
    void connectorRemoved(const QString &connectorId);
    void reattachConnectors(const QString &instanceName);
    void rerouteConnectors(const QString &instanceName);

    PortItem *portAt(const QPointF &scenePos) const;
    void startConnecting(PortItem *source, const QPointF &scenePos);
    void updateConnecting(const QPointF &scenePos);
    void finishConnecting(const QPointF &scenePos);
    void clearHighlights();
    void commitMoves();
    void push(QUndoCommand *command);

    QPointer<SystemModel> m_model;
    QPointer<QUndoStack> m_undoStack;
    QHash<QString, ComponentItem *> m_components;
    QHash<QString, QColor> m_bodyColors; ///< set by setBodyColor(), by instance name
    QHash<QString, ConnectorItem *> m_connectors;
    QHash<QString, ConnectorInfo> m_removedConnectors;
    bool m_gridVisible = true;
    bool m_snapToGrid = true;
    bool m_rebuilding = false; ///< rebuild() is adding every item
    PortItem *m_dragSource = nullptr;
    QGraphicsPathItem *m_rubberConnector = nullptr;
    QString m_lastRefusal;
    int m_pasteCount = 0;
};

} // namespace SystemEditor
