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

// The fonts and their metrics are made once: building a QFont and measuring with it on every
// paint of a thousand components costs more than drawing them.
const QFont &titleFont()
{
    static const QFont font = [] {
        QFont f;
        f.setBold(true);
        return f;
    }();
    return font;
}

const QFont &typeFont()
{
    static const QFont font = [] {
        QFont f;
        f.setItalic(true);
        f.setPointSizeF(f.pointSizeF() * 0.85);
        return f;
    }();
    return font;
}

const QFont &labelFont()
{
    static const QFont font = [] {
        QFont f;
        f.setPointSizeF(f.pointSizeF() * 0.8);
        return f;
    }();
    return font;
}

const QFontMetricsF &titleMetrics()
{
    static const QFontMetricsF metrics(titleFont());
    return metrics;
}

const QFontMetricsF &typeMetrics()
{
    static const QFontMetricsF metrics(typeFont());
    return metrics;
}

const QFontMetricsF &labelMetrics()
{
    static const QFontMetricsF metrics(labelFont());
    return metrics;
}

/// A composite's frame is filled with a translucent light tint over the canvas.
constexpr QColor CompositeFill(228, 232, 250, 110);

constexpr qreal CompositeZ = -2; // under connectors (-1) and components (0)
constexpr qreal FrameWidth = 8;

/// Below this scale the port labels are a few pixels high and cannot be read; leaving them out
/// keeps a zoomed-out view of a large system fast.
constexpr qreal LabelDetailLimit = 0.45;
/// Below this scale the type line is left out too; the instance name stays.
constexpr qreal TypeDetailLimit = 0.3;

} // namespace

ComponentItem::ComponentItem(const ComponentAppearance &appearance, QGraphicsItem *parent)
    : QGraphicsObject(parent)
    , m_appearance(appearance)
{
    setFlags(ItemIsMovable | ItemIsSelectable | ItemIsFocusable | ItemSendsGeometryChanges);
    setAcceptHoverEvents(true);
    // A composite's frame lies under its members and their connectors.
    setZValue(appearance.isComposite() ? CompositeZ : 0);
    relayout();
    rebuildPorts();
}

void ComponentItem::setAppearance(const ComponentAppearance &appearance)
{
    if (appearance == m_appearance)
        return;
    m_appearance = appearance;
    setZValue(appearance.isComposite() ? CompositeZ : 0);
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
    if (m_appearance.isComposite()) {
        // Only the frame and the title band: clicks inside reach the members.
        path.addRect(m_geometry.body.adjusted(FrameWidth, compositeBandHeight(), -FrameWidth,
                                              -FrameWidth));
    }
    return path;
}

qreal ComponentItem::compositeBandHeight()
{
    return titleMetrics().height() + typeMetrics().height() + 8;
}

ComponentTextSizes ComponentItem::measureText() const
{
    const QFontMetricsF &title = titleMetrics();
    const QFontMetricsF &type = typeMetrics();
    const QFontMetricsF &label = labelMetrics();
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
    m_text
        = BodyTextColours::on(m_appearance.isComposite() ? CompositeFill : m_appearance.bodyColor);
    m_geometry = ComponentGeometry::layout(m_appearance, measureText());
    layoutPortLabels();
}

void ComponentItem::layoutPortLabels()
{
    // Placed and elided once per layout, not on every paint.
    m_labels.clear();
    const QFontMetricsF &metrics = labelMetrics();
    const qreal h = metrics.height();
    const QRectF body = m_geometry.body;
    const qreal innerWidth = body.width() - 2 * LabelMargin;
    for (int i = 0; i < m_appearance.ports.size(); ++i) {
        const PortInfo &port = m_appearance.ports.at(i);
        const QPointF at = m_geometry.portCenters.at(i);
        PortLabel label;
        label.align = Qt::AlignVCenter;
        switch (port.side) {
        case PortSide::Left:
            label.rect = QRectF(body.left() + LabelMargin, at.y() - h / 2, innerWidth, h);
            label.align |= Qt::AlignLeft;
            break;
        case PortSide::Right:
            label.rect = QRectF(body.left() + LabelMargin, at.y() - h / 2, innerWidth, h);
            label.align |= Qt::AlignRight;
            break;
        case PortSide::Top:
            label.rect = QRectF(at.x() - PortPitch * 2, body.top() + 2, PortPitch * 4, h);
            label.align |= Qt::AlignHCenter;
            break;
        case PortSide::Bottom:
            label.rect = QRectF(at.x() - PortPitch * 2, body.bottom() - 2 - h, PortPitch * 4, h);
            label.align |= Qt::AlignHCenter;
            break;
        }
        label.text = metrics.elidedText(port.profileName, Qt::ElideRight, label.rect.width());
        m_labels.append(label);
    }
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
    const qreal detail = option->levelOfDetailFromTransform(painter->worldTransform());
    if (m_appearance.isComposite()) {
        paintComposite(painter, selected, detail >= TypeDetailLimit);
    } else {
        painter->setPen(selected ? QPen(QColor(30, 110, 230), 2.5)
                                 : QPen(QColor(60, 60, 60), 1.2));
        painter->setBrush(m_appearance.bodyColor);
        painter->drawRoundedRect(m_geometry.body, 4, 4);
        paintTitles(painter, detail >= TypeDetailLimit);
    }
    if (detail >= LabelDetailLimit)
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

void ComponentItem::paintTitles(QPainter *painter, bool withType) const
{
    const QRectF body = m_geometry.body;
    const qreal top = m_geometry.title.top();
    const qreal titleHeight = titleMetrics().height();
    painter->setPen(m_text.title);
    painter->setFont(titleFont());
    painter->drawText(QRectF(body.left(), top, body.width(), titleHeight), Qt::AlignCenter,
                      m_appearance.instanceName);
    if (!withType)
        return;
    painter->setPen(m_text.type);
    painter->setFont(typeFont());
    painter->drawText(QRectF(body.left(), top + titleHeight, body.width(), typeMetrics().height()),
                      Qt::AlignCenter, m_appearance.typeName);
}

void ComponentItem::paintComposite(QPainter *painter, bool selected, bool withType) const
{
    QPen frame(selected ? QColor(30, 110, 230) : QColor(80, 80, 130), selected ? 2.5 : 1.5);
    frame.setStyle(Qt::DashLine);
    painter->setPen(frame);
    painter->setBrush(CompositeFill);
    painter->drawRoundedRect(m_geometry.body, 8, 8);
    const QRectF band = m_geometry.body.adjusted(FrameWidth, 4, -FrameWidth, 0);
    const qreal titleHeight = titleMetrics().height();
    painter->setPen(m_text.title);
    painter->setFont(titleFont());
    painter->drawText(QRectF(band.left(), band.top(), band.width(), titleHeight),
                      Qt::AlignLeft | Qt::AlignVCenter, m_appearance.instanceName);
    if (!withType)
        return;
    painter->setPen(m_text.type);
    painter->setFont(typeFont());
    painter->drawText(QRectF(band.left(), band.top() + titleHeight, band.width(),
                             typeMetrics().height()),
                      Qt::AlignLeft | Qt::AlignVCenter,
                      tr("Composite (%1)").arg(m_appearance.compositeType));
}

void ComponentItem::paintPortLabels(QPainter *painter) const
{
    painter->setFont(labelFont());
    painter->setPen(m_text.portLabel);
    for (const PortLabel &label : m_labels)
        painter->drawText(label.rect, label.align, label.text);
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
