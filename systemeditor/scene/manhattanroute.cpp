// SPDX-License-Identifier: MIT
#include "manhattanroute.h"

#include "portgeometry.h"

#include <cmath>

namespace SystemEditor {

namespace {

bool isHorizontal(PortSide side)
{
    return side == PortSide::Left || side == PortSide::Right;
}

void appendPoint(QPolygonF &route, const QPointF &point)
{
    if (route.isEmpty() || route.last() != point)
        route.append(point);
}

/// True when the last segment of `route` runs horizontally.
bool endsHorizontally(const QPolygonF &route)
{
    const QPointF a = route.at(route.size() - 2);
    const QPointF b = route.last();
    return qFuzzyCompare(a.y(), b.y());
}

/// Adds `to`, with an elbow first when it is not in line with the last point; the elbow turns
/// away from the direction the route arrived in, so that no segment doubles back on itself.
void appendOrthogonal(QPolygonF &route, const QPointF &to)
{
    const QPointF from = route.last();
    if (!qFuzzyCompare(from.x(), to.x()) && !qFuzzyCompare(from.y(), to.y()))
        appendPoint(route, endsHorizontally(route) ? QPointF(from.x(), to.y())
                                                   : QPointF(to.x(), from.y()));
    appendPoint(route, to);
}

/// The coordinate of a detour lane beside both bodies (above/below for horizontal sides,
/// left/right for vertical ones), on the side that makes the shorter detour.
qreal detourLane(const QPointF &from, const QPointF &to, bool horizontalSides,
                 const QRectF &bodies)
{
    const auto along = [horizontalSides](const QPointF &p) {
        return horizontalSides ? p.y() : p.x();
    };
    const qreal low = bodies.isEmpty() ? std::min(along(from), along(to)) - 2 * RouteLead
                                       : (horizontalSides ? bodies.top() : bodies.left())
            - RouteLead * 1.5;
    const qreal high = bodies.isEmpty() ? std::max(along(from), along(to)) + 2 * RouteLead
                                        : (horizontalSides ? bodies.bottom() : bodies.right())
            + RouteLead * 1.5;
    const qreal viaLow = std::abs(along(from) - low) + std::abs(along(to) - low);
    const qreal viaHigh = std::abs(along(from) - high) + std::abs(along(to) - high);
    return viaLow <= viaHigh ? low : high;
}

/// Automatic middle between the ends of the two leads. Ports facing each other meet halfway; ports
/// facing away run along a lane beside both bodies; perpendicular ones turn once.
void appendAutomaticMiddle(QPolygonF &route, const QPointF &to, PortSide startSide,
                           PortSide endSide, const QRectF &bodies)
{
    const QPointF from = route.last();
    const bool horizontal = isHorizontal(startSide);
    if (horizontal != isHorizontal(endSide)) {
        appendPoint(route, horizontal ? QPointF(to.x(), from.y()) : QPointF(from.x(), to.y()));
        appendPoint(route, to);
        return;
    }
    const bool startAhead = QPointF::dotProduct(to - from, outwardNormal(startSide)) >= 0;
    const bool endAhead = QPointF::dotProduct(from - to, outwardNormal(endSide)) >= 0;
    if (startAhead && endAhead) {
        const QPointF mid = (from + to) / 2;
        appendPoint(route, horizontal ? QPointF(mid.x(), from.y()) : QPointF(from.x(), mid.y()));
        appendPoint(route, horizontal ? QPointF(mid.x(), to.y()) : QPointF(to.x(), mid.y()));
    } else {
        const qreal lane = detourLane(from, to, horizontal, bodies);
        appendPoint(route, horizontal ? QPointF(from.x(), lane) : QPointF(lane, from.y()));
        appendPoint(route, horizontal ? QPointF(to.x(), lane) : QPointF(lane, to.y()));
    }
    appendPoint(route, to);
}

bool isBetween(qreal a, qreal b, qreal c)
{
    return (a <= b && b <= c) || (c <= b && b <= a);
}

/// Removes points in the middle of straight runs, except the user's bend points.
QPolygonF simplified(const QPolygonF &route, const QList<QPointF> &keep)
{
    QPolygonF result;
    for (const QPointF &point : route) {
        if (result.size() >= 2 && !keep.contains(result.last())) {
            const QPointF a = result.at(result.size() - 2);
            const QPointF b = result.last();
            const bool sameX = qFuzzyCompare(a.x(), b.x()) && qFuzzyCompare(b.x(), point.x())
                && isBetween(a.y(), b.y(), point.y());
            const bool sameY = qFuzzyCompare(a.y(), b.y()) && qFuzzyCompare(b.y(), point.y())
                && isBetween(a.x(), b.x(), point.x());
            if (sameX || sameY)
                result.removeLast();
        }
        appendPoint(result, point);
    }
    return result;
}

/// Within the rounding of saved coordinates, which are whole numbers.
bool sameCoordinate(qreal a, qreal b)
{
    return std::abs(a - b) <= 1.0;
}

bool aligned(const QPointF &a, const QPointF &b)
{
    return sameCoordinate(a.x(), b.x()) || sameCoordinate(a.y(), b.y());
}

/// True when `point` lies on the line leaving a port on `side` at `port`.
bool onLead(const QPointF &port, PortSide side, const QPointF &point)
{
    return isHorizontal(side) ? sameCoordinate(port.y(), point.y())
                              : sameCoordinate(port.x(), point.x());
}

/// True when `entries` are corners as this editor saves them: keyed 1…n, each in line with the
/// next, the first on the start's lead and the last on the end's.
bool isCornerChain(const QPointF &start, PortSide startSide, const QPointF &end,
                   PortSide endSide, const QMap<int, QPointF> &entries)
{
    if (entries.firstKey() != 1 || entries.lastKey() != entries.size())
        return false;
    const QList<QPointF> corners = entries.values();
    for (int i = 0; i + 1 < corners.size(); ++i) {
        if (!aligned(corners.at(i), corners.at(i + 1)))
            return false;
    }
    return onLead(start, startSide, corners.first()) && onLead(end, endSide, corners.last());
}

} // namespace

QPolygonF constrainedRoute(const QPolygonF &route, const QMap<int, QPointF> &entries)
{
    QPolygonF points = route;
    if (points.size() == 2) {
        const QPointF middle = (points.first() + points.last()) / 2;
        points = QPolygonF {points.first(), middle, middle, points.last()};
    }
    // As RT System Editor does: in key order, each entry slides its whole segment; a
    // zero-length segment counts as vertical.
    for (auto it = entries.cbegin(); it != entries.cend(); ++it) {
        const int i = it.key();
        if (i < 0 || i > points.size() - 2)
            continue;
        if (qFuzzyCompare(points.at(i).x() + 1, points.at(i + 1).x() + 1)) {
            points[i].setX(it->x());
            points[i + 1].setX(it->x());
        } else if (qFuzzyCompare(points.at(i).y() + 1, points.at(i + 1).y() + 1)) {
            points[i].setY(it->y());
            points[i + 1].setY(it->y());
        }
    }
    return points;
}

QList<QPointF> savedRouteCorners(const QPointF &start, PortSide startSide, const QPointF &end,
                                 PortSide endSide, const QMap<int, QPointF> &entries,
                                 const QRectF &bodies)
{
    if (entries.isEmpty())
        return {};
    if (isCornerChain(start, startSide, end, endSide, entries))
        return entries.values();
    const QPolygonF route
        = constrainedRoute(manhattanRoute(start, startSide, end, endSide, {}, bodies), entries);
    // The ends stay on the ports; manhattanRoute() joins them to the moved corners.
    return QList<QPointF>(route.cbegin() + 1, route.cend() - 1);
}

QPolygonF manhattanRoute(const QPointF &start, PortSide startSide, const QPointF &end,
                         PortSide endSide, const QList<QPointF> &bendPoints,
                         const QRectF &bodies)
{
    const QPointF startLead = start + outwardNormal(startSide) * RouteLead;
    const QPointF endLead = end + outwardNormal(endSide) * RouteLead;
    QPolygonF route {start, startLead};
    if (bendPoints.isEmpty()) {
        appendAutomaticMiddle(route, endLead, startSide, endSide, bodies);
    } else {
        for (const QPointF &bend : bendPoints)
            appendOrthogonal(route, bend);
        appendOrthogonal(route, endLead);
    }
    appendPoint(route, end);
    return simplified(route, bendPoints);
}

QList<QPointF> routeCorners(const QPolygonF &route)
{
    QList<QPointF> corners;
    for (int i = 1; i + 1 < route.size(); ++i)
        corners.append(route.at(i));
    // A straight route still offers one point to pull a bend out of.
    if (corners.isEmpty() && route.size() == 2)
        corners.append((route.first() + route.last()) / 2);
    return corners;
}

} // namespace SystemEditor
