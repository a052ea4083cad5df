// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <string>

namespace Runtime {

/// A manager's settings before rtc.conf and the command line apply (OpenRTM-aist's defaults).
Properties managerDefaults();

/**
 * The first configuration file of OpenRTM-aist's search order that exists: the file named by
 * RTC_MANAGER_CONFIG, ./rtc.conf, /etc/rtc.conf, /etc/rtc/rtc.conf, /usr/local/etc/rtc.conf,
 * /usr/local/etc/rtc/rtc.conf. Empty when there is none.
 */
std::string findConfigFile();

/// Reads rtc.conf @p file into @p config; false when it cannot be read. Bad lines go to stderr.
bool readConfigFile(const std::string &file, Properties *config);

/**
 * A manager's configuration from OpenRTM-aist's command line: `-f FILE` (else the search of
 * findConfigFile()), `-i` (a missing -f file is not an error), `-o key:value` (or key=value,
 * repeatable, later wins), `-p PORT`, `-d` (master), `-a` (no manager servant); `-ORB…` options
 * with their values are left to the ORB. Command-line values win over the file, the file over
 * the defaults. False with @p error naming the argument or file when the line cannot be used.
 */
bool parseManagerArguments(int argc, char **argv, Properties *config, std::string *error);

} // namespace Runtime
