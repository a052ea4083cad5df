// SPDX-License-Identifier: MIT
#pragma once

// Shared by the deployment benchmarks: a system of OpenRTM's example components to restore onto
// live managers.

#include "rtsprofile.h"

#include <functional>

namespace Bench {

/// Where a generated component goes: its name server (`host:port`) and host context.
struct Placement
{
    QString server;
    QString host;
};

/**
 * `pairs` ConsoleIn sources `Src<i>` and ConsoleOut sinks `Snk<i>`, source i connected to sinks
 * i … i + fanOut - 1 (TimedLong, push). `placement(k)` places component k: sources are the even
 * k = 2i, sinks the odd k = 2i + 1. Each has one periodic context at `rate` Hz.
 */
inline Profile::RtsProfile liveSystem(const QString &name, int pairs, int fanOut,
                                      const std::function<Placement(int)> &placement,
                                      const QString &rate, const QString &subscription)
{
    const auto component = [&rate](const Placement &where, const QString &type, const QString &instance,
                                   const QString &port) {
        Profile::RtsComponent c;
        c.id = QStringLiteral("RTC:AIST:example:%1:2.0.0").arg(type);
        c.instanceName = instance;
        c.pathUri = QStringLiteral("%1/%2.host_cxt/%3.rtc").arg(where.server, where.host, instance);
        Profile::RtsPort p;
        p.name = instance + QLatin1Char('.') + port;
        c.dataPorts.append(p);
        Profile::RtsExecutionContext ec;
        ec.id = QStringLiteral("0");
        ec.kind = QStringLiteral("PeriodicExecutionContext");
        ec.rate = rate;
        c.executionContexts.append(ec);
        return c;
    };
    Profile::RtsProfile profile = Profile::RtsProfile::createNew("Bench", name, "1.0");
    for (int i = 0; i < pairs; ++i) {
        profile.components.append(
            component(placement(2 * i), QStringLiteral("ConsoleIn"), QStringLiteral("Src%1").arg(i), "out"));
        profile.components.append(
            component(placement(2 * i + 1), QStringLiteral("ConsoleOut"), QStringLiteral("Snk%1").arg(i), "in"));
    }
    for (int i = 0; i < pairs; ++i) {
        for (int k = 0; k < fanOut; ++k) {
            const QString source = QStringLiteral("Src%1").arg(i);
            const QString sink = QStringLiteral("Snk%1").arg((i + k) % pairs);
            Profile::RtsDataPortConnector c;
            c.connectorId = QStringLiteral("bench-%1-%2").arg(i).arg(k);
            c.name = source + QLatin1Char('_') + sink;
            c.dataType = QStringLiteral("IDL:RTC/TimedLong:1.0");
            c.interfaceType = QStringLiteral("corba_cdr");
            c.dataflowType = QStringLiteral("push");
            c.subscriptionType = subscription;
            c.source.instanceName = source;
            c.source.portName = source + QStringLiteral(".out");
            c.target.instanceName = sink;
            c.target.portName = sink + QStringLiteral(".in");
            profile.dataPortConnectors.append(c);
        }
    }
    return profile;
}

} // namespace Bench
