// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QCoreApplication>

namespace SystemEditor {

/// Whether two ports may be connected, and why not when they may not.
struct ConnectionCheck
{
    bool allowed = false;
    QString reason; ///< empty when allowed
    /// Allowed data connections: the out port's end and the in port's end, in that order.
    ConnectorEnd source;
    ConnectorEnd target;
    ConnectorKind kind = ConnectorKind::Data;

    explicit operator bool() const { return allowed; }
};

/**
 * The reference's connection rules.
 *
 * Data ports connect only an OutPort to an InPort with the same data type, or with any type when
 * one port's data type is "any" (an FSM component's EventInPort); either may be picked first, the
 * result orders them out → in. Service ports connect when at least one interface of
 * one port pairs with an interface of the other: same instance name and opposite polarity
 * (Provided ↔ Required); differing types are for the connector dialog to warn about. Ports of the same component never connect. Ports whose
 * kind is unknown (no RTC profile) are assumed compatible with any data port: the user knows what
 * the file meant.
 */
class ConnectionRules
{
    Q_DECLARE_TR_FUNCTIONS(ConnectionRules)

public:
    /// Checks two ports of the model.
    static ConnectionCheck check(const SystemModel &model, const ConnectorEnd &first,
                                 const ConnectorEnd &second);
    /// Checks two described ports (instance names only matter for the same-component rule).
    static ConnectionCheck check(const ConnectorEnd &firstEnd, const PortInfo &first,
                                 const ConnectorEnd &secondEnd, const PortInfo &second);
    /// Interface pairs (index in `a`, index in `b`) that match by instance name and polarity.
    static QList<QPair<int, int>> matchingInterfaces(const QList<InterfaceInfo> &a,
                                                     const QList<InterfaceInfo> &b);

private:
    static ConnectionCheck checkData(const ConnectorEnd &firstEnd, const PortInfo &first,
                                     const ConnectorEnd &secondEnd, const PortInfo &second);
    static ConnectionCheck checkService(const ConnectorEnd &firstEnd, const PortInfo &first,
                                        const ConnectorEnd &secondEnd, const PortInfo &second);
};

} // namespace SystemEditor
