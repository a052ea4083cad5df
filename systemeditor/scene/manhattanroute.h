// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QPolygonF>

namespace SystemEditor {

/**
 * A connector's path made of horizontal and vertical segments only. It leaves `start` and
 * enters `end` straight out of their sides (a short lead), then passes through `bendPoints` in
 * order; an elbow is added wherever two consecutive points are not aligned. Without bend points
 * the middle is routed automatically: ports facing each other meet halfway, ports facing away
 * go round `bodies` (the united rectangles of the two components, if known).
 */
QPolygonF manhattanRoute(const QPointF &start, PortSide startSide, const QPointF &end,
                         PortSide endSide, const QList<QPointF> &bendPoints = {},
                         const QRectF &bodies = {});

/// The points of a route between its ends (its corners): what the user drags as bend points.
QList<QPointF> routeCorners(const QPolygonF &route);

/// Length of the straight piece leaving a port before the route turns.
inline constexpr qreal RouteLead = 16.0;

} // namespace SystemEditor
