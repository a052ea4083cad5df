// SPDX-License-Identifier: MIT
#pragma once

#include "componentappearance.h"

#include <QGraphicsObject>
#include <QHash>

namespace SystemEditor {

class PortItem;

/**
 * A component instance on the canvas: a body with the instance name and type, and its ports
 * (PortItem children) on the sides the RTC profile asks for, turned by the component's
 * direction. Drawn from a ComponentAppearance only; the scene refreshes it when the model
 * changes.
 *
 * A composite component is drawn as a dashed frame under its members, with its kind in the
 * title band and its exported ports on the frame; only the frame and the band take clicks.
 *
 * The user moves it (the scene turns the move into an undo command when the mouse is released)
 * and resizes it with the handle at the bottom-right corner of a selected item, which emits
 * resizeRequested().
 */
class ComponentItem : public QGraphicsObject
{
    Q_OBJECT

public:
    enum { Type = UserType + 1 };

    explicit ComponentItem(const ComponentAppearance &appearance, QGraphicsItem *parent = nullptr);

    int type() const override { return Type; }
    QString instanceName() const { return m_appearance.instanceName; }
    const ComponentAppearance &appearance() const { return m_appearance; }
    /// Redraws from new data; ports are rebuilt and laid out again.
    void setAppearance(const ComponentAppearance &appearance);

    QRectF bodyRect() const { return m_geometry.body; }
    PortItem *portItem(const QString &portName) const { return m_ports.value(portName); }
    QList<PortItem *> portItems() const;

    /// Positions snap to multiples of `grid` while dragging (0: no snapping).
    void setSnapGrid(qreal grid) { m_snapGrid = grid; }
    /// The area of the resize handle, in item coordinates.
    QRectF resizeHandleRect() const;

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option,
               QWidget *widget) override;

signals:
    /// The user dragged the resize handle to a new body size.
    void resizeRequested(const QString &instanceName, const QSizeF &size);
    /// The body or the ports moved within the item (new layout).
    void geometryChanged();

protected:
    QVariant itemChange(GraphicsItemChange change, const QVariant &value) override;
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;
    void hoverMoveEvent(QGraphicsSceneHoverEvent *event) override;

private:
    ComponentTextSizes measureText() const;
    void relayout();
    void layoutPortLabels();
    void rebuildPorts();
    void paintTitles(QPainter *painter, bool withType) const;
    void paintPortLabels(QPainter *painter) const;
    void paintComposite(QPainter *painter, bool selected, bool withType) const;
    static qreal compositeBandHeight();

    /// A port's name as drawn inside the body: placed and elided at layout time.
    struct PortLabel
    {
        QRectF rect;
        int align = 0;
        QString text;
    };

    ComponentAppearance m_appearance;
    ComponentGeometry m_geometry;
    BodyTextColours m_text; ///< chosen for the body colour at layout time
    QList<PortLabel> m_labels;
    QHash<QString, PortItem *> m_ports;
    qreal m_snapGrid = 0;
    bool m_resizing = false;
    QSizeF m_resizeStartSize;
    QPointF m_resizeStartPos;
};

} // namespace SystemEditor
