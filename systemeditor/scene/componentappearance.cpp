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
    }
    appearance.size = model.layout(instanceName).size;
    appearance.ports = model.ports(instanceName);
    for (const PortInfo &port : std::as_const(appearance.ports)) {
        if (model.isPortConnected(instanceName, port.name))
            appearance.connectedPorts.insert(port.name);
    }
    return appearance;
}

bool ComponentAppearance::operator==(const ComponentAppearance &other) const
{
    return instanceName == other.instanceName && typeName == other.typeName
        && size == other.size && bodyColor == other.bodyColor && ports == other.ports
        && connectedPorts == other.connectedPorts;
}

namespace {

std::array<int, 4> portsPerSide(const ComponentAppearance &component)
{
    std::array<int, 4> counts {0, 0, 0, 0};
    for (const PortInfo &port : component.ports)
        ++counts[int(port.side)];
    return counts;
}

QPointF placeOnSide(const QRectF &body, PortSide side, int index, int count)
{
    const qreal fraction = qreal(index + 1) / qreal(count + 1);
    const QPointF out = outwardNormal(side) * PortHalfSize;
    switch (side) {
    case PortSide::Left:
        return QPointF(body.left(), body.top() + body.height() * fraction) + out;
    case PortSide::Right:
        return QPointF(body.right(), body.top() + body.height() * fraction) + out;
    case PortSide::Top:
        return QPointF(body.left() + body.width() * fraction, body.top()) + out;
    case PortSide::Bottom:
        break;
    }
    return QPointF(body.left() + body.width() * fraction, body.bottom()) + out;
}

} // namespace

QSizeF ComponentGeometry::minimumBodySize(const ComponentAppearance &component,
                                          const ComponentTextSizes &text)
{
    const std::array<int, 4> counts = portsPerSide(component);
    const int vertical = std::max(counts[int(PortSide::Left)], counts[int(PortSide::Right)]);
    const int horizontal = std::max(counts[int(PortSide::Top)], counts[int(PortSide::Bottom)]);
    // Labels of left and right ports sit inside the body on either side of the centre; labels of
    // top and bottom ports need their own rows above and below the title.
    const qreal sideLabels = (counts[int(PortSide::Left)] > 0 ? text.widestLabel : 0)
        + (counts[int(PortSide::Right)] > 0 ? text.widestLabel : 0);
    const qreal width = std::max({text.titleWidth + 24, sideLabels + 24, 100.0,
                                  (horizontal + 1) * std::max(PortPitch, text.widestLabel + 8)});
    qreal height = text.titleHeight + 24;
    if (horizontal > 0)
        height += 2 * (text.labelHeight + 6);
    height = std::max({height, 60.0, (vertical + 1) * PortPitch});
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
    std::array<int, 4> placed {0, 0, 0, 0};
    for (const PortInfo &port : component.ports) {
        const int side = int(port.side);
        geometry.portCenters.append(placeOnSide(geometry.body, port.side, placed[side]++,
                                                counts[side]));
    }
    return geometry;
}

} // namespace SystemEditor
