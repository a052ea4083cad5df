// SPDX-License-Identifier: MIT
// The header generated components include for their OutPorts.
#ifndef RTM_DATAOUTPORT_H
#define RTM_DATAOUTPORT_H

#include <rtm/OutPort.h>

#include <sys/utsname.h>

#endif // RTM_DATAOUTPORT_H
