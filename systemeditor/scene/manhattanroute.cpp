// SPDX-License-Identifier: MIT
#include "manhattanroute.h"

#include "portgeometry.h"

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

/// Automatic middle between the two stub ends. When the end lies ahead of the start, the route
/// turns halfway between them; when it lies behind, it runs across between the two ports.
void appendAutomaticMiddle(QPolygonF &route, const QPointF &to, PortSide startSide)
{
    const QPointF from = route.last();
    const QPointF normal = outwardNormal(startSide);
    const bool ahead = QPointF::dotProduct(to - from, normal) >= 0;
    if (isHorizontal(startSide) == ahead) {
        const qreal midX = (from.x() + to.x()) / 2;
        appendPoint(route, QPointF(midX, from.y()));
        appendPoint(route, QPointF(midX, to.y()));
    } else {
        const qreal midY = (from.y() + to.y()) / 2;
        appendPoint(route, QPointF(from.x(), midY));
        appendPoint(route, QPointF(to.x(), midY));
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

} // namespace

QPolygonF manhattanRoute(const QPointF &start, PortSide startSide, const QPointF &end,
                         PortSide endSide, const QList<QPointF> &bendPoints)
{
    const QPointF startStub = start + outwardNormal(startSide) * RouteStub;
    const QPointF endStub = end + outwardNormal(endSide) * RouteStub;
    QPolygonF route {start, startStub};
    if (bendPoints.isEmpty()) {
        appendAutomaticMiddle(route, endStub, startSide);
    } else {
        for (const QPointF &bend : bendPoints)
            appendOrthogonal(route, bend);
        appendOrthogonal(route, endStub);
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
