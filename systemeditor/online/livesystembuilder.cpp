// SPDX-License-Identifier: MIT
#include "livesystembuilder.h"

#include <QSet>

namespace SystemEditor::LiveSystemBuilder {

using namespace Profile;

namespace {

QString instanceOf(const QString &portName)
{
    return portName.section(QLatin1Char('.'), 0, 0);
}

RtcDataPort dataPort(const Corba::PortInfo &port)
{
    RtcDataPort p;
    p.portType = port.portType();
    p.name = port.shortName();
    p.type = Corba::propertyValue(port.properties, QStringLiteral("dataport.data_type"));
    p.position = port.isDataOut() ? QStringLiteral("RIGHT") : QStringLiteral("LEFT");
    return p;
}

RtcServicePort servicePort(const Corba::PortInfo &port)
{
    RtcServicePort p;
    p.name = port.shortName();
    p.position = QStringLiteral("RIGHT");
    for (const Corba::PortInterfaceInfo &i : port.interfaces) {
        RtcServiceInterface iface;
        iface.name = i.instanceName;
        iface.instanceName = i.instanceName;
        iface.type = i.typeName;
        iface.direction = i.provided ? QStringLiteral("Provided") : QStringLiteral("Required");
        p.interfaces.append(iface);
    }
    return p;
}

// Both ends of a live connector: the first two port names that belong to displayed components.
template<typename Connector>
std::vector<Connector> connectors(const std::vector<Corba::PortInfo> &ports,
                                  const QStringList &instances, bool service)
{
    std::vector<Connector> result;
    QSet<QString> seen;
    for (const Corba::PortInfo &port : ports) {
        if (port.isService() != service)
            continue;
        for (const Corba::ConnectorInfo &c : port.connectors) {
            if (seen.contains(c.id) || c.ports.size() < 2)
                continue;
            const QString from = c.ports.at(0);
            const QString to = c.ports.at(1);
            if (!instances.contains(instanceOf(from)) || !instances.contains(instanceOf(to)))
                continue;
            seen.insert(c.id);
            Connector connector;
            connector.connectorId = c.id;
            connector.name = c.name;
            connector.source.instanceName = instanceOf(from);
            connector.source.portName = from;
            connector.target.instanceName = instanceOf(to);
            connector.target.portName = to;
            for (const auto &[key, value] : c.properties) {
                if (!key.contains(QLatin1String("ior"), Qt::CaseInsensitive))
                    setRtsProperty(connector.properties, key, value);
            }
            result.push_back(connector);
        }
    }
    return result;
}

} // namespace

LiveComponentRecord component(const Corba::ComponentInfo &info, const QString &path,
                              const QString &ior)
{
    LiveComponentRecord record;
    RtcProfile &rtc = record.rtc;
    rtc.basicInfo.name = info.typeName;
    rtc.basicInfo.vendor = info.vendor;
    rtc.basicInfo.category = info.category;
    rtc.basicInfo.version = info.version;
    rtc.basicInfo.description = info.description;
    RtsComponent &c = record.component;
    c.instanceName = info.instanceName;
    c.id = QStringLiteral("RTC:%1:%2:%3:%4")
               .arg(info.vendor, info.category, info.typeName, info.version);
    rtc.id = c.id;
    c.pathUri = path;
    setRtsProperty(c.properties, QStringLiteral("IOR"), ior);
    setRtsProperty(c.properties, QStringLiteral("COMPONENT_PATH_ID"), path);
    for (const Corba::PortInfo &port : info.ports) {
        RtsPort listed;
        listed.name = port.name;
        if (port.isService()) {
            rtc.servicePorts.append(servicePort(port));
            c.servicePorts.append(listed);
        } else {
            rtc.dataPorts.append(dataPort(port));
            c.dataPorts.append(listed);
        }
    }
    return record;
}

std::vector<RtsDataPortConnector> dataConnectors(const std::vector<Corba::PortInfo> &ports,
                                                 const QStringList &instances)
{
    return connectors<RtsDataPortConnector>(ports, instances, false);
}

std::vector<RtsServicePortConnector> serviceConnectors(const std::vector<Corba::PortInfo> &ports,
                                                       const QStringList &instances)
{
    return connectors<RtsServicePortConnector>(ports, instances, true);
}

} // namespace SystemEditor::LiveSystemBuilder
