// SPDX-License-Identifier: MIT
#include "rtjson.h"

namespace Cli {

using namespace Corba;

QJsonObject propertiesToJson(const Properties &properties)
{
    QJsonObject object;
    for (const auto &property : properties)
        object.insert(property.first, property.second);
    return object;
}

QJsonObject connectorToJson(const ConnectorInfo &connector)
{
    return {{"name", connector.name},
            {"id", connector.id},
            {"ports", QJsonArray::fromStringList(connector.ports)},
            {"properties", propertiesToJson(connector.properties)}};
}

QJsonObject portToJson(const PortInfo &port)
{
    QJsonArray interfaces;
    for (const PortInterfaceInfo &interface : port.interfaces) {
        interfaces.append(QJsonObject {{"instanceName", interface.instanceName},
                                       {"typeName", interface.typeName},
                                       {"polarity", interface.provided ? "provided" : "required"}});
    }
    QJsonArray connectors;
    for (const ConnectorInfo &connector : port.connectors)
        connectors.append(connectorToJson(connector));
    return {{"name", port.shortName()}, {"fullName", port.name},
            {"type", port.portType()},  {"interfaces", interfaces},
            {"connectors", connectors}, {"properties", propertiesToJson(port.properties)}};
}

QJsonObject contextToJson(const ExecutionContextInfo &context)
{
    return {{"handle", context.handle},   {"owned", context.owned},
            {"kind", context.kind},       {"rate", context.rate},
            {"running", context.running}, {"state", stateName(context.state)}};
}

QJsonObject componentToJson(const ComponentInfo &component)
{
    QJsonArray ports;
    for (const PortInfo &port : component.ports)
        ports.append(portToJson(port));
    return {{"instanceName", component.instanceName},
            {"typeName", component.typeName},
            {"description", component.description},
            {"version", component.version},
            {"vendor", component.vendor},
            {"category", component.category},
            {"properties", propertiesToJson(component.properties)},
            {"ports", ports}};
}

QJsonObject nodeToJson(const NamingNode &node)
{
    QJsonObject object {
        {"name", node.name}, {"path", node.path}, {"type", nodeTypeName(node.type)}};
    if (!node.reason.isEmpty())
        object.insert("reason", node.reason);
    if (!node.answering)
        object.insert("answering", false);
    if (!node.children.empty()) {
        QJsonArray children;
        for (const NamingNode &child : node.children)
            children.append(nodeToJson(child));
        object.insert("children", children);
    }
    return object;
}

PortCounts countPorts(const std::vector<PortInfo> &ports)
{
    PortCounts counts;
    for (const PortInfo &port : ports) {
        const int connected = port.connectors.empty() ? 0 : 1;
        ++counts.total;
        counts.connected += connected;
        if (port.isDataIn()) {
            ++counts.in;
            counts.inConnected += connected;
        } else if (port.isDataOut()) {
            ++counts.out;
            counts.outConnected += connected;
        } else if (port.isService()) {
            ++counts.service;
            counts.serviceConnected += connected;
        }
    }
    return counts;
}

} // namespace Cli
