// SPDX-License-Identifier: MIT
// HRTM's name for OpenRTM's basic data types (RTC::TimedLong, …).
#include <rtm/idl/BasicDataTypeSkel.h>
