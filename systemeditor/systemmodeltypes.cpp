// SPDX-License-Identifier: MIT
// The small value types of systemmodel.h: directions, port sides, bend point text, equality.
#include "systemmodel.h"

#include <QMap>
#include <QRegularExpression>

#include <tuple>

namespace SystemEditor {

namespace {

QString numberText(qreal value)
{
    return QString::number(qRound(value));
}

} // namespace

// ---- small value types ---------------------------------------------------------------------

Direction directionFromText(const QString &text)
{
    const QString upper = text.trimmed().toUpper();
    if (upper == QLatin1String("LEFT"))
        return Direction::Left;
    if (upper == QLatin1String("UP"))
        return Direction::Up;
    if (upper == QLatin1String("DOWN"))
        return Direction::Down;
    return Direction::Right;
}

QString directionText(Direction direction)
{
    switch (direction) {
    case Direction::Left:
        return QStringLiteral("LEFT");
    case Direction::Up:
        return QStringLiteral("UP");
    case Direction::Down:
        return QStringLiteral("DOWN");
    case Direction::Right:
        break;
    }
    return QStringLiteral("RIGHT");
}

PortSide rotatedSide(PortSide side, Direction direction)
{
    switch (direction) {
    case Direction::Right:
        return side;
    case Direction::Left: {
        static const PortSide mirrored[] = {PortSide::Right, PortSide::Left, PortSide::Top,
                                            PortSide::Bottom};
        return mirrored[int(side)];
    }
    case Direction::Down: {
        // A quarter turn clockwise: inputs come from above, outputs leave below.
        static const PortSide turned[] = {PortSide::Top, PortSide::Bottom, PortSide::Right,
                                          PortSide::Left};
        return turned[int(side)];
    }
    case Direction::Up: {
        static const PortSide turned[] = {PortSide::Bottom, PortSide::Top, PortSide::Left,
                                          PortSide::Right};
        return turned[int(side)];
    }
    }
    return side;
}

bool InterfaceInfo::operator==(const InterfaceInfo &other) const
{
    return std::tie(name, type, instanceName, polarity)
        == std::tie(other.name, other.type, other.instanceName, other.polarity);
}

bool PortInfo::operator==(const PortInfo &other) const
{
    return std::tie(name, profileName, kind, dataType, interfaces, profileSide, side, described)
        == std::tie(other.name, other.profileName, other.kind, other.dataType, other.interfaces,
                    other.profileSide, other.side, other.described);
}

bool ComponentLayout::operator==(const ComponentLayout &other) const
{
    return position == other.position && size == other.size && direction == other.direction;
}

bool ConnectorEnd::operator==(const ConnectorEnd &other) const
{
    return instanceName == other.instanceName && portName == other.portName;
}

bool ConnectorInfo::operator==(const ConnectorInfo &other) const
{
    return std::tie(id, name, kind, source, target, bendPoints, bendPointEntries)
        == std::tie(other.id, other.name, other.kind, other.source, other.target,
                    other.bendPoints, other.bendPointEntries);
}

QString bendPointsToText(const QList<QPointF> &points)
{
    // Corner i starts route segment i (segment 0 leaves the source port), so RT System Editor,
    // which keys segments, moves each of its segments through the corner that starts ours.
    QStringList items;
    for (int i = 0; i < points.size(); ++i) {
        items << QStringLiteral("%1:(%2,%3)")
                     .arg(i + 1)
                     .arg(numberText(points.at(i).x()), numberText(points.at(i).y()));
    }
    return QLatin1Char('{') + items.join(QLatin1Char(',')) + QLatin1Char('}');
}

std::optional<QList<QPointF>> bendPointsFromText(const QString &text)
{
    const std::optional<QMap<int, QPointF>> entries = bendPointEntriesFromText(text);
    if (!entries)
        return std::nullopt;
    return entries->values();
}

std::optional<QMap<int, QPointF>> bendPointEntriesFromText(const QString &text)
{
    static const QRegularExpression item(
        QStringLiteral(R"(^\s*(\d+)\s*:\s*\(\s*(-?\d+(?:\.\d+)?)\s*,\s*(-?\d+(?:\.\d+)?)\s*\)\s*$)"));
    QString body = text.trimmed();
    if (!body.startsWith(QLatin1Char('{')) || !body.endsWith(QLatin1Char('}')))
        return std::nullopt;
    body = body.mid(1, body.size() - 2);
    QMap<int, QPointF> ordered;
    if (body.trimmed().isEmpty())
        return ordered;
    // Items are separated by the commas that follow a ')'.
    const QStringList items = body.split(QRegularExpression(QStringLiteral(R"((?<=\))\s*,)")));
    for (const QString &entry : items) {
        const QRegularExpressionMatch m = item.match(entry);
        if (!m.hasMatch())
            return std::nullopt;
        ordered.insert(m.captured(1).toInt(),
                       QPointF(m.captured(2).toDouble(), m.captured(3).toDouble()));
    }
    return ordered;
}

} // namespace SystemEditor
