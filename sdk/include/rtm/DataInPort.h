// SPDX-License-Identifier: MIT
// The header generated components include for their InPorts.
#ifndef RTM_DATAINPORT_H
#define RTM_DATAINPORT_H

#include <rtm/InPort.h>

#include <sys/utsname.h>

#endif // RTM_DATAINPORT_H
