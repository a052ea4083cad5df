// SPDX-License-Identifier: MIT
#include "pastecommand.h"

#include "instancecommands.h"
#include "componentfactory.h"
#include "connectorcommands.h"

#include <QSet>

namespace SystemEditor {

using namespace Profile;

namespace {

/// Points a connector end at the renamed component (`Old.port` → `New.port`).
void renameEnd(RtsTargetPort &end, const QHash<QString, QString> &names)
{
    const QString newName = names.value(end.instanceName);
    const QString prefix = end.instanceName + QLatin1Char('.');
    if (end.portName.startsWith(prefix))
        end.portName = newName + QLatin1Char('.') + end.portName.mid(prefix.size());
    end.instanceName = newName;
}

template<typename Connector>
QList<Connector> innerConnectors(const QList<Connector> &all, const QStringList &names)
{
    QList<Connector> result;
    for (const Connector &c : all) {
        if (names.contains(c.source.instanceName) && names.contains(c.target.instanceName))
            result << c;
    }
    return result;
}

QString freeName(const SystemModel &model, const QString &typeName, const QSet<QString> &taken)
{
    for (int n = 0;; ++n) {
        const QString candidate = typeName + QString::number(n);
        if (!model.hasComponent(candidate) && !taken.contains(candidate))
            return candidate;
    }
}

} // namespace

ComponentClipboard ComponentClipboard::copy(const SystemModel &model,
                                            const QStringList &instanceNames)
{
    ComponentClipboard clipboard;
    QStringList copied;
    for (const QString &name : model.componentIds()) {
        if (!instanceNames.contains(name))
            continue;
        clipboard.components << *model.component(name);
        if (const RtcProfile *rtc = model.rtcProfile(name))
            clipboard.rtcProfiles.insert(name, *rtc);
        copied << name;
    }
    clipboard.dataConnectors = innerConnectors(model.profile().dataPortConnectors, copied);
    clipboard.serviceConnectors = innerConnectors(model.profile().servicePortConnectors, copied);
    return clipboard;
}

PasteComponentsCommand::PasteComponentsCommand(SystemModel *model,
                                               const ComponentClipboard &clipboard,
                                               const QPointF &offset, QUndoCommand *parent)
    : QUndoCommand(parent)
{
    QHash<QString, QString> names;
    QSet<QString> taken;
    for (const RtsComponent &component : clipboard.components) {
        const auto rtc = clipboard.rtcProfiles.constFind(component.instanceName);
        const RtcProfile *profile = rtc == clipboard.rtcProfiles.constEnd() ? nullptr : &*rtc;
        const QString name = freeName(*model, componentTypeName(component, profile), taken);
        taken.insert(name);
        names.insert(component.instanceName, name);
        m_names << name;
        RtsComponent pasted = renamedComponent(component, name);
        if (pasted.layout) {
            pasted.layout->x = QString::number(RtsLocation::toInt(pasted.layout->x).value_or(0)
                                               + qRound(offset.x()));
            pasted.layout->y = QString::number(RtsLocation::toInt(pasted.layout->y).value_or(0)
                                               + qRound(offset.y()));
        }
        new AddComponentCommand(model, pasted,
                                profile ? std::optional<RtcProfile>(*profile) : std::nullopt,
                                this);
    }
    for (RtsDataPortConnector c : clipboard.dataConnectors) {
        c.connectorId = newConnectorId();
        renameEnd(c.source, names);
        renameEnd(c.target, names);
        new ConnectCommand(model, c, this);
    }
    for (RtsServicePortConnector c : clipboard.serviceConnectors) {
        c.connectorId = newConnectorId();
        renameEnd(c.source, names);
        renameEnd(c.target, names);
        new ConnectCommand(model, c, this);
    }
    setText(tr("Paste %n components", nullptr, int(m_names.size())));
}

} // namespace SystemEditor
