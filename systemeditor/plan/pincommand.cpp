// SPDX-License-Identifier: MIT
#include "pincommand.h"

#include "deployer.h"
#include "requirements.h"

namespace SystemEditor {

PinComponentCommand::PinComponentCommand(SystemModel *model, const QString &instanceName,
                                         const QString &node, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_instance(instanceName)
{
    if (const Profile::RtsComponent *component = model->component(instanceName))
        m_before = Profile::rtsPropertyValue(component->properties, Planner::Key::Pin);
    if (!node.isEmpty())
        m_after = node;
    setText(node.isEmpty() ? tr("Free %1").arg(instanceName)
                           : tr("Pin %1 to %2").arg(instanceName, node));
}

void PinComponentCommand::redo()
{
    apply(m_after);
}

void PinComponentCommand::undo()
{
    apply(m_before);
}

void PinComponentCommand::apply(const std::optional<QString> &pin)
{
    const Profile::RtsComponent *current = m_model ? m_model->component(m_instance) : nullptr;
    if (!current)
        return;
    Profile::RtsComponent component = *current;
    if (pin)
        Profile::setRtsProperty(component.properties, Planner::Key::Pin, *pin);
    else
        component.properties.removeIf([](const Profile::RtsProperty &p) { return p.name == Planner::Key::Pin; });
    m_model->setComponent(component);
}

QString pinnedNode(const SystemModel &model, const QString &instanceName)
{
    const Profile::RtsComponent *component = model.component(instanceName);
    return component ? Deploy::pinOf(*component) : QString();
}

} // namespace SystemEditor
