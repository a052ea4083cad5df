// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "namingbrowser.h"

#include <QJsonArray>
#include <QJsonObject>

namespace Cli {

/// JSON forms of the live-system values printed by `rtctl ... --json`.
QJsonObject propertiesToJson(const Corba::Properties &properties);
QJsonObject connectorToJson(const Corba::ConnectorInfo &connector);
QJsonObject portToJson(const Corba::PortInfo &port);
QJsonObject contextToJson(const Corba::ExecutionContextInfo &context);
QJsonObject componentToJson(const Corba::ComponentInfo &component);
/// name, path, type and (for zombies) reason; children when the node has any.
QJsonObject nodeToJson(const Corba::NamingNode &node);

/// Port counts shown by `ls -l`: total/connected overall and per kind.
struct PortCounts
{
    int total = 0, connected = 0, in = 0, inConnected = 0, out = 0, outConnected = 0;
    int service = 0, serviceConnected = 0;
};
PortCounts countPorts(const std::vector<Corba::PortInfo> &ports);

} // namespace Cli
