// SPDX-License-Identifier: MIT
#pragma once

// Internal to the rtcorba library: RTC IDL structures to the library's value types.

#include "corbatypes.h"

#include <RTC.hh>

namespace Corba::Internal {

ConnectorInfo toConnectorInfo(const RTC::ConnectorProfile &profile);
PortInfo toPortInfo(const RTC::PortProfile &profile);
ComponentInfo toComponentInfo(const RTC::ComponentProfile &profile);
LifeCycleState toLifeCycleState(RTC::LifeCycleState state);
QString executionKindName(RTC::ExecutionKind kind);
ConfigurationSet toConfigurationSet(const SDOPackage::ConfigurationSet &set);
SDOPackage::ConfigurationSet toSdoConfigurationSet(const ConfigurationSet &set);

} // namespace Corba::Internal
