// SPDX-License-Identifier: MIT
// The edits a user makes on the canvas; each becomes one step on the undo stack.
#include "systemscene.h"

#include "instancecommands.h"
#include "componentfactory.h"
#include "compositecommands.h"
#include "componentitem.h"
#include "connectorcommands.h"
#include "connectoritem.h"
#include "pastecommand.h"
#include "portitem.h"

#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>
#include <QUndoStack>

namespace SystemEditor {

namespace {

constexpr qreal PasteOffset = 40;

} // namespace

void SystemScene::push(QUndoCommand *command)
{
    if (m_undoStack) {
        m_undoStack->push(command);
        return;
    }
    // A scene without undo stack still applies what it is asked to.
    command->redo();
    delete command;
}

void SystemScene::deleteSelection()
{
    const QStringList components = selectedComponents();
    QStringList connectors;
    for (const QString &id : selectedConnectors()) {
        const std::optional<ConnectorInfo> info = m_model->connector(id);
        // Connectors of deleted components go with them.
        if (info && !components.contains(info->source.instanceName)
            && !components.contains(info->target.instanceName))
            connectors.append(id);
    }
    if (components.isEmpty() && connectors.isEmpty())
        return;
    auto *macro = new QUndoCommand(tr("Delete"));
    for (const QString &id : std::as_const(connectors))
        new DisconnectCommand(m_model, id, macro);
    if (!components.isEmpty())
        new RemoveComponentsCommand(m_model, components, macro);
    push(macro);
}

void SystemScene::copySelection()
{
    const QStringList components = selectedComponents();
    if (components.isEmpty())
        return;
    // The system clipboard, so that another window or another rtstudio can paste them.
    QGuiApplication::clipboard()->setMimeData(
        ComponentClipboard::copy(*m_model, components).toMimeData());
    m_pasteCount = 0;
}

bool SystemScene::canPaste()
{
    return ComponentClipboard::canRead(QGuiApplication::clipboard()->mimeData());
}

bool SystemScene::paste()
{
    QString error;
    const std::optional<ComponentClipboard> clipboard
        = ComponentClipboard::fromMimeData(QGuiApplication::clipboard()->mimeData(), &error);
    if (!clipboard) {
        emit statusMessage(error);
        return false;
    }
    ++m_pasteCount;
    auto *command = new PasteComponentsCommand(m_model, *clipboard,
                                               QPointF(PasteOffset, PasteOffset) * m_pasteCount);
    const QStringList names = command->pastedNames();
    push(command);
    selectComponents(names);
    return true;
}

QString SystemScene::groupSelection(const QString &compositeType,
                                    const QList<ConnectorEnd> &exportedPorts)
{
    const QStringList members = selectedComponents();
    if (members.isEmpty())
        return {};
    // Around the members as drawn (with their labels), not only as saved.
    QRectF bounds;
    for (const QString &member : members) {
        const ComponentItem *item = m_components.value(member);
        bounds |= item->mapRectToScene(item->bodyRect());
    }
    auto *command = new CreateCompositeCommand(m_model, compositeType, members, exportedPorts, {},
                                               nullptr, bounds);
    const QString name = command->instanceName();
    push(command);
    selectComponents({name});
    return name;
}

QStringList SystemScene::selectedComposites() const
{
    QStringList names;
    for (const QString &name : selectedComponents()) {
        if (m_components.value(name)->appearance().isComposite())
            names.append(name);
    }
    return names;
}

bool SystemScene::decomposeSelection()
{
    const QStringList composites = selectedComposites();
    if (composites.isEmpty())
        return false;
    if (composites.size() == 1) {
        push(new DecomposeCommand(m_model, composites.first()));
        return true;
    }
    auto *macro = new QUndoCommand(tr("Decompose %n composites", nullptr, int(composites.size())));
    for (const QString &name : composites)
        new DecomposeCommand(m_model, name, macro);
    push(macro);
    return true;
}

void SystemScene::setDirectionOfSelection(Direction direction)
{
    QStringList names;
    for (const QString &name : selectedComponents()) {
        if (m_model->layout(name).direction != direction)
            names.append(name);
    }
    if (names.isEmpty())
        return;
    if (names.size() == 1) {
        push(new SetDirectionCommand(m_model, names.first(), direction));
        return;
    }
    auto *macro = new QUndoCommand(tr("Turn Components"));
    for (const QString &name : std::as_const(names))
        new SetDirectionCommand(m_model, name, direction, macro);
    push(macro);
}

void SystemScene::alignSelection(Alignment alignment)
{
    if (MoveComponentsCommand *command
        = alignComponentsCommand(m_model, selectedComponents(), alignment))
        push(command);
}

bool SystemScene::renameComponent(const QString &oldName, const QString &newName)
{
    const QString name = newName.trimmed();
    if (name == oldName)
        return true;
    if (name.isEmpty() || m_model->hasComponent(name) || !m_model->hasComponent(oldName)) {
        const QString reason = name.isEmpty()
            ? tr("An instance name cannot be empty.")
            : tr("There is already a component called \"%1\".").arg(name);
        emit statusMessage(reason);
        return false;
    }
    push(new RenameComponentCommand(m_model, oldName, name));
    return true;
}

QString SystemScene::addComponent(const Profile::RtcProfile &rtc, const QString &pathUri,
                                  const QPointF &position)
{
    const QString name = m_model->uniqueInstanceName(componentTypeName({}, &rtc));
    const Profile::RtsComponent component = componentFromRtcProfile(rtc, name, pathUri, position);
    auto *command = new AddComponentCommand(m_model, component, rtc);
    push(command);
    return m_model->hasComponent(name) ? name : QString();
}

void SystemScene::connectPorts(const ConnectionCheck &check, const ConnectorSettings &settings)
{
    if (!check.allowed || check.kind != ConnectorKind::Data)
        return;
    push(new ConnectCommand(m_model,
                            makeDataConnector(*m_model, check.source, check.target, settings)));
}

void SystemScene::connectServicePorts(const ConnectionCheck &check,
                                      const ServiceConnectorSettings &settings)
{
    if (!check.allowed || check.kind != ConnectorKind::Service)
        return;
    push(new ConnectCommand(m_model,
                            makeServiceConnector(*m_model, check.source, check.target, settings)));
}

void SystemScene::editConnector(const QString &connectorId, const ConnectorSettings &settings)
{
    if (EditConnectorCommand *command
        = EditConnectorCommand::fromSettings(m_model, connectorId, settings))
        push(command);
}

void SystemScene::editServiceConnector(const QString &connectorId,
                                       const ServiceConnectorSettings &settings)
{
    if (EditConnectorCommand *command
        = EditConnectorCommand::fromSettings(m_model, connectorId, settings))
        push(command);
}

void SystemScene::commitMoves()
{
    QHash<QString, QPointF> positions;
    for (auto it = m_components.cbegin(); it != m_components.cend(); ++it) {
        if (it.value()->pos() != m_model->layout(it.key()).position)
            positions.insert(it.key(), it.value()->pos());
    }
    if (!positions.isEmpty())
        push(new MoveComponentsCommand(m_model, positions));
}

} // namespace SystemEditor
