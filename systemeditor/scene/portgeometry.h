// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QColor>
#include <QPainterPath>
#include <QPointF>

namespace SystemEditor {

/// The unit vector pointing out of a component's body on `side`.
QPointF outwardNormal(PortSide side);

/// Port shape centred on (0,0), pointing out of the body on `side`: InPorts are notched blocks
/// (data comes in), OutPorts arrow heads pointing out, service ports squares and ports no RTC
/// profile describes circles.
QPainterPath portShape(PortKind kind, PortSide side);

/// Fill colour of a port: data ports blue when unconnected and light green when connected;
/// service ports light blue, cyan when connected.
QColor portColor(PortKind kind, bool connected);

/// Half the edge length of a port shape.
inline constexpr qreal PortHalfSize = 7.0;

} // namespace SystemEditor
