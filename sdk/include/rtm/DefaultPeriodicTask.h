// SPDX-License-Identifier: MIT
// The periodic task the execution contexts' factory gives by default.
#ifndef RTC_DEFAULTPERIODICTASK_H
#define RTC_DEFAULTPERIODICTASK_H

namespace coil
{
class PeriodicTask;
} // namespace coil

namespace RTC
{
/// coil::PeriodicTask under the name the periodic task factory knows it by (`default`).
using DefaultPeriodicTask = coil::PeriodicTask;
} // namespace RTC

extern "C" {
/// Registers DefaultPeriodicTask with RTC::PeriodicTaskFactory as `default`.
void DefaultPeriodicTaskInit();
}

#endif // RTC_DEFAULTPERIODICTASK_H
