// SPDX-License-Identifier: MIT
#include "portconnection.h"

#include "corbacall.h"

#include <RTC.hh>

#include <QSet>

#include <algorithm>

namespace Corba {

using namespace Internal;

namespace {

const QString dataportPrefix = QStringLiteral("dataport.");

bool isData(const PortInfo &port)
{
    return port.isDataIn() || port.isDataOut();
}

// OpenRTM lists allowed values comma-separated ("push, pull"); "Any" accepts everything.
QStringList listedValues(const PortInfo &port, const QString &key)
{
    QStringList values;
    for (const QString &entry : propertyValue(port.properties, key).split(QLatin1Char(','))) {
        if (!entry.trimmed().isEmpty())
            values.append(entry.trimmed());
    }
    return values;
}

bool allowsAny(const QStringList &listed)
{
    return listed.isEmpty() || listed.contains(QLatin1String("any"), Qt::CaseInsensitive);
}

bool allows(const PortInfo &port, const QString &key, const QString &value)
{
    const QStringList listed = listedValues(port, key);
    return allowsAny(listed) || listed.contains(value, Qt::CaseInsensitive);
}

// rtcon accepts an out port with in ports, or one in port with one out port in either order.
QString directionProblem(const std::vector<PortInfo> &ports)
{
    if (ports.size() == 2 && ports[0].isDataIn() && ports[1].isDataOut())
        return QString();
    if (!ports.front().isDataOut())
        return QStringLiteral("%1 is not an output port").arg(ports.front().name);
    for (size_t i = 1; i < ports.size(); ++i) {
        if (!ports[i].isDataIn())
            return QStringLiteral("%1 is not an input port").arg(ports[i].name);
    }
    return QString();
}

QString dataProblem(const std::vector<PortInfo> &ports, const Properties &properties)
{
    const QString direction = directionProblem(ports);
    if (!direction.isEmpty())
        return direction;
    for (const auto &property : properties) {
        if (!property.first.startsWith(dataportPrefix))
            continue;
        for (const PortInfo &port : ports) {
            if (!allows(port, property.first, property.second))
                return QStringLiteral("%1 does not allow %2=%3 (allowed: %4)")
                    .arg(port.name, property.first, property.second,
                         propertyValue(port.properties, property.first));
        }
    }
    return QString();
}

QString serviceProblem(const std::vector<PortInfo> &ports)
{
    for (size_t i = 1; i < ports.size(); ++i) {
        if (!ports[i].isService())
            return QStringLiteral("%1 is not a service port").arg(ports[i].name);
    }
    for (const PortInterfaceInfo &interface : ports.front().interfaces) {
        for (size_t i = 1; i < ports.size(); ++i) {
            const auto &others = ports[i].interfaces;
            const bool paired = std::any_of(others.begin(), others.end(), [&](const auto &other) {
                return other.instanceName == interface.instanceName
                    && other.provided != interface.provided;
            });
            if (!paired)
                return QStringLiteral("interface '%1' of %2 has no %3 counterpart in %4")
                    .arg(interface.instanceName, ports.front().name,
                         interface.provided ? QStringLiteral("required")
                                            : QStringLiteral("provided"),
                         ports[i].name);
        }
    }
    return QString();
}

QStringList namesOf(const std::vector<PortInfo> &ports)
{
    QStringList names;
    for (const PortInfo &port : ports)
        names.append(port.name);
    return names;
}

QStringList iorsOf(const std::vector<PortInfo> &ports)
{
    QStringList iors;
    for (const PortInfo &port : ports)
        iors.append(port.ior);
    return iors;
}

QSet<QString> asSet(const QStringList &list)
{
    return QSet<QString>(list.begin(), list.end());
}

/**
 * Why ports answered a connect with PRECONDITION_NOT_MET. OpenRTM-aist's ports (and
 * rtmanager's) refuse a second connection between ports already connected unless the connector
 * says `dataport.allow_dup_connection` YES, more connections than a data port takes, and a
 * connector id the port already holds.
 */
QString preconditionReason(const std::vector<PortInfo> &ports)
{
    for (const PortInfo &port : ports) {
        for (const ConnectorInfo &connector : port.connectors) {
            for (const PortInfo &other : ports) {
                if (&other != &port
                    && (connector.portIors.contains(other.ior)
                        || connector.ports.contains(other.name)))
                    return QStringLiteral(
                               "%1 is already connected to %2 (connector %3); "
                               "-p dataport.allow_dup_connection=YES connects them again")
                        .arg(port.name, other.name, connector.id);
            }
        }
    }
    return QStringLiteral(
        "a port has as many connections as it takes (dataport.inport.fan_in, "
        "dataport.outport.fan_out; 100 unless set), or already holds this connector id");
}

RTC::PortService_ptr portService(const PortInfo &port, const QString &path)
{
    CORBA::Object_var object = toObject(port.ior, path);
    return RTC::PortService::_unchecked_narrow(object.in());
}

} // namespace

Properties PortConnection::effectiveProperties(const std::vector<PortInfo> &ports,
                                               const Properties &given)
{
    Properties properties;
    if (!ports.empty() && isData(ports.front())) {
        properties = {{QStringLiteral("dataport.dataflow_type"), QStringLiteral("push")},
                      {QStringLiteral("dataport.interface_type"), QStringLiteral("corba_cdr")},
                      {QStringLiteral("dataport.subscription_type"), QStringLiteral("new")}};
        const PortInfo &source = ports.size() == 2 && ports[1].isDataOut() ? ports[1] : ports[0];
        const QString dataType
            = propertyValue(source.properties, QStringLiteral("dataport.data_type"));
        if (!dataType.isEmpty())
            properties.append({QStringLiteral("dataport.data_type"), dataType});
    }
    for (const auto &property : given)
        setProperty(properties, property.first, property.second);
    return properties;
}

QString PortConnection::problem(const std::vector<PortInfo> &ports, const Properties &properties)
{
    if (ports.size() < 2)
        return QStringLiteral("a connection needs at least two ports");
    if (isData(ports.front()))
        return dataProblem(ports, properties);
    if (ports.front().isService())
        return serviceProblem(ports);
    return QStringLiteral("%1 has an unknown port type '%2'")
        .arg(ports.front().name, ports.front().portType());
}

QStringList PortConnection::commonValues(const std::vector<PortInfo> &ports, const QString &key)
{
    QStringList common;
    for (const PortInfo &port : ports) {
        const QStringList listed = listedValues(port, key);
        if (allowsAny(listed))
            continue;
        for (const QString &value : listed) {
            if (std::all_of(ports.begin(), ports.end(),
                            [&](const PortInfo &other) { return allows(other, key, value); }))
                common.append(value);
        }
        break;
    }
    return common;
}

QString PortConnection::defaultName(const std::vector<PortInfo> &ports)
{
    QStringList names;
    for (const PortInfo &port : ports)
        names.append(port.shortName());
    return names.join(QLatin1Char('_'));
}

ConnectorInfo PortConnection::connect(const std::vector<PortInfo> &ports,
                                      const ConnectionRequest &request, const QString &path)
{
    const Properties properties = effectiveProperties(ports, request.properties);
    const QString why = problem(ports, properties);
    if (!why.isEmpty())
        throw Error(Error::Kind::Incompatible,
                    QStringLiteral("%1: cannot connect: %2").arg(path, why));
    if (request.noDuplicates) {
        // The same ports: by reference, or by name when every end still answers (a connector left
        // to a port whose process has gone does not count, even when a new port of the same name
        // has taken its place).
        const QSet<QString> wanted = asSet(iorsOf(ports));
        const QSet<QString> wantedNames = asSet(namesOf(ports));
        for (const ConnectorInfo &connector : ports.front().connectors) {
            if (asSet(connector.portIors) == wanted
                || (asSet(connector.ports) == wantedNames && !hasEndGone(connector)))
                throw Error(
                    Error::Kind::Refused,
                    QStringLiteral("%1: already connected (connector %2)").arg(path, connector.id));
        }
    }
    return connectAsGiven(ports, request.name.isEmpty() ? defaultName(ports) : request.name,
                          request.id, properties, path);
}

ConnectorInfo PortConnection::connectAsGiven(const std::vector<PortInfo> &ports, const QString &name,
                                             const QString &id, const Properties &properties,
                                             const QString &path)
{
    RTC::ConnectorProfile profile;
    profile.name = name.toUtf8().constData();
    profile.connector_id = id.toUtf8().constData();
    profile.properties = toNVList(properties);
    profile.ports.length(CORBA::ULong(ports.size()));
    for (size_t i = 0; i < ports.size(); ++i)
        profile.ports[CORBA::ULong(i)] = portService(ports[i], path);
    RTC::PortService_var source = portService(ports.front(), path);
    const int code = call(path, [&] { return int(source->connect(profile)); });
    if (code == int(RTC::PRECONDITION_NOT_MET))
        throw Error(Error::Kind::Refused,
                    QStringLiteral("%1: connect returned PRECONDITION_NOT_MET: %2")
                        .arg(path, preconditionReason(ports)));
    checkReturnCode(code, path, QStringLiteral("connect"));
    return {toQString(profile.name.in()), toQString(profile.connector_id.in()), namesOf(ports),
            fromNVList(profile.properties), iorsOf(ports)};
}

void PortConnection::disconnect(const PortInfo &port, const QString &connectorId,
                                const QString &path)
{
    RTC::PortService_var service = portService(port, path);
    const QByteArray id = connectorId.toUtf8();
    checkReturnCode(call(path, [&] { return int(service->disconnect(id.constData())); }), path,
                    QStringLiteral("disconnect(%1)").arg(connectorId));
}

void PortConnection::disconnectAll(const PortInfo &port, const QString &path)
{
    RTC::PortService_var service = portService(port, path);
    checkReturnCode(call(path, [&] { return int(service->disconnect_all()); }), path,
                    QStringLiteral("disconnect_all"));
}

bool PortConnection::hasEndGone(const ConnectorInfo &connector)
{
    for (const QString &ior : connector.portIors) {
        try {
            CORBA::Object_var end = toObject(ior, connector.id);
            if (call(connector.id, [&] { return bool(end->_non_existent()); }))
                return true;
        } catch (const Error &) {
            return true;
        }
    }
    return false;
}

} // namespace Corba
