// SPDX-License-Identifier: MIT
// Live connect and disconnect of the online diagram.
#include "onlinediagram.h"

#include "connectionrules.h"
#include "connectoritem.h"
#include "iorendpoint.h"
#include "onlinesession.h"
#include "portconnection.h"
#include "systemmodel.h"
#include "systemscene.h"

#include <QLabel>

namespace SystemEditor {

std::optional<Corba::PortInfo> OnlineDiagram::livePort(const QString &portName) const
{
    const QString instance = portName.section(QLatin1Char('.'), 0, 0);
    for (const Corba::PortInfo &port : m_live.value(instance).ports) {
        if (port.name == portName)
            return port;
    }
    return std::nullopt;
}

ConnectorDialog::Choices OnlineDiagram::choicesFor(const QString &outPort,
                                                   const QString &inPort) const
{
    ConnectorDialog::Choices choices;
    const auto out = livePort(outPort);
    const auto in = livePort(inPort);
    if (!out || !in)
        return choices;
    // What both ports allow of what the dialog offers (OpenRTM-aist's OutPorts also list `block`
    // and `nonblock`, its other names for flush and new); the dialog's whole list where they say
    // nothing or disagree (the connect then reports why).
    auto both = [&](const QStringList &offered, const char *key) {
        QStringList common
            = Corba::PortConnection::commonValues({*out, *in}, QString::fromLatin1(key));
        common.removeIf([&](const QString &value) { return !offered.contains(value); });
        return common.isEmpty() ? offered : common;
    };
    choices.interfaceTypes = both(choices.interfaceTypes, "dataport.interface_type");
    choices.dataflowTypes = both(choices.dataflowTypes, "dataport.dataflow_type");
    choices.subscriptionTypes = both(choices.subscriptionTypes, "dataport.subscription_type");
    return choices;
}

void OnlineDiagram::requestConnection(const ConnectionCheck &check)
{
    const QString source = check.source.portName;
    const QString target = check.target.portName;
    const auto out = livePort(source);
    if (!out)
        return;
    ConnectorSettings proposed = ConnectorSettings::defaults(
        out->shortName(), target.section(QLatin1Char('.'), 1),
        Corba::propertyValue(out->properties, QStringLiteral("dataport.data_type")));
    if (check.kind == ConnectorKind::Service) {
        connectLive(source, target, proposed);
        return;
    }
    const ConnectorDialog::Choices choices = choicesFor(source, target);
    if (!choices.interfaceTypes.contains(proposed.interfaceType))
        proposed.interfaceType = choices.interfaceTypes.value(0);
    if (!choices.dataflowTypes.contains(proposed.dataflowType))
        proposed.dataflowType = choices.dataflowTypes.value(0);
    if (!choices.subscriptionTypes.contains(proposed.subscriptionType))
        proposed.subscriptionType = choices.subscriptionTypes.value(0);
    std::optional<ConnectorSettings> settings;
    if (m_connectorEditor) {
        settings = m_connectorEditor(proposed, choices);
    } else {
        ConnectorDialog dialog(proposed, choices, this);
        if (dialog.exec() == QDialog::Accepted)
            settings = dialog.settings();
    }
    if (settings)
        connectLive(source, target, *settings);
}

void OnlineDiagram::submitConnection(const QString &host, const std::function<void()> &call)
{
    m_session->submit(
        host,
        [call] {
            call();
            return QVariant();
        },
        this,
        [this](const OnlineResult &result) {
            if (!result.ok)
                m_status->setText(result.error);
            emit connectionFinished(result.ok ? QString() : result.error);
            // The connector is drawn from what the ports report: read them now, not in a few
            // rounds.
            markPortsStale();
            poll();
        });
}

void OnlineDiagram::connectLive(const QString &sourcePort, const QString &targetPort,
                                const ConnectorSettings &settings)
{
    const auto source = livePort(sourcePort);
    const auto target = livePort(targetPort);
    if (!source || !target)
        return;
    Corba::ConnectionRequest request;
    request.name = settings.name;
    if (!source->isService()) {
        // The same dataport.* keys the offline editor writes into a system file.
        Profile::RtsDataPortConnector written;
        settings.applyTo(written);
        for (const Profile::RtsProperty &p : written.properties) {
            if (p.value && !p.value->isEmpty())
                Corba::setProperty(request.properties, p.name, *p.value);
        }
    }
    const std::vector<Corba::PortInfo> ports {*source, *target};
    const QString path = m_live.value(sourcePort.section(QLatin1Char('.'), 0, 0)).path;
    const QString endpoint = Corba::iorEndpoint(source->ior);
    submitConnection(endpoint.isEmpty() ? path : endpoint, [ports, request, path] {
        Corba::PortConnection::connect(ports, request, path);
    });
}

void OnlineDiagram::disconnectLive(const QString &connectorId)
{
    const auto connector = m_model->connector(connectorId);
    if (!connector)
        return;
    const auto port = livePort(connector->source.portName);
    if (!port)
        return;
    const QString path = m_live.value(connector->source.instanceName).path;
    const Corba::PortInfo through = *port;
    const QString endpoint = Corba::iorEndpoint(through.ior);
    submitConnection(endpoint.isEmpty() ? path : endpoint, [through, connectorId, path] {
        Corba::PortConnection::disconnect(through, connectorId, path);
    });
}

} // namespace SystemEditor
