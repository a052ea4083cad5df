// SPDX-License-Identifier: MIT
// The common base of data and service ports (RTC::PortService servants).
#ifndef RTM_PORTBASE_H
#define RTM_PORTBASE_H

#include <rtm/CORBA_SeqUtil.h>
#include <rtm/NVUtil.h>
#include <rtm/RTC.h>

#include <rtmruntime/portbase.h>

#include <array>
#include <compare>
#include <condition_variable>
#include <iostream>
#include <mutex>

namespace RTC
{
/// A port of a component: its profile, its connections and the connect/disconnect protocol.
using PortBase = ::Runtime::PortBase;
} // namespace RTC

#endif // RTM_PORTBASE_H
