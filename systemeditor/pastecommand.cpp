// SPDX-License-Identifier: MIT
#include "pastecommand.h"

#include "instancecommands.h"
#include "componentfactory.h"
#include "connectorcommands.h"

#include "profileio.h"
#include "rtcxml.h"
#include "rtsxml.h"

#include <QDataStream>
#include <QIODevice>
#include <QMimeData>
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

QMimeData *ComponentClipboard::toMimeData() const
{
    RtsProfile fragment;
    fragment.id = QStringLiteral("RTSystem:RTStudio:Clipboard:1.0");
    fragment.version = RtsProfile::CurrentVersion;
    fragment.creationDate = fragment.updateDate = QStringLiteral("2000-01-01T00:00:00");
    fragment.components = components;
    fragment.dataPortConnectors = dataConnectors;
    fragment.servicePortConnectors = serviceConnectors;
    const QByteArray xml = writeRtsXml(fragment);
    QByteArray rtcs;
    QDataStream stream(&rtcs, QIODevice::WriteOnly);
    for (auto it = rtcProfiles.cbegin(); it != rtcProfiles.cend(); ++it)
        stream << it.key() << writeRtcXml(it.value());
    auto *mime = new QMimeData;
    mime->setData(MimeType, xml);
    mime->setData(RtcMimeType, rtcs);
    mime->setText(QString::fromUtf8(xml));
    return mime;
}

bool ComponentClipboard::canRead(const QMimeData *mime)
{
    return mime && mime->hasFormat(MimeType);
}

namespace {

/// The RTC profiles written by toMimeData(); unreadable entries are left out (their
/// components paste without port kinds, as when their RTC.xml is missing).
QHash<QString, RtcProfile> readRtcProfiles(const QByteArray &data)
{
    QHash<QString, RtcProfile> profiles;
    QDataStream stream(data);
    while (!stream.atEnd()) {
        QString instance;
        QByteArray xml;
        stream >> instance >> xml;
        if (stream.status() != QDataStream::Ok)
            break;
        Diagnostics diagnostics;
        if (std::optional<RtcProfile> rtc = readRtcXml(xml, QString(), &diagnostics))
            profiles.insert(instance, *rtc);
    }
    return profiles;
}

} // namespace

std::optional<ComponentClipboard> ComponentClipboard::fromMimeData(const QMimeData *mime,
                                                                   QString *error)
{
    if (!canRead(mime)) {
        *error = QCoreApplication::translate("SystemEditor::ComponentClipboard",
                                             "The clipboard holds no components.");
        return std::nullopt;
    }
    Diagnostics diagnostics;
    const std::optional<RtsProfile> fragment
        = readRtsXml(mime->data(MimeType), QStringLiteral("clipboard"), &diagnostics);
    if (!fragment || fragment->components.isEmpty()) {
        const QString detail = diagnostics.isEmpty() ? QString() : diagnostics.first().toString();
        *error = QCoreApplication::translate("SystemEditor::ComponentClipboard",
                                             "The clipboard's components cannot be read: %1")
                     .arg(detail.isEmpty() ? QStringLiteral("no components") : detail);
        return std::nullopt;
    }
    ComponentClipboard clipboard;
    clipboard.components = fragment->components;
    clipboard.dataConnectors = fragment->dataPortConnectors;
    clipboard.serviceConnectors = fragment->servicePortConnectors;
    clipboard.rtcProfiles = readRtcProfiles(mime->data(RtcMimeType));
    QStringList names;
    for (const RtsComponent &component : std::as_const(clipboard.components))
        names << component.instanceName;
    // Connectors whose ends were not copied along would point at nothing once pasted.
    clipboard.dataConnectors = innerConnectors(clipboard.dataConnectors, names);
    clipboard.serviceConnectors = innerConnectors(clipboard.serviceConnectors, names);
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
