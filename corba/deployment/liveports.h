// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QString>

#include <vector>

namespace Deploy {

/// The short port name of a saved port name (`Inst0.out` → `out`; `out` stays).
QString shortPortName(const QString &savedName, const QString &instanceName);
/// The port of `ports` that a saved port name means, or nullptr.
const Corba::PortInfo *findPort(const std::vector<Corba::PortInfo> &ports, const QString &savedName,
                                const QString &instanceName);
/// True when two data type names mean the same type (`IDL:RTC/TimedLong:1.0`, `RTC::TimedLong`).
bool sameDataType(const QString &a, const QString &b);
/// The connector `connectorId` of `port`, or nullptr.
const Corba::ConnectorInfo *findConnector(const Corba::PortInfo &port, const QString &connectorId);

} // namespace Deploy
