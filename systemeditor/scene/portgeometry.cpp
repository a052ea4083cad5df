// SPDX-License-Identifier: MIT
#include "portgeometry.h"

#include <QTransform>

namespace SystemEditor {

QPointF outwardNormal(PortSide side)
{
    switch (side) {
    case PortSide::Left:
        return {-1, 0};
    case PortSide::Right:
        return {1, 0};
    case PortSide::Top:
        return {0, -1};
    case PortSide::Bottom:
        break;
    }
    return {0, 1};
}

namespace {

/// The shape for a port on the right side; other sides rotate it.
QPainterPath rightSideShape(PortKind kind)
{
    const qreal h = PortHalfSize;
    QPainterPath path;
    switch (kind) {
    case PortKind::DataIn:
        // A block with a notch in its outer edge: data comes in.
        path.moveTo(-h, -h);
        path.lineTo(h, -h);
        path.lineTo(h * 0.1, 0);
        path.lineTo(h, h);
        path.lineTo(-h, h);
        break;
    case PortKind::DataOut:
        // An arrow head pointing away from the body: data goes out.
        path.moveTo(-h, -h);
        path.lineTo(h * 0.1, -h);
        path.lineTo(h, 0);
        path.lineTo(h * 0.1, h);
        path.lineTo(-h, h);
        break;
    case PortKind::Service:
        path.addRect(-h, -h, 2 * h, 2 * h);
        return path;
    case PortKind::Unknown:
        path.addEllipse(QPointF(0, 0), h, h);
        return path;
    }
    path.closeSubpath();
    return path;
}

qreal rotationFor(PortSide side)
{
    switch (side) {
    case PortSide::Right:
        return 0;
    case PortSide::Bottom:
        return 90;
    case PortSide::Left:
        return 180;
    case PortSide::Top:
        break;
    }
    return 270;
}

} // namespace

QPainterPath portShape(PortKind kind, PortSide side)
{
    return QTransform().rotate(rotationFor(side)).map(rightSideShape(kind));
}

QColor portColor(PortKind kind, bool connected)
{
    if (kind == PortKind::Service)
        return connected ? QColor(0, 220, 230) : QColor(173, 216, 250);
    return connected ? QColor(144, 238, 144) : QColor(50, 100, 220);
}

} // namespace SystemEditor
