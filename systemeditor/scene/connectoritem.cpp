// SPDX-License-Identifier: MIT
#include "connectoritem.h"

#include "manhattanroute.h"
#include "portitem.h"

#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QPainterPathStroker>
#include <QStyleOptionGraphicsItem>

#include <algorithm>

namespace SystemEditor {

namespace {

constexpr qreal HandleRadius = 4;

QColor connectorColor(ConnectorKind kind)
{
    return kind == ConnectorKind::Service ? QColor(0, 140, 160) : QColor(40, 40, 40);
}

} // namespace

ConnectorItem::ConnectorItem(const ConnectorInfo &info, QGraphicsItem *parent)
    : QGraphicsObject(parent)
    , m_info(info)
{
    setFlags(ItemIsSelectable | ItemIsFocusable);
    setZValue(-1); // under the components, so ports stay clickable
    setToolTip(info.name);
}

void ConnectorItem::setInfo(const ConnectorInfo &info)
{
    m_info = info;
    setToolTip(info.name);
    updateRoute();
}

void ConnectorItem::setPorts(PortItem *source, PortItem *target)
{
    m_source = source;
    m_target = target;
    updateRoute();
}

void ConnectorItem::updateRoute()
{
    if (!m_source || !m_target) {
        setRoute({});
        return;
    }
    const QList<QPointF> bends = m_draggedHandle >= 0 ? m_draggedCorners : savedCorners();
    setRoute(manhattanRoute(m_source->connectionPoint(), m_source->port().side,
                            m_target->connectionPoint(), m_target->port().side, bends,
                            bodies()));
}

QRectF ConnectorItem::bodies() const
{
    const auto bodyOf = [](const PortItem *port) {
        return port->parentItem() ? port->parentItem()->sceneBoundingRect() : QRectF();
    };
    return bodyOf(m_source).united(bodyOf(m_target));
}

QList<QPointF> ConnectorItem::savedCorners() const
{
    if (!m_source || !m_target)
        return {};
    return savedRouteCorners(m_source->connectionPoint(), m_source->port().side,
                             m_target->connectionPoint(), m_target->port().side,
                             m_info.bendPointEntries, bodies());
}

void ConnectorItem::setRoute(const QPolygonF &route)
{
    prepareGeometryChange();
    m_route = route;
    m_path = QPainterPath();
    m_path.addPolygon(route);
    update();
}

int ConnectorItem::handleAt(const QPointF &scenePos) const
{
    const QList<QPointF> corners = routeCorners(m_route);
    for (int i = 0; i < corners.size(); ++i) {
        if (QLineF(corners.at(i), scenePos).length() <= HandleRadius + 3)
            return i;
    }
    return -1;
}

QRectF ConnectorItem::boundingRect() const
{
    const qreal margin = HandleRadius + 4;
    return m_path.boundingRect().adjusted(-margin, -margin, margin, margin);
}

QPainterPath ConnectorItem::shape() const
{
    QPainterPathStroker stroker;
    stroker.setWidth(8);
    QPainterPath shape = stroker.createStroke(m_path);
    if (isSelected()) {
        for (const QPointF &corner : routeCorners(m_route))
            shape.addEllipse(corner, HandleRadius + 3, HandleRadius + 3);
    }
    return shape;
}

void ConnectorItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const bool selected = option->state & QStyle::State_Selected;
    QPen pen(selected ? QColor(30, 110, 230) : connectorColor(m_info.kind), selected ? 2.5 : 1.6);
    if (m_info.kind == ConnectorKind::Service)
        pen.setStyle(Qt::DashLine);
    painter->setPen(pen);
    painter->setBrush(Qt::NoBrush);
    // Dashes keep their phase only when the whole route is drawn.
    if (m_info.kind == ConnectorKind::Service)
        painter->drawPolyline(m_route);
    else
        drawVisibleRoute(painter, pen.widthF());
    if (!selected)
        return;
    painter->setPen(QPen(QColor(30, 110, 230), 1));
    painter->setBrush(Qt::white);
    for (const QPointF &corner : routeCorners(m_route))
        painter->drawRect(QRectF(corner - QPointF(HandleRadius, HandleRadius),
                                 QSizeF(2 * HandleRadius, 2 * HandleRadius)));
}

namespace {

/// The part of the view the painter can reach, in the painter's (item) coordinates.
QRectF paintableArea(const QPainter *painter)
{
    const QPaintDevice *device = painter->device();
    QRectF area = painter->worldTransform().inverted().mapRect(
        QRectF(0, 0, device->width(), device->height()));
    if (painter->hasClipping())
        area &= painter->clipBoundingRect();
    return area;
}

/// `segment` (axis-parallel) cut to `area`.
QLineF clipped(const QLineF &segment, const QRectF &area)
{
    const auto clamp = [&area](const QPointF &p) {
        return QPointF(std::clamp(p.x(), area.left(), area.right()),
                       std::clamp(p.y(), area.top(), area.bottom()));
    };
    return QLineF(clamp(segment.p1()), clamp(segment.p2()));
}

} // namespace

void ConnectorItem::drawVisibleRoute(QPainter *painter, qreal penWidth) const
{
    // Connectors of a large system cross the whole diagram: their bounding rectangles cover
    // any view, so most of them are asked to paint although little or nothing of them shows.
    // Stroking only the runs of segments that reach the view (cut a pen's width outside it, so
    // caps stay invisible and corners keep their joins) keeps pan and zoom fast.
    const QRectF area = paintableArea(painter).adjusted(-4 * penWidth, -4 * penWidth,
                                                        4 * penWidth, 4 * penWidth);
    if (!area.isValid() || area.contains(m_path.boundingRect())) {
        painter->drawPolyline(m_route);
        return;
    }
    QPolygonF run;
    for (int i = 0; i + 1 < m_route.size(); ++i) {
        const QLineF segment(m_route.at(i), m_route.at(i + 1));
        const QRectF box = QRectF(segment.p1(), segment.p2()).normalized();
        if (!box.adjusted(-0.5, -0.5, 0.5, 0.5).intersects(area)) {
            if (run.size() > 1)
                painter->drawPolyline(run);
            run.clear();
            continue;
        }
        const QLineF cut = clipped(segment, area);
        if (!run.isEmpty() && run.last() != cut.p1()) {
            // The route left the area at the corner and comes back: a new run.
            if (run.size() > 1)
                painter->drawPolyline(run);
            run.clear();
        }
        if (run.isEmpty())
            run << cut.p1();
        run << cut.p2();
    }
    if (run.size() > 1)
        painter->drawPolyline(run);
}

void ConnectorItem::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    const int handle = isSelected() ? handleAt(event->scenePos()) : -1;
    if (event->button() == Qt::LeftButton && handle >= 0) {
        m_draggedHandle = handle;
        m_draggedCorners = routeCorners(m_route);
        event->accept();
        return;
    }
    QGraphicsObject::mousePressEvent(event);
}

void ConnectorItem::mouseMoveEvent(QGraphicsSceneMouseEvent *event)
{
    if (m_draggedHandle < 0) {
        QGraphicsObject::mouseMoveEvent(event);
        return;
    }
    m_draggedCorners[m_draggedHandle] = event->scenePos();
    updateRoute();
}

void ConnectorItem::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    if (m_draggedHandle < 0) {
        QGraphicsObject::mouseReleaseEvent(event);
        return;
    }
    // The corners of the route drawn, elbows included, so that what is saved is a right-angled
    // path from port to port (see savedRouteCorners()).
    const QList<QPointF> corners = routeCorners(m_route);
    m_draggedHandle = -1;
    m_draggedCorners.clear();
    if (corners != savedCorners())
        emit bendPointsRequested(m_info.id, corners);
    updateRoute();
}

void ConnectorItem::mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event)
{
    emit editRequested(m_info.id);
    event->accept();
}

} // namespace SystemEditor
