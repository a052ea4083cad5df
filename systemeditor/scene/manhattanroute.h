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

/**
 * RT System Editor's reading of `BEND_POINT` entries: segment i of `route` (segment 0 leaves the
 * start) is moved through entries[i], sideways only: a vertical segment takes the entry's x, a
 * horizontal one its y, and the segments beside it stretch to meet it. Keys beyond the route's
 * segments are ignored. A straight route is first given RT System Editor's three segments (a
 * zero-length jog halfway), so that its middle can be moved.
 */
QPolygonF constrainedRoute(const QPolygonF &route, const QMap<int, QPointF> &entries);

/**
 * The corners a connector routes through for its saved `BEND_POINT` entries (empty when none).
 * Entries keyed 1…n that make a right-angled path from the start's lead to the end's are corners
 * as this editor writes them; any other entries are RT System Editor's segment positions, applied
 * with constrainedRoute() to the automatic route, which is what RT System Editor draws for ports
 * facing each other.
 */
QList<QPointF> savedRouteCorners(const QPointF &start, PortSide startSide, const QPointF &end,
                                 PortSide endSide, const QMap<int, QPointF> &entries,
                                 const QRectF &bodies = {});

/// Length of the straight piece leaving a port before the route turns.
inline constexpr qreal RouteLead = 16.0;

} // namespace SystemEditor
