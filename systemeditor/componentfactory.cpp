// SPDX-License-Identifier: MIT
#include "componentfactory.h"

#include "systemmodel.h"

namespace SystemEditor {

using namespace Profile;

namespace {

RtsPort portNamed(const QString &instanceName, const QString &portName)
{
    RtsPort port;
    port.name = instanceName + QLatin1Char('.') + portName;
    port.visible = QStringLiteral("true");
    return port;
}

} // namespace

RtsComponent componentFromRtcProfile(const RtcProfile &rtc, const QString &instanceName,
                                     const QString &pathUri, const QPointF &position)
{
    RtsComponent component;
    component.id = rtc.id.isEmpty() ? rtc.idFromBasicInfo() : rtc.id;
    component.pathUri = pathUri;
    component.instanceName = instanceName;
    component.compositeType = QStringLiteral("None");
    component.isRequired = QStringLiteral("true");
    component.visible = QStringLiteral("true");
    for (const RtcDataPort &port : rtc.dataPorts)
        component.dataPorts << portNamed(instanceName, port.name);
    for (const RtcServicePort &port : rtc.servicePorts)
        component.servicePorts << portNamed(instanceName, port.name);
    if (!rtc.configurations.isEmpty()) {
        RtsConfigurationSet set;
        set.id = QStringLiteral("default");
        for (const RtcConfiguration &configuration : rtc.configurations) {
            RtsConfigurationData data;
            data.name = configuration.name;
            data.data = configuration.defaultValue;
            set.data << data;
        }
        component.configurationSets << set;
        component.activeConfigurationSet = set.id;
    }
    RtsLocation location;
    location.x = QString::number(qRound(position.x()));
    location.y = QString::number(qRound(position.y()));
    location.width = location.height = QStringLiteral("-1");
    location.direction = QStringLiteral("RIGHT");
    component.layout = location;
    return component;
}

QString componentTypeName(const RtsComponent &component, const RtcProfile *rtc)
{
    if (rtc && !rtc->basicInfo.name.isEmpty())
        return rtc->basicInfo.name;
    if (const std::optional<RtsComponentTypeId> id = RtsComponentTypeId::parse(component.id)) {
        if (!id->name.isEmpty())
            return id->name;
    }
    return QStringLiteral("Component");
}

QSizeF componentSize(const SystemModel &model, const QString &instanceName)
{
    const ComponentLayout layout = model.layout(instanceName);
    int perSide[4] = {0, 0, 0, 0};
    for (const PortInfo &port : model.ports(instanceName))
        ++perSide[int(port.side)];
    const int vertical = qMax(perSide[int(PortSide::Left)], perSide[int(PortSide::Right)]);
    const int horizontal = qMax(perSide[int(PortSide::Top)], perSide[int(PortSide::Bottom)]);
    const qreal width = layout.size.width() > 0
        ? layout.size.width()
        : qMax(DefaultComponentWidth, (horizontal + 1) * PortSpacing);
    const qreal height = layout.size.height() > 0
        ? layout.size.height()
        : qMax(MinimumComponentHeight, (vertical + 1) * PortSpacing);
    return QSizeF(width, height);
}

} // namespace SystemEditor
