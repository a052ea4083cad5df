// SPDX-License-Identifier: MIT
#include "componentitem.h"

#include "portgeometry.h"
#include "portitem.h"

#include <QFontMetricsF>
#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <cmath>

namespace SystemEditor {

namespace {

constexpr qreal HandleSize = 10;
constexpr qreal LabelMargin = 4;

QFont titleFont()
{
    QFont font;
    font.setBold(true);
    return font;
}

QFont typeFont()
{
    QFont font;
    font.setItalic(true);
    font.setPointSizeF(font.pointSizeF() * 0.85);
    return font;
}

QFont labelFont()
{
    QFont font;
    font.setPointSizeF(font.pointSizeF() * 0.8);
    return font;
}

} // namespace

ComponentItem::ComponentItem(const ComponentAppearance &appearance, QGraphicsItem *parent)
    : QGraphicsObject(parent)
    , m_appearance(appearance)
{
    setFlags(ItemIsMovable | ItemIsSelectable | ItemIsFocusable | ItemSendsGeometryChanges);
    setAcceptHoverEvents(true);
    relayout();
    rebuildPorts();
}

void ComponentItem::setAppearance(const ComponentAppearance &appearance)
{
    if (appearance == m_appearance)
        return;
    m_appearance = appearance;
    prepareGeometryChange();
    relayout();
    rebuildPorts();
    update();
}

QList<PortItem *> ComponentItem::portItems() const
{
    QList<PortItem *> items;
    for (const PortInfo &port : m_appearance.ports) {
        if (PortItem *item = m_ports.value(port.name))
            items.append(item);
    }
    return items;
}

QRectF ComponentItem::resizeHandleRect() const
{
    const QPointF corner = m_geometry.body.bottomRight();
    return QRectF(corner - QPointF(HandleSize, HandleSize), corner);
}

QRectF ComponentItem::boundingRect() const
{
    const qreal margin = 2 * PortHalfSize + 2;
    return m_geometry.body.adjusted(-margin, -margin, margin, margin);
}

QPainterPath ComponentItem::shape() const
{
    QPainterPath path;
    path.addRect(m_geometry.body);
    return path;
}

ComponentTextSizes ComponentItem::measureText() const
{
    const QFontMetricsF title(titleFont());
    const QFontMetricsF type(typeFont());
    const QFontMetricsF label(labelFont());
    ComponentTextSizes sizes;
    sizes.titleWidth = std::max(title.horizontalAdvance(m_appearance.instanceName),
                                type.horizontalAdvance(m_appearance.typeName));
    sizes.titleHeight = title.height() + type.height();
    for (const PortInfo &port : m_appearance.ports)
        sizes.widestLabel = std::max(sizes.widestLabel, label.horizontalAdvance(port.profileName));
    sizes.widestLabel += LabelMargin;
    sizes.labelHeight = label.height();
    return sizes;
}

void ComponentItem::relayout()
{
    m_geometry = ComponentGeometry::layout(m_appearance, measureText());
}

void ComponentItem::rebuildPorts()
{
    qDeleteAll(m_ports);
    m_ports.clear();
    for (int i = 0; i < m_appearance.ports.size(); ++i) {
        const PortInfo &port = m_appearance.ports.at(i);
        auto *item = new PortItem(m_appearance.instanceName, port,
                                  m_appearance.connectedPorts.contains(port.name), this);
        item->setPos(m_geometry.portCenters.at(i));
        m_ports.insert(port.name, item);
    }
    emit geometryChanged();
}

void ComponentItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const bool selected = option->state & QStyle::State_Selected;
    painter->setPen(selected ? QPen(QColor(30, 110, 230), 2.5) : QPen(QColor(60, 60, 60), 1.2));
    painter->setBrush(m_appearance.bodyColor);
    painter->drawRoundedRect(m_geometry.body, 4, 4);
    paintTitles(painter);
    paintPortLabels(painter);
    if (selected) {
        painter->setPen(Qt::NoPen);
        painter->setBrush(QColor(30, 110, 230));
        QPainterPath handle;
        const QRectF rect = resizeHandleRect();
        handle.moveTo(rect.bottomLeft());
        handle.lineTo(rect.bottomRight());
        handle.lineTo(rect.topRight());
        handle.closeSubpath();
        painter->drawPath(handle);
    }
}

void ComponentItem::paintTitles(QPainter *painter) const
{
    const QFontMetricsF title(titleFont());
    const QFontMetricsF type(typeFont());
    const QRectF body = m_geometry.body;
    const qreal top = m_geometry.title.top();
    painter->setPen(QColor(20, 20, 20));
    painter->setFont(titleFont());
    painter->drawText(QRectF(body.left(), top, body.width(), title.height()), Qt::AlignCenter,
                      m_appearance.instanceName);
    painter->setPen(QColor(90, 90, 90));
    painter->setFont(typeFont());
    painter->drawText(QRectF(body.left(), top + title.height(), body.width(), type.height()),
                      Qt::AlignCenter, m_appearance.typeName);
}

void ComponentItem::paintPortLabels(QPainter *painter) const
{
    painter->setFont(labelFont());
    painter->setPen(QColor(50, 50, 80));
    const QFontMetricsF metrics(labelFont());
    const qreal h = metrics.height();
    const QRectF body = m_geometry.body;
    for (int i = 0; i < m_appearance.ports.size(); ++i) {
        const PortInfo &port = m_appearance.ports.at(i);
        const QPointF at = m_geometry.portCenters.at(i);
        const qreal innerWidth = body.width() - 2 * LabelMargin;
        QRectF rect;
        Qt::Alignment align = Qt::AlignVCenter;
        switch (port.side) {
        case PortSide::Left:
            rect = QRectF(body.left() + LabelMargin, at.y() - h / 2, innerWidth, h);
            align |= Qt::AlignLeft;
            break;
        case PortSide::Right:
            rect = QRectF(body.left() + LabelMargin, at.y() - h / 2, innerWidth, h);
            align |= Qt::AlignRight;
            break;
        case PortSide::Top:
            rect = QRectF(at.x() - PortPitch * 2, body.top() + 2, PortPitch * 4, h);
            align |= Qt::AlignHCenter;
            break;
        case PortSide::Bottom:
            rect = QRectF(at.x() - PortPitch * 2, body.bottom() - 2 - h, PortPitch * 4, h);
            align |= Qt::AlignHCenter;
            break;
        }
        painter->drawText(rect, int(align),
                          metrics.elidedText(port.profileName, Qt::ElideRight, rect.width()));
    }
}

QVariant ComponentItem::itemChange(GraphicsItemChange change, const QVariant &value)
{
    if (change == ItemPositionChange && m_snapGrid > 0) {
        const QPointF p = value.toPointF();
        return QPointF(std::round(p.x() / m_snapGrid) * m_snapGrid,
                       std::round(p.y() / m_snapGrid) * m_snapGrid);
    }
    return QGraphicsObject::itemChange(change, value);
}

void ComponentItem::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && isSelected()
        && resizeHandleRect().contains(event->pos())) {
        m_resizing = true;
        m_resizeStartSize = m_geometry.body.size();
        m_resizeStartPos = event->scenePos();
        event->accept();
        return;
    }
    QGraphicsObject::mousePressEvent(event);
}

void ComponentItem::mouseMoveEvent(QGraphicsSceneMouseEvent *event)
{
    if (!m_resizing) {
        QGraphicsObject::mouseMoveEvent(event);
        return;
    }
    // Preview the new size locally; the model gets it on release.
    const QPointF delta = event->scenePos() - m_resizeStartPos;
    prepareGeometryChange();
    m_appearance.size = QSizeF(m_resizeStartSize.width() + delta.x(),
                               m_resizeStartSize.height() + delta.y());
    relayout();
    const QList<PortItem *> ports = portItems();
    for (int i = 0; i < ports.size(); ++i)
        ports.at(i)->setPos(m_geometry.portCenters.at(i));
    emit geometryChanged();
    update();
}

void ComponentItem::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    if (!m_resizing) {
        QGraphicsObject::mouseReleaseEvent(event);
        return;
    }
    m_resizing = false;
    if (m_geometry.body.size() != m_resizeStartSize)
        emit resizeRequested(m_appearance.instanceName, m_geometry.body.size());
}

void ComponentItem::hoverMoveEvent(QGraphicsSceneHoverEvent *event)
{
    const bool onHandle = isSelected() && resizeHandleRect().contains(event->pos());
    setCursor(onHandle ? Qt::SizeFDiagCursor : Qt::ArrowCursor);
    QGraphicsObject::hoverMoveEvent(event);
}

} // namespace SystemEditor
