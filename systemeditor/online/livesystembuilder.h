// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "rtcprofile.h"
#include "rtscomponent.h"
#include "rtsconnector.h"

#include <QString>

#include <vector>

namespace SystemEditor {

/// A live component turned into the records the System Editor model draws.
struct LiveComponentRecord
{
    Profile::RtsComponent component;
    Profile::RtcProfile rtc;
};

/**
 * Converts what the client library reads from live components into RTS/RTC profile records, so
 * the online diagram reuses the offline model and canvas: ports come from the component profile,
 * connectors from the ports' live connector profiles.
 */
namespace LiveSystemBuilder {

/// The records of the component at `path` (reference `ior`) with profile `info`.
LiveComponentRecord component(const Corba::ComponentInfo &info, const QString &path,
                              const QString &ior);
/// The data-port connectors among `ports` (of every displayed component) whose both ends belong
/// to components in `instances`; each connector once, keyed by its live connector id.
std::vector<Profile::RtsDataPortConnector> dataConnectors(const std::vector<Corba::PortInfo> &ports,
                                                          const QStringList &instances);
/// The same for service-port connectors.
std::vector<Profile::RtsServicePortConnector>
serviceConnectors(const std::vector<Corba::PortInfo> &ports, const QStringList &instances);

} // namespace LiveSystemBuilder

} // namespace SystemEditor
