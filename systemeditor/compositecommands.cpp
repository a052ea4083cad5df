// SPDX-License-Identifier: MIT
#include "compositecommands.h"

#include "componentfactory.h"

#include <QRectF>

namespace SystemEditor {

using namespace Profile;

namespace {

/// Copies the member's RTC description of `port`, renamed to the exported name.
void exportPort(const SystemModel &model, const ConnectorEnd &end, RtsComponent &composite,
                RtcProfile &rtc)
{
    RtsPort port;
    port.name = end.portName;
    port.visible = QStringLiteral("true");
    const std::optional<PortInfo> info = model.port(end.instanceName, end.portName);
    const RtcProfile *memberRtc = model.rtcProfile(end.instanceName);
    if (info && info->kind == PortKind::Service) {
        composite.servicePorts << port;
        if (const RtcServicePort *p = memberRtc ? memberRtc->servicePort(info->profileName) : nullptr) {
            RtcServicePort copy = *p;
            copy.name = end.portName;
            rtc.servicePorts << copy;
        }
        return;
    }
    composite.dataPorts << port;
    if (const RtcDataPort *p = memberRtc && info ? memberRtc->dataPort(info->profileName) : nullptr) {
        RtcDataPort copy = *p;
        copy.name = end.portName;
        rtc.dataPorts << copy;
    }
}

} // namespace

QStringList compositeKinds()
{
    return {QStringLiteral("PeriodicECShared"), QStringLiteral("PeriodicStateShared"),
            QStringLiteral("Grouping")};
}

std::pair<RtsComponent, RtcProfile> makeComposite(const SystemModel &model,
                                                  const QString &instanceName,
                                                  const QString &compositeType,
                                                  const QStringList &members,
                                                  const QList<ConnectorEnd> &exportedPorts,
                                                  const QRectF &membersBounds)
{
    // OpenRTM-aist's composite factories: vendor jp.go.aist, category composite.<type>.
    RtcProfile rtc;
    rtc.basicInfo.name = compositeType + QStringLiteral("Composite");
    rtc.basicInfo.vendor = QStringLiteral("jp.go.aist");
    rtc.basicInfo.category = QStringLiteral("composite.") + compositeType;
    rtc.basicInfo.version = QStringLiteral("1.0");
    rtc.id = rtc.idFromBasicInfo();

    RtsComponent composite;
    composite.id = rtc.id;
    composite.instanceName = instanceName;
    composite.compositeType = compositeType;
    composite.isRequired = QStringLiteral("true");
    composite.visible = QStringLiteral("true");
    QRectF bounds;
    for (const QString &member : members) {
        const RtsComponent *c = model.component(member);
        if (!c)
            continue;
        RtsParticipant participant;
        participant.participant.componentId = c->id;
        participant.participant.instanceName = member;
        composite.participants << participant;
        bounds |= QRectF(model.layout(member).position, componentSize(model, member));
    }
    if (membersBounds.isValid())
        bounds = membersBounds;
    for (const ConnectorEnd &end : exportedPorts)
        exportPort(model, end, composite, rtc);
    RtsLocation location;
    location.x = QString::number(qRound(bounds.left() - 20));
    location.y = QString::number(qRound(bounds.top() - 20));
    location.width = QString::number(qRound(bounds.width() + 40));
    location.height = QString::number(qRound(bounds.height() + 40));
    location.direction = QStringLiteral("RIGHT");
    composite.layout = location;
    return {composite, rtc};
}

CreateCompositeCommand::CreateCompositeCommand(SystemModel *model, const QString &compositeType,
                                               const QStringList &members,
                                               const QList<ConnectorEnd> &exportedPorts,
                                               const QString &instanceName, QUndoCommand *parent,
                                               const QRectF &membersBounds)
    : QUndoCommand(parent)
{
    m_name = instanceName.isEmpty() || model->hasComponent(instanceName)
        ? model->uniqueInstanceName(compositeType)
        : instanceName;
    auto [composite, rtc] = makeComposite(*model, m_name, compositeType, members, exportedPorts,
                                            membersBounds);
    new AddComponentCommand(model, composite, rtc, this);
    setText(tr("Create composite %1").arg(m_name));
}

DecomposeCommand::DecomposeCommand(SystemModel *model, const QString &compositeName,
                                   QUndoCommand *parent)
    : RemoveComponentsCommand(model, {compositeName}, parent)
{
    setText(tr("Decompose %1").arg(compositeName));
}

} // namespace SystemEditor
