// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QGraphicsPathItem>

namespace SystemEditor {

class PortItem;

/**
 * A connector drawn as a Manhattan route between two PortItems. When selected it shows a handle
 * on each corner; dragging one emits bendPointsRequested() with all corners, which the scene
 * turns into an undo command that stores them as `BEND_POINT`. Saved entries in RT System
 * Editor's form (segment positions) are drawn where it drew them.
 */
class ConnectorItem : public QGraphicsObject
{
    Q_OBJECT

public:
    enum { Type = UserType + 3 };

    explicit ConnectorItem(const ConnectorInfo &info, QGraphicsItem *parent = nullptr);

    int type() const override { return Type; }
    QString connectorId() const { return m_info.id; }
    const ConnectorInfo &info() const { return m_info; }
    void setInfo(const ConnectorInfo &info);
    /// The ports it joins (null when a port is not drawn); the route follows them.
    void setPorts(PortItem *source, PortItem *target);
    PortItem *sourcePort() const { return m_source; }
    PortItem *targetPort() const { return m_target; }

    /// Recomputes the route from the ports' current positions.
    void updateRoute();
    QPolygonF route() const { return m_route; }
    /// Index of the corner handle at `scenePos`, or -1.
    int handleAt(const QPointF &scenePos) const;

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option,
               QWidget *widget) override;

signals:
    void bendPointsRequested(const QString &connectorId, const QList<QPointF> &points);
    void editRequested(const QString &connectorId);

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event) override;

private:
    void setRoute(const QPolygonF &route);
    /// The two components' bodies, which automatic routes go round.
    QRectF bodies() const;
    /// The corners its `BEND_POINT` entries give (savedRouteCorners()); empty = route freely.
    QList<QPointF> savedCorners() const;
    void drawVisibleRoute(QPainter *painter, qreal penWidth) const;

    ConnectorInfo m_info;
    PortItem *m_source = nullptr;
    PortItem *m_target = nullptr;
    QPolygonF m_route;
    QPainterPath m_path;
    int m_draggedHandle = -1;
    QList<QPointF> m_draggedCorners;
};

} // namespace SystemEditor
