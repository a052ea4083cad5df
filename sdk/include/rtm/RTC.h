// SPDX-License-Identifier: MIT
// The base of every OpenRTM-aist header: the ORB, OpenRTM's IDL types and the export macro.
#ifndef RTM_RTC_H
#define RTM_RTC_H

#include <omniORB4/CORBA.h>
#include <omnithread.h>

#include <BasicDataType.hh>
#include <ExtendedDataTypes.hh>
#include <InterfaceDataTypes.hh>
#include <OpenRTM.hh>
#include <RTC.hh>
#include <SDOPackage.hh>

#include <coil/Properties.h>

// Symbols of a component module need no decoration on this platform; the macro exists so that
// sources written for Windows too compile unchanged.
#ifndef DLL_EXPORT
#define DLL_EXPORT
#endif
#ifndef WINAPI
#define WINAPI
#endif

// Servants written for the C++ mapping 1.0 derive from PortableServer::RefCountServantBase; in
// the 1.1 mapping (omniORB 4) ServantBase counts references itself, so the name maps to it, as
// OpenRTM-aist maps it. Defined after the ORB's headers, which declare the old name themselves.
#ifndef RefCountServantBase
#define RefCountServantBase ServantBase
#endif

/// Tells sources that they are built against RT Studio's SDK rather than OpenRTM-aist itself.
#define RTSTUDIO_RTM_SDK 1

namespace RTC
{
using Properties = coil::Properties;
/// The handle a component knows an execution context by (OpenRTM's name for it).
using UniqueId = ExecutionContextHandle_t;
} // namespace RTC

#endif // RTM_RTC_H
