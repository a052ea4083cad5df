// SPDX-License-Identifier: MIT
#include "rtconnectcommand.h"

#include "corbaerror.h"
#include "portconnection.h"

#include <QSet>

namespace Cli {

using namespace Corba;

QString RtConnectCommand::summary() const
{
    return m_connect ? QStringLiteral("connect ports") : QStringLiteral("disconnect ports");
}

QString RtConnectCommand::usage() const
{
    if (m_connect)
        return QStringLiteral(
            "Usage: rtctl con [-n NAME] [-i ID] [-p KEY=VALUE]... [--no-duplicates] [--timeout "
            "MS]\n"
            "                 SRC:PORT DST:PORT [DST:PORT...]\n\n"
            "Connects ports (rtshell's rtcon) and prints the connector id.\n"
            "Data ports connect out to in only; defaults dataport.dataflow_type=push,\n"
            "dataport.interface_type=corba_cdr, dataport.subscription_type=new and "
            "dataport.data_type\n"
            "of the output port; every dataport.* value must be allowed by each port unless the "
            "port\n"
            "says 'any'. Service ports: each interface must meet one with the same instance name "
            "and\n"
            "the opposite polarity. Refused pairs are reported with the reason (exit code 1).\n"
            "  -n NAME          connector name (default: the ports' short names joined by '_')\n"
            "  -i ID            connector id (default: chosen by the port)\n"
            "  -p KEY=VALUE     connector property; repeatable\n"
            "  --no-duplicates  fail when the ports are already connected\n");
    return QStringLiteral(
        "Usage: rtctl dis [-i ID] [--timeout MS] PATH[:PORT] [PATH:PORT...]\n\n"
        "Disconnects (rtshell's rtdis): a component alone loses every connection of every port;\n"
        "one PATH:PORT loses all its connections (or only connector ID with -i); several\n"
        "PATH:PORTs lose the connectors that link all of them.\n");
}

QStringList RtConnectCommand::flagNames() const
{
    return m_connect ? QStringList {QStringLiteral("--no-duplicates")} : QStringList();
}

QStringList RtConnectCommand::optionNames() const
{
    if (m_connect)
        return {QStringLiteral("-n"), QStringLiteral("-i"), QStringLiteral("-p")};
    return {QStringLiteral("-i")};
}

int RtConnectCommand::execute(const RtOptions &options, Streams streams)
{
    return m_connect ? connect(options, streams) : disconnect(options, streams);
}

std::vector<PortInfo> RtConnectCommand::ports(const QStringList &texts) const
{
    std::vector<PortInfo> result;
    for (const QString &text : texts) {
        const RtPath target = path(text);
        if (target.port.isEmpty())
            throw Error(Error::Kind::BadPath,
                        target.toString() + QStringLiteral(": no :PORT given"));
        result.push_back(component(target).port(target.port));
    }
    return result;
}

int RtConnectCommand::connect(const RtOptions &options, Streams streams)
{
    if (options.positionals.size() < 2)
        return usageError(QStringLiteral("con needs a source and at least one destination port"),
                          streams);
    ConnectionRequest request;
    request.name = options.value(QStringLiteral("-n"));
    request.id = options.value(QStringLiteral("-i"));
    request.noDuplicates = options.has(QStringLiteral("--no-duplicates"));
    for (const QString &property : options.values.value(QStringLiteral("-p"))) {
        const int equals = property.indexOf(QLatin1Char('='));
        if (equals <= 0)
            return usageError(QStringLiteral("-p needs KEY=VALUE, got '%1'").arg(property),
                              streams);
        request.properties.append({property.left(equals), property.mid(equals + 1)});
    }
    const std::vector<PortInfo> portList = ports(options.positionals);
    const ConnectorInfo made
        = PortConnection::connect(portList, request, path(options.positionals.first()).toString());
    streams.out << made.id << '\n';
    return ExitOk;
}

int RtConnectCommand::disconnect(const RtOptions &options, Streams streams)
{
    if (options.positionals.isEmpty())
        return usageError(QStringLiteral("dis needs at least one PATH"), streams);
    const QString id = options.value(QStringLiteral("-i"));
    const RtPath first = path(options.positionals.first());
    if (options.positionals.size() == 1 && first.port.isEmpty()) {
        if (!id.isEmpty())
            return usageError(QStringLiteral("-i needs a PATH:PORT"), streams);
        for (const PortInfo &port : component(first).ports())
            PortConnection::disconnectAll(port,
                                          first.toString() + QLatin1Char(':') + port.shortName());
        return ExitOk;
    }
    const std::vector<PortInfo> portList = ports(options.positionals);
    if (portList.size() == 1 && id.isEmpty()) {
        PortConnection::disconnectAll(portList.front(), first.toString());
        return ExitOk;
    }
    QSet<QString> wanted;
    for (const PortInfo &port : portList)
        wanted.insert(port.name);
    int disconnected = 0;
    for (const ConnectorInfo &connector : portList.front().connectors) {
        const QSet<QString> linked(connector.ports.begin(), connector.ports.end());
        if ((id.isEmpty() || connector.id == id) && linked.contains(wanted)) {
            PortConnection::disconnect(portList.front(), connector.id, first.toString());
            ++disconnected;
        }
    }
    if (disconnected == 0)
        throw Error(Error::Kind::NotFound,
                    first.toString()
                        + (id.isEmpty() ? QStringLiteral(": no such connection")
                                        : QStringLiteral(": no connector '%1'").arg(id)));
    return ExitOk;
}

} // namespace Cli
