// SPDX-License-Identifier: MIT
#include "componentappearance.h"

#include "portgeometry.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace SystemEditor {

ComponentAppearance ComponentAppearance::fromModel(const SystemModel &model,
                                                   const QString &instanceName)
{
    ComponentAppearance appearance;
    appearance.instanceName = instanceName;
    if (const Profile::RtsComponent *component = model.component(instanceName)) {
        const std::optional<Profile::RtsComponentTypeId> type
            = Profile::RtsComponentTypeId::parse(component->id);
        appearance.typeName = type ? type->name : component->id;
        const QString composite = component->compositeType.value_or(QString());
        if (!composite.isEmpty() && composite != QLatin1String("None"))
            appearance.compositeType = composite;
    }
    appearance.size = model.layout(instanceName).size;
    appearance.ports = model.ports(instanceName);
    for (const PortInfo &port : std::as_const(appearance.ports)) {
        if (model.isPortConnected(instanceName, port.name))
            appearance.connectedPorts.insert(port.name);
    }
    return appearance;
}

namespace {

// WCAG 2 relative luminance of an sRGB colour.
double relativeLuminance(const QColor &colour)
{
    const auto linear = [](double channel) {
        return channel <= 0.03928 ? channel / 12.92 : std::pow((channel + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * linear(colour.redF()) + 0.7152 * linear(colour.greenF())
        + 0.0722 * linear(colour.blueF());
}

} // namespace

double contrastRatio(const QColor &a, const QColor &b)
{
    const double first = relativeLuminance(a);
    const double second = relativeLuminance(b);
    return (std::max(first, second) + 0.05) / (std::min(first, second) + 0.05);
}

BodyTextColours BodyTextColours::on(const QColor &body)
{
    const BodyTextColours dark {QColor(20, 20, 20), QColor(35, 35, 35), QColor(30, 30, 60)};
    const BodyTextColours light {Qt::white, Qt::white, Qt::white};
    return contrastRatio(body, dark.title) >= contrastRatio(body, light.title) ? dark : light;
}

bool ComponentAppearance::operator==(const ComponentAppearance &other) const
{
    return instanceName == other.instanceName && typeName == other.typeName
        && size == other.size && bodyColor == other.bodyColor && ports == other.ports
        && connectedPorts == other.connectedPorts && compositeType == other.compositeType;
}

namespace {

std::array<int, 4> portsPerSide(const ComponentAppearance &component)
{
    std::array<int, 4> counts {0, 0, 0, 0};
    for (const PortInfo &port : component.ports)
        ++counts[int(port.side)];
    return counts;
}

/// The rows of a body from top to bottom: labels of top ports, titles, the side ports' area,
/// labels of bottom ports.
struct Rows
{
    qreal top = 0;
    qreal title = 0;
    qreal bottom = 0;
};

Rows rowsFor(const std::array<int, 4> &counts, const ComponentTextSizes &text)
{
    Rows rows;
    rows.top = counts[int(PortSide::Top)] > 0 ? text.labelHeight + 6 : 2;
    rows.title = text.titleHeight + 8;
    rows.bottom = counts[int(PortSide::Bottom)] > 0 ? text.labelHeight + 6 : 4;
    return rows;
}

/// Ports on the left and right share the area below the titles; ports on the top and bottom
/// spread over the whole width.
QPointF placeOnSide(const QRectF &body, const Rows &rows, PortSide side, int index, int count)
{
    const qreal areaTop = body.top() + rows.top + rows.title;
    const qreal areaHeight = body.bottom() - rows.bottom - areaTop;
    const qreal y = areaTop + areaHeight * (index + 0.5) / count;
    const qreal x = body.left() + body.width() * qreal(index + 1) / qreal(count + 1);
    const QPointF out = outwardNormal(side) * PortHalfSize;
    switch (side) {
    case PortSide::Left:
        return QPointF(body.left(), y) + out;
    case PortSide::Right:
        return QPointF(body.right(), y) + out;
    case PortSide::Top:
        return QPointF(x, body.top()) + out;
    case PortSide::Bottom:
        break;
    }
    return QPointF(x, body.bottom()) + out;
}

} // namespace

QSizeF ComponentGeometry::minimumBodySize(const ComponentAppearance &component,
                                          const ComponentTextSizes &text)
{
    const std::array<int, 4> counts = portsPerSide(component);
    const int vertical = std::max(counts[int(PortSide::Left)], counts[int(PortSide::Right)]);
    const int horizontal = std::max(counts[int(PortSide::Top)], counts[int(PortSide::Bottom)]);
    // Labels of left and right ports share a row when both sides have ports.
    const qreal sideLabels = (counts[int(PortSide::Left)] > 0 ? text.widestLabel : 0)
        + (counts[int(PortSide::Right)] > 0 ? text.widestLabel : 0);
    const qreal width = std::max({text.titleWidth + 24, sideLabels + 24, 100.0,
                                  (horizontal + 1) * std::max(PortPitch, text.widestLabel + 8)});
    const Rows rows = rowsFor(counts, text);
    const qreal height = std::max(rows.top + rows.title + vertical * PortPitch + rows.bottom, 60.0);
    // Whole numbers: the system file stores sizes as integers.
    return {std::ceil(width), std::ceil(height)};
}

ComponentGeometry ComponentGeometry::layout(const ComponentAppearance &component,
                                            const ComponentTextSizes &text)
{
    QSizeF size = minimumBodySize(component, text);
    if (component.size.width() > 0)
        size.setWidth(std::max(size.width(), component.size.width()));
    if (component.size.height() > 0)
        size.setHeight(std::max(size.height(), component.size.height()));
    ComponentGeometry geometry;
    geometry.body = QRectF(QPointF(0, 0), size);
    const std::array<int, 4> counts = portsPerSide(component);
    const Rows rows = rowsFor(counts, text);
    // Without side ports the titles sit in the middle.
    const bool sidePorts = counts[int(PortSide::Left)] + counts[int(PortSide::Right)] > 0;
    const qreal titleTop = sidePorts ? rows.top + 4
                                     : rows.top + (size.height() - rows.top - rows.bottom
                                                   - text.titleHeight) / 2;
    geometry.title = QRectF(0, titleTop, size.width(), text.titleHeight);
    std::array<int, 4> placed {0, 0, 0, 0};
    for (const PortInfo &port : component.ports) {
        const int side = int(port.side);
        geometry.portCenters.append(placeOnSide(geometry.body, rows, port.side, placed[side]++,
                                                counts[side]));
    }
    return geometry;
}

} // namespace SystemEditor
