// SPDX-License-Identifier: MIT
#pragma once

#include <coil/Properties.h>

#include <properties.h>

#include <omniORB4/CORBA.h>

namespace RTC {
class Manager;
}

namespace RTC::Sdk {

/// Every leaf of @p properties as flat `a.b.c` keys.
Runtime::Properties toRuntime(const coil::Properties &properties);
/// Flat keys as a coil property tree.
coil::Properties toCoil(const Runtime::Properties &properties);
/// The process's root POA (the ORB is initialised on first use if nobody did it).
PortableServer::POA_ptr rootPoa();
/// Makes @p manager (an object of a class derived from RTC::Manager) the process's manager, which
/// init() then starts. False when the process has a manager already.
bool adoptManager(RTC::Manager *manager);

} // namespace RTC::Sdk
