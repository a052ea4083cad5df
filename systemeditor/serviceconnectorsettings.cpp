// SPDX-License-Identifier: MIT
#include "serviceconnectorsettings.h"

#include "connectorsettings.h"

#include <algorithm>
#include <tuple>

namespace SystemEditor {

using namespace Profile;

namespace {

const QString Required = QStringLiteral("required");
const QString Provided = QStringLiteral("provided");
const QString PortWord = QStringLiteral("port");

} // namespace

InterfaceDescriptor InterfaceDescriptor::of(const ServicePortSide &side,
                                            const InterfaceInfo &interface)
{
    InterfaceDescriptor d;
    d.componentName = side.instanceName;
    d.portName = side.portName;
    d.required = interface.polarity != RtcDirection::Provided;
    d.type = interface.type;
    d.instanceName = interface.instanceName;
    return d;
}

std::optional<InterfaceDescriptor> InterfaceDescriptor::parse(const QString &text)
{
    const QStringList parts = text.split(QLatin1Char('.'));
    InterfaceDescriptor d;
    if (parts.size() == 3 && parts.at(0) == PortWord) {
        d.type = parts.at(1);
        d.instanceName = parts.at(2);
        return d;
    }
    // The reference's check: six parts, `port` second, a polarity fourth.
    if (parts.size() != 6 || parts.at(1) != PortWord
        || (parts.at(3) != Required && parts.at(3) != Provided))
        return std::nullopt;
    d.componentName = parts.at(0);
    d.portName = parts.at(2);
    d.required = parts.at(3) == Required;
    d.type = parts.at(4);
    d.instanceName = parts.at(5);
    return d;
}

QString InterfaceDescriptor::toString() const
{
    if (componentName.isEmpty() && portName.isEmpty())
        return QStringList {PortWord, type, instanceName}.join(QLatin1Char('.'));
    return QStringList {componentName, PortWord,   portName, required ? Required : Provided,
                        type,          instanceName}
        .join(QLatin1Char('.'));
}

bool InterfaceDescriptor::names(const ServicePortSide &side, const InterfaceInfo &interface) const
{
    const InterfaceDescriptor other = of(side, interface);
    if (type != other.type || instanceName != other.instanceName || required != other.required)
        return false;
    const bool shortForm = componentName.isEmpty() && portName.isEmpty();
    return shortForm
        || (componentName == other.componentName && portName == other.portName);
}

ServiceConnectorSettings
ServiceConnectorSettings::fromConnector(const RtsServicePortConnector &connector)
{
    ServiceConnectorSettings s;
    s.name = connector.name;
    s.connectingPort = {connector.source.instanceName, connector.source.portName};
    for (const RtsProperty &property : connector.properties) {
        if (isMappingKey(property.name))
            s.mapping.append({property.name, property.value.value_or(QString())});
    }
    // One order for comparing with what the dialog gives back.
    std::sort(s.mapping.begin(), s.mapping.end());
    return s;
}

void ServiceConnectorSettings::applyTo(RtsServicePortConnector &connector) const
{
    connector.name = name;
    if (isSamePort(connector.target, connectingPort)
        && !isSamePort(connector.source, connectingPort))
        reverseConnectorEnds(connector);
    // As the reference: every mapping property goes, the dialog's entries come back.
    connector.properties.removeIf(
        [](const RtsProperty &property) { return isMappingKey(property.name); });
    for (const auto &[consumer, provider] : mapping)
        setRtsProperty(connector.properties, consumer, provider);
}

bool ServiceConnectorSettings::isSamePort(const RtsTargetPort &end, const ConnectorEnd &port)
{
    if (port.instanceName.isEmpty() || end.instanceName != port.instanceName)
        return false;
    // OpenRTM names ports `<instance>.<port>`; the dialog knows them without the prefix.
    const QString prefix = port.instanceName + QLatin1Char('.');
    const auto bare = [&prefix](const QString &name) {
        return name.startsWith(prefix) ? name.mid(prefix.size()) : name;
    };
    return bare(end.portName) == bare(port.portName);
}

bool ServiceConnectorSettings::isMappingKey(const QString &key)
{
    const std::optional<InterfaceDescriptor> d = InterfaceDescriptor::parse(key);
    return d && d->required;
}

QStringList ServiceConnectorSettings::validate() const
{
    QStringList problems;
    if (name.trimmed().isEmpty() || name.size() > ConnectorSettings::MaxNameLength)
        problems << tr("The name must have 1 to %1 characters.")
                        .arg(ConnectorSettings::MaxNameLength);
    return problems;
}

bool ServiceConnectorSettings::operator==(const ServiceConnectorSettings &other) const
{
    return std::tie(name, mapping, connectingPort)
        == std::tie(other.name, other.mapping, other.connectingPort);
}

} // namespace SystemEditor
