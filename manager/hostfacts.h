// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

namespace Runtime {

/**
 * What this host offers a deployment planner, as manager profile properties: `os.name`,
 * `os.release`, `os.version`, `os.arch`, `os.hostname` (OpenRTM-aist's keys, from uname),
 * `os.distribution` (os-release's `ID VERSION_ID`), `rtstudio.cpu_count`, `rtstudio.memory_kib`,
 * `rtstudio.load_average` (one minute) and `rtstudio.sdk_abi` (the component SDK's SONAME). A fact
 * the system does not give is left out: planners take it as unknown.
 */
Properties hostFacts();

/// The `os.*` keys alone, which OpenRTM-aist's managers keep in their configuration.
Properties osFacts();

} // namespace Runtime
