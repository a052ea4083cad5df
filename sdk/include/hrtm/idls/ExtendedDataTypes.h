// SPDX-License-Identifier: MIT
// HRTM's name for OpenRTM's extended data types (RTC::TimedPose2D, …).
#include <rtm/idl/ExtendedDataTypesSkel.h>
