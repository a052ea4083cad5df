// SPDX-License-Identifier: MIT
#include "connectorcommands.h"

#include "systemcommandids.h"

#include <QUuid>

namespace SystemEditor {

using namespace Profile;

namespace {

RtsTargetPort targetPort(const SystemModel &model, const ConnectorEnd &end)
{
    RtsTargetPort port;
    port.instanceName = end.instanceName;
    port.portName = end.portName;
    if (const RtsComponent *component = model.component(end.instanceName)) {
        port.componentId = component->id;
        // The reference keeps the component's path with each end.
        if (!component->pathUri.isEmpty())
            setRtsProperty(port.properties, QStringLiteral("COMPONENT_PATH_ID"),
                           component->pathUri);
    }
    return port;
}

QString shortName(const QString &portName)
{
    return portName.mid(portName.lastIndexOf(QLatin1Char('.')) + 1);
}

} // namespace

QString newConnectorId()
{
    return QUuid::createUuid().toString(QUuid::WithoutBraces);
}

RtsDataPortConnector makeDataConnector(const SystemModel &model, const ConnectorEnd &source,
                                       const ConnectorEnd &target,
                                       const ConnectorSettings &settings)
{
    RtsDataPortConnector connector;
    connector.connectorId = newConnectorId();
    connector.source = targetPort(model, source);
    connector.target = targetPort(model, target);
    connector.visible = QStringLiteral("true");
    settings.applyTo(connector, &model);
    return connector;
}

RtsServicePortConnector makeServiceConnector(const SystemModel &model, const ConnectorEnd &source,
                                             const ConnectorEnd &target, const QString &name)
{
    RtsServicePortConnector connector;
    connector.connectorId = newConnectorId();
    connector.name = name.isEmpty()
        ? shortName(source.portName) + QLatin1Char('_') + shortName(target.portName)
        : name;
    connector.source = targetPort(model, source);
    connector.target = targetPort(model, target);
    connector.visible = QStringLiteral("true");
    return connector;
}

RtsServicePortConnector makeServiceConnector(const SystemModel &model, const ConnectorEnd &source,
                                             const ConnectorEnd &target,
                                             const ServiceConnectorSettings &settings)
{
    RtsServicePortConnector connector = makeServiceConnector(model, source, target, settings.name);
    settings.applyTo(connector);
    return connector;
}

// ---- ConnectCommand ------------------------------------------------------------------------

ConnectCommand::ConnectCommand(SystemModel *model, const RtsDataPortConnector &connector,
                               QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_id(connector.connectorId)
    , m_data(connector)
    , m_topLevel(parent == nullptr)
{
    setText(tr("Connect %1").arg(connector.name));
}

ConnectCommand::ConnectCommand(SystemModel *model, const RtsServicePortConnector &connector,
                               QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_id(connector.connectorId)
    , m_service(connector)
    , m_topLevel(parent == nullptr)
{
    setText(tr("Connect %1").arg(connector.name));
}

void ConnectCommand::redo()
{
    m_applied = m_model
        && (m_data ? m_model->addDataConnector(*m_data)
                   : m_service && m_model->addServiceConnector(*m_service));
    // A refused top-level connect is dropped by QUndoStack::push(); inside a macro it just does
    // nothing.
    if (m_topLevel)
        setObsolete(!m_applied);
}

void ConnectCommand::undo()
{
    if (m_model && m_applied)
        m_model->removeConnector(m_id);
}

// ---- DisconnectCommand ---------------------------------------------------------------------

DisconnectCommand::DisconnectCommand(SystemModel *model, const QString &connectorId,
                                     QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_id(connectorId)
{
    m_index = model->connectorIndex(connectorId);
    if (const RtsDataPortConnector *c = model->dataConnector(connectorId))
        m_data = *c;
    else if (const RtsServicePortConnector *s = model->serviceConnector(connectorId))
        m_service = *s;
    const QString name = m_data ? m_data->name : m_service ? m_service->name : connectorId;
    setText(tr("Disconnect %1").arg(name));
}

void DisconnectCommand::redo()
{
    if (m_model)
        m_model->removeConnector(m_id);
}

void DisconnectCommand::undo()
{
    if (!m_model)
        return;
    if (m_data)
        m_model->addDataConnector(*m_data, m_index);
    else if (m_service)
        m_model->addServiceConnector(*m_service, m_index);
}

// ---- EditConnectorCommand ------------------------------------------------------------------

EditConnectorCommand::EditConnectorCommand(SystemModel *model, const RtsDataPortConnector &after,
                                           QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_dataAfter(after)
{
    if (const RtsDataPortConnector *c = model->dataConnector(after.connectorId))
        m_dataBefore = *c;
    setText(tr("Edit connector %1").arg(after.name));
}

EditConnectorCommand::EditConnectorCommand(SystemModel *model,
                                           const RtsServicePortConnector &after,
                                           QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_serviceAfter(after)
{
    if (const RtsServicePortConnector *c = model->serviceConnector(after.connectorId))
        m_serviceBefore = *c;
    setText(tr("Edit connector %1").arg(after.name));
}

EditConnectorCommand *EditConnectorCommand::fromSettings(SystemModel *model,
                                                         const QString &connectorId,
                                                         const ConnectorSettings &settings)
{
    const RtsDataPortConnector *current = model->dataConnector(connectorId);
    if (!current)
        return nullptr;
    RtsDataPortConnector after = *current;
    settings.applyTo(after, model);
    return new EditConnectorCommand(model, after);
}

EditConnectorCommand *EditConnectorCommand::fromSettings(SystemModel *model,
                                                         const QString &connectorId,
                                                         const ServiceConnectorSettings &settings)
{
    const RtsServicePortConnector *current = model->serviceConnector(connectorId);
    if (!current)
        return nullptr;
    RtsServicePortConnector after = *current;
    settings.applyTo(after);
    return new EditConnectorCommand(model, after);
}

void EditConnectorCommand::redo()
{
    if (!m_model)
        return;
    if (m_dataBefore && m_dataAfter)
        m_model->setDataConnector(*m_dataAfter);
    else if (m_serviceBefore && m_serviceAfter)
        m_model->setServiceConnector(*m_serviceAfter);
}

void EditConnectorCommand::undo()
{
    if (!m_model)
        return;
    if (m_dataBefore)
        m_model->setDataConnector(*m_dataBefore);
    else if (m_serviceBefore)
        m_model->setServiceConnector(*m_serviceBefore);
}

// ---- SetBendPointsCommand ------------------------------------------------------------------

SetBendPointsCommand::SetBendPointsCommand(SystemModel *model, const QString &connectorId,
                                           const QList<QPointF> &points, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_id(connectorId)
    , m_after(points)
{
    if (const std::optional<ConnectorInfo> info = model->connector(connectorId))
        m_before = info->bendPoints;
    setText(tr("Edit bend points"));
}

void SetBendPointsCommand::redo()
{
    if (m_model)
        m_model->setBendPoints(m_id, m_after);
}

void SetBendPointsCommand::undo()
{
    if (m_model)
        m_model->setBendPoints(m_id, m_before);
}

int SetBendPointsCommand::id() const
{
    return BendPointsCommandId;
}

bool SetBendPointsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SetBendPointsCommand *>(other);
    if (next->m_model != m_model || next->m_id != m_id)
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

} // namespace SystemEditor
