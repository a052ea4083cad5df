// SPDX-License-Identifier: MIT
// Periodic task implementations by name.
#ifndef RTC_PERIODICTASKFACTORY_H
#define RTC_PERIODICTASKFACTORY_H

#include <coil/Factory.h>
#include <coil/PeriodicTaskBase.h>

namespace RTC
{
/// The periodic task implementations by name: `default` is coil::PeriodicTask (DefaultPeriodicTaskInit()).
using PeriodicTaskFactory = ::coil::GlobalFactory<coil::PeriodicTaskBase>;
} // namespace RTC

#endif // RTC_PERIODICTASKFACTORY_H
