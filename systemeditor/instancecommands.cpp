// SPDX-License-Identifier: MIT
#include "instancecommands.h"

#include "systemcommandids.h"
#include "componentfactory.h"
#include "connectorcommands.h"

#include <QRectF>

namespace SystemEditor {

using namespace Profile;

// ---- AddComponentCommand -------------------------------------------------------------------

Profile::RtsComponent renamedComponent(RtsComponent component, const QString &newName)
{
    const QString prefix = component.instanceName + QLatin1Char('.');
    const auto rename = [&](QList<RtsPort> &ports) {
        for (RtsPort &port : ports) {
            if (port.name.startsWith(prefix))
                port.name = newName + QLatin1Char('.') + port.name.mid(prefix.size());
        }
    };
    rename(component.dataPorts);
    rename(component.servicePorts);
    component.instanceName = newName;
    return component;
}

AddComponentCommand::AddComponentCommand(SystemModel *model, const RtsComponent &component,
                                         const std::optional<RtcProfile> &rtc,
                                         QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_component(component)
    , m_rtc(rtc)
{
    if (component.instanceName.isEmpty() || model->hasComponent(component.instanceName)) {
        const QString typeName = componentTypeName(component, rtc ? &*rtc : nullptr);
        m_component = renamedComponent(component, model->uniqueInstanceName(typeName));
    }
    setText(tr("Add %1").arg(m_component.instanceName));
}

void AddComponentCommand::redo()
{
    if (m_model)
        m_model->addComponent(m_component, m_rtc);
}

void AddComponentCommand::undo()
{
    if (m_model)
        m_model->removeComponent(m_component.instanceName);
}

// ---- RemoveComponentsCommand ---------------------------------------------------------------

namespace {

/// Removes one component (no connectors); restores it, with its RTC profile, at its index.
class RemoveOneComponentCommand : public QUndoCommand
{
public:
    RemoveOneComponentCommand(SystemModel *model, const QString &name, QUndoCommand *parent)
        : QUndoCommand(parent)
        , m_model(model)
        , m_component(*model->component(name))
        , m_index(model->componentIndex(name))
    {
        if (const RtcProfile *rtc = model->rtcProfile(name))
            m_rtc = *rtc;
    }

    void redo() override
    {
        if (m_model)
            m_model->removeComponent(m_component.instanceName);
    }
    void undo() override
    {
        if (m_model)
            m_model->addComponent(m_component, m_rtc, m_index);
    }

private:
    QPointer<SystemModel> m_model;
    RtsComponent m_component;
    int m_index;
    std::optional<RtcProfile> m_rtc;
};

} // namespace

RemoveComponentsCommand::RemoveComponentsCommand(SystemModel *model,
                                                 const QStringList &instanceNames,
                                                 QUndoCommand *parent)
    : QUndoCommand(parent)
{
    QStringList connectors;
    for (const QString &name : instanceNames) {
        for (const QString &id : model->connectorsOf(name)) {
            if (!connectors.contains(id))
                connectors << id;
        }
    }
    // Every child records its index in the state before this command. Removing from the back
    // keeps the earlier indices valid; undo runs the children in reverse and so re-inserts from
    // the front, each into the place it had.
    std::sort(connectors.begin(), connectors.end(), [model](const QString &a, const QString &b) {
        return model->connectorIndex(a) > model->connectorIndex(b);
    });
    for (const QString &id : connectors)
        new DisconnectCommand(model, id, this);
    QStringList components;
    for (const QString &name : instanceNames) {
        if (model->hasComponent(name) && !components.contains(name))
            components << name;
    }
    std::sort(components.begin(), components.end(), [model](const QString &a, const QString &b) {
        return model->componentIndex(a) > model->componentIndex(b);
    });
    for (const QString &name : components)
        new RemoveOneComponentCommand(model, name, this);
    setText(components.size() == 1 ? tr("Delete %1").arg(components.first())
                                   : tr("Delete %n components", nullptr, int(components.size())));
}

// ---- MoveComponentsCommand -----------------------------------------------------------------

MoveComponentsCommand::MoveComponentsCommand(SystemModel *model,
                                             const QHash<QString, QPointF> &positions,
                                             const QString &text, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_after(positions)
    , m_mergeable(text.isEmpty())
{
    for (auto it = positions.cbegin(); it != positions.cend(); ++it) {
        if (const RtsComponent *c = model->component(it.key()))
            m_before.insert(it.key(), c->layout);
    }
    setText(text.isEmpty() ? tr("Move") : text);
}

void MoveComponentsCommand::redo()
{
    if (!m_model)
        return;
    for (auto it = m_after.cbegin(); it != m_after.cend(); ++it)
        m_model->moveComponent(it.key(), it.value());
}

void MoveComponentsCommand::undo()
{
    if (!m_model)
        return;
    for (auto it = m_before.cbegin(); it != m_before.cend(); ++it)
        m_model->setLocation(it.key(), it.value());
}

int MoveComponentsCommand::id() const
{
    return MoveComponentsCommandId;
}

bool MoveComponentsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const MoveComponentsCommand *>(other);
    if (!m_mergeable || !next->m_mergeable || next->m_model != m_model
        || next->m_after.keys() != m_after.keys())
        return false;
    m_after = next->m_after;
    return true;
}

QHash<QString, QPointF> alignedPositions(const SystemModel &model,
                                         const QStringList &instanceNames, Alignment alignment)
{
    QHash<QString, QPointF> result;
    if (instanceNames.isEmpty())
        return result;
    const QRectF anchor(model.layout(instanceNames.first()).position,
                        componentSize(model, instanceNames.first()));
    for (const QString &name : instanceNames) {
        const QSizeF size = componentSize(model, name);
        QPointF p = model.layout(name).position;
        switch (alignment) {
        case Alignment::Left:
            p.setX(anchor.left());
            break;
        case Alignment::Right:
            p.setX(anchor.right() - size.width());
            break;
        case Alignment::Top:
            p.setY(anchor.top());
            break;
        case Alignment::Bottom:
            p.setY(anchor.bottom() - size.height());
            break;
        case Alignment::HorizontalCenter:
            p.setX(anchor.center().x() - size.width() / 2);
            break;
        case Alignment::VerticalCenter:
            p.setY(anchor.center().y() - size.height() / 2);
            break;
        }
        result.insert(name, p);
    }
    return result;
}

MoveComponentsCommand *alignComponentsCommand(SystemModel *model,
                                              const QStringList &instanceNames,
                                              Alignment alignment)
{
    if (instanceNames.size() < 2)
        return nullptr;
    return new MoveComponentsCommand(model, alignedPositions(*model, instanceNames, alignment),
                                     MoveComponentsCommand::tr("Align"));
}

// ---- ResizeComponentCommand ----------------------------------------------------------------

ResizeComponentCommand::ResizeComponentCommand(SystemModel *model, const QString &instanceName,
                                               const QSizeF &size, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_name(instanceName)
    , m_after(size)
{
    if (const RtsComponent *c = model->component(instanceName))
        m_before = c->layout;
    setText(tr("Resize %1").arg(instanceName));
}

void ResizeComponentCommand::redo()
{
    if (m_model)
        m_model->resizeComponent(m_name, m_after);
}

void ResizeComponentCommand::undo()
{
    if (m_model)
        m_model->setLocation(m_name, m_before);
}

int ResizeComponentCommand::id() const
{
    return ResizeComponentCommandId;
}

bool ResizeComponentCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const ResizeComponentCommand *>(other);
    if (next->m_model != m_model || next->m_name != m_name)
        return false;
    m_after = next->m_after;
    return true;
}

// ---- RenameComponentCommand ----------------------------------------------------------------

RenameComponentCommand::RenameComponentCommand(SystemModel *model, const QString &oldName,
                                               const QString &newName, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_old(oldName)
    , m_new(newName)
    , m_topLevel(parent == nullptr)
{
    setText(tr("Rename %1 to %2").arg(oldName, newName));
}

void RenameComponentCommand::redo()
{
    m_applied = m_model && m_model->renameComponent(m_old, m_new);
    // QUndoStack::push() drops a command that turned out obsolete, so a refused rename leaves
    // no step behind.
    if (m_topLevel)
        setObsolete(!m_applied);
}

void RenameComponentCommand::undo()
{
    if (m_model && m_applied)
        m_model->renameComponent(m_new, m_old);
}

// ---- SetDirectionCommand -------------------------------------------------------------------

SetDirectionCommand::SetDirectionCommand(SystemModel *model, const QString &instanceName,
                                         Direction direction, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_name(instanceName)
    , m_after(direction)
{
    if (const RtsComponent *c = model->component(instanceName))
        m_before = c->layout;
    setText(tr("Turn %1").arg(instanceName));
}

void SetDirectionCommand::redo()
{
    if (m_model)
        m_model->setDirection(m_name, m_after);
}

void SetDirectionCommand::undo()
{
    if (m_model)
        m_model->setLocation(m_name, m_before);
}

// ---- SetConfigurationSetsCommand -----------------------------------------------------------

SetConfigurationSetsCommand::SetConfigurationSetsCommand(
    SystemModel *model, const QString &instanceName, const QList<RtsConfigurationSet> &sets,
    const std::optional<QString> &activeSet, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_name(instanceName)
    , m_afterSets(sets)
    , m_afterActive(activeSet)
{
    if (const RtsComponent *c = model->component(instanceName)) {
        m_beforeSets = c->configurationSets;
        m_beforeActive = c->activeConfigurationSet;
    }
    setText(tr("Edit configuration of %1").arg(instanceName));
}

void SetConfigurationSetsCommand::redo()
{
    if (m_model)
        m_model->setConfigurationSets(m_name, m_afterSets, m_afterActive);
}

void SetConfigurationSetsCommand::undo()
{
    if (m_model)
        m_model->setConfigurationSets(m_name, m_beforeSets, m_beforeActive);
}

} // namespace SystemEditor
