// SPDX-License-Identifier: MIT
// The manager's settings before rtc.conf and the command line apply.
#ifndef RTM_DEFAULTCONFIGURATION_H
#define RTM_DEFAULTCONFIGURATION_H

#include "rtm/version.h"
#include "rtm/config_rtc.h"

namespace RTC
{
/**
 * Key / value pairs, ending with an empty key: the defaults the runtime's manager starts from
 * (the same as those it applies itself), as coil::Properties(default_config) reads them.
 */
const char *const default_config[] = {
    "config.version", openrtm_version,
    "openrtm.name", openrtm_name,
    "openrtm.version", openrtm_version,
    "manager.instance_name", "manager",
    "manager.name", "manager",
    "manager.naming_formats", "%h.host_cxt/%n.mgr",
    "manager.is_master", "NO",
    "manager.corba_servant", "YES",
    "manager.modules.load_path", ".",
    "manager.components.naming_policy", "process_unique",
    "manager.language", "C++",
    "manager.modules.C++.suffixes", "so",
    "naming.enable", "YES",
    "naming.type", "corba",
    "naming.formats", "%h.host_cxt/%n.rtc",
    "corba.id", corba_name,
    "corba.nameservers", "localhost",
    "corba.master_manager", "localhost:2810",
    "exec_cxt.periodic.type", "PeriodicExecutionContext",
    "exec_cxt.periodic.rate", "1000",
    "exec_cxt.transition_timeout", "0.5",
    "logger.enable", "YES",
    "logger.file_name", "./rtc%p.log",
    "logger.log_level", "INFO",
    ""};
} // namespace RTC

#endif // RTM_DEFAULTCONFIGURATION_H
