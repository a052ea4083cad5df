// SPDX-License-Identifier: MIT
// Mouse interaction of the canvas: dragging a connector from port to port, committing moves.
#include "systemscene.h"

#include "componentitem.h"
#include "connectoritem.h"
#include "portitem.h"

#include <QGraphicsPathItem>
#include <QGraphicsSceneMouseEvent>

namespace SystemEditor {

namespace {

ConnectorEnd endOf(const PortItem *port)
{
    return {port->instanceName(), port->port().name};
}

} // namespace

PortItem *SystemScene::portAt(const QPointF &scenePos) const
{
    // A little tolerance: port shapes are small, and a drop next to one still means it.
    const QRectF area(scenePos - QPointF(4, 4), QSizeF(8, 8));
    for (QGraphicsItem *item : items(area, Qt::IntersectsItemShape, Qt::DescendingOrder)) {
        if (item->type() == PortItem::Type)
            return static_cast<PortItem *>(item);
    }
    return nullptr;
}

void SystemScene::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    PortItem *port = event->button() == Qt::LeftButton ? portAt(event->scenePos()) : nullptr;
    if (!port || !m_undoStack) {
        QGraphicsScene::mousePressEvent(event);
        return;
    }
    startConnecting(port, event->scenePos());
    event->accept();
}

void SystemScene::mouseMoveEvent(QGraphicsSceneMouseEvent *event)
{
    if (m_dragSource) {
        updateConnecting(event->scenePos());
        event->accept();
        return;
    }
    QGraphicsScene::mouseMoveEvent(event);
}

void SystemScene::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    if (m_dragSource) {
        finishConnecting(event->scenePos());
        event->accept();
        return;
    }
    QGraphicsScene::mouseReleaseEvent(event);
    if (event->button() == Qt::LeftButton)
        commitMoves();
}

void SystemScene::mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event)
{
    QGraphicsItem *item = itemAt(event->scenePos(), QTransform());
    while (item && item->type() != ComponentItem::Type && item->type() != ConnectorItem::Type)
        item = item->parentItem();
    if (item && item->type() == ComponentItem::Type) {
        emit componentActivated(static_cast<ComponentItem *>(item)->instanceName());
        event->accept();
        return;
    }
    QGraphicsScene::mouseDoubleClickEvent(event);
}

void SystemScene::startConnecting(PortItem *source, const QPointF &scenePos)
{
    m_dragSource = source;
    m_lastRefusal.clear();
    m_rubberConnector = new QGraphicsPathItem;
    m_rubberConnector->setPen(QPen(QColor(255, 140, 0), 2, Qt::DashLine));
    m_rubberConnector->setZValue(10);
    addItem(m_rubberConnector);
    const ConnectorEnd from = endOf(source);
    for (ComponentItem *component : std::as_const(m_components)) {
        for (PortItem *port : component->portItems()) {
            if (port == source)
                continue;
            const bool legal = ConnectionRules::check(*m_model, from, endOf(port)).allowed;
            port->setHighlight(legal ? PortItem::Highlight::Legal : PortItem::Highlight::Illegal);
        }
    }
    updateConnecting(scenePos);
}

void SystemScene::updateConnecting(const QPointF &scenePos)
{
    QPainterPath path(m_dragSource->connectionPoint());
    path.lineTo(scenePos);
    m_rubberConnector->setPath(path);
    PortItem *target = portAt(scenePos);
    if (!target || target == m_dragSource)
        return;
    const ConnectionCheck check = ConnectionRules::check(*m_model, endOf(m_dragSource),
                                                         endOf(target));
    emit statusMessage(check.allowed ? tr("Release to connect to %1").arg(target->port().name)
                                     : check.reason);
}

void SystemScene::finishConnecting(const QPointF &scenePos)
{
    PortItem *target = portAt(scenePos);
    const ConnectorEnd from = endOf(m_dragSource);
    const bool sameStart = target == m_dragSource;
    clearHighlights();
    if (!target || sameStart)
        return;
    const ConnectionCheck check = ConnectionRules::check(*m_model, from, endOf(target));
    if (!check.allowed) {
        m_lastRefusal = check.reason;
        emit statusMessage(check.reason);
        emit connectionRefused(check.reason);
        return;
    }
    emit connectRequested(check);
}

void SystemScene::clearHighlights()
{
    for (ComponentItem *component : std::as_const(m_components)) {
        for (PortItem *port : component->portItems())
            port->setHighlight(PortItem::Highlight::None);
    }
    delete m_rubberConnector;
    m_rubberConnector = nullptr;
    m_dragSource = nullptr;
}

} // namespace SystemEditor
