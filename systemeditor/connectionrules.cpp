// SPDX-License-Identifier: MIT
#include "connectionrules.h"

namespace SystemEditor {

namespace {

ConnectionCheck refused(const QString &reason)
{
    ConnectionCheck check;
    check.reason = reason;
    return check;
}

bool opposite(Profile::RtcDirection a, Profile::RtcDirection b)
{
    using Profile::RtcDirection;
    return (a == RtcDirection::Provided && b == RtcDirection::Required)
        || (a == RtcDirection::Required && b == RtcDirection::Provided);
}

// An InPort of data type "any" (an FSM component's EventInPort) takes samples of every type.
bool takesAnyType(const PortInfo &port)
{
    return port.dataType.compare(QLatin1String("any"), Qt::CaseInsensitive) == 0;
}

} // namespace

ConnectionCheck ConnectionRules::check(const SystemModel &model, const ConnectorEnd &first,
                                       const ConnectorEnd &second)
{
    const std::optional<PortInfo> a = model.port(first.instanceName, first.portName);
    const std::optional<PortInfo> b = model.port(second.instanceName, second.portName);
    if (!a)
        return refused(tr("Port %1 of %2 does not exist.").arg(first.portName, first.instanceName));
    if (!b)
        return refused(
            tr("Port %1 of %2 does not exist.").arg(second.portName, second.instanceName));
    return check(first, *a, second, *b);
}

ConnectionCheck ConnectionRules::check(const ConnectorEnd &firstEnd, const PortInfo &first,
                                       const ConnectorEnd &secondEnd, const PortInfo &second)
{
    if (firstEnd.instanceName == secondEnd.instanceName)
        return refused(tr("Ports of the same component cannot be connected."));
    const bool firstService = first.kind == PortKind::Service;
    const bool secondService = second.kind == PortKind::Service;
    if (firstService != secondService)
        return refused(tr("A data port cannot be connected to a service port."));
    return firstService ? checkService(firstEnd, first, secondEnd, second)
                        : checkData(firstEnd, first, secondEnd, second);
}

ConnectionCheck ConnectionRules::checkData(const ConnectorEnd &firstEnd, const PortInfo &first,
                                           const ConnectorEnd &secondEnd, const PortInfo &second)
{
    if (first.kind == PortKind::DataIn && second.kind == PortKind::DataIn)
        return refused(tr("Two InPorts cannot be connected; connect an OutPort to an InPort."));
    if (first.kind == PortKind::DataOut && second.kind == PortKind::DataOut)
        return refused(tr("Two OutPorts cannot be connected; connect an OutPort to an InPort."));
    const bool known = first.kind != PortKind::Unknown && second.kind != PortKind::Unknown;
    if (known && first.dataType != second.dataType && !takesAnyType(first)
        && !takesAnyType(second)) {
        return refused(tr("The data types differ: %1 and %2.")
                           .arg(first.dataType, second.dataType));
    }
    ConnectionCheck result;
    result.allowed = true;
    result.kind = ConnectorKind::Data;
    // The out port is the source; with an unknown port, the known one decides, else pick order.
    const bool firstIsSource = first.kind == PortKind::DataOut || second.kind == PortKind::DataIn
        || (first.kind == PortKind::Unknown && second.kind == PortKind::Unknown);
    result.source = firstIsSource ? firstEnd : secondEnd;
    result.target = firstIsSource ? secondEnd : firstEnd;
    return result;
}

ConnectionCheck ConnectionRules::checkService(const ConnectorEnd &firstEnd,
                                              const PortInfo &first,
                                              const ConnectorEnd &secondEnd,
                                              const PortInfo &second)
{
    // Ports the RTC profile does not describe have no interfaces to compare.
    if (first.described && second.described
        && matchingInterfaces(first.interfaces, second.interfaces).isEmpty()) {
        return refused(tr("No interface of %1 pairs with one of %2 (same instance name, "
                          "one provided and one required).")
                           .arg(first.name, second.name));
    }
    ConnectionCheck result;
    result.allowed = true;
    result.kind = ConnectorKind::Service;
    result.source = firstEnd;
    result.target = secondEnd;
    return result;
}

QList<QPair<int, int>> ConnectionRules::matchingInterfaces(const QList<InterfaceInfo> &a,
                                                           const QList<InterfaceInfo> &b)
{
    QList<QPair<int, int>> pairs;
    for (int i = 0; i < a.size(); ++i) {
        for (int j = 0; j < b.size(); ++j) {
            if (opposite(a.at(i).polarity, b.at(j).polarity)
                && a.at(i).instanceName == b.at(j).instanceName)
                pairs.append({i, j});
        }
    }
    return pairs;
}

} // namespace SystemEditor
