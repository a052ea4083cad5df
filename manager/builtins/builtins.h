// SPDX-License-Identifier: MIT
#pragma once

#include "componentfactory.h"

#include <vector>

namespace Runtime {

/**
 * Stand-ins for OpenRTM-aist's example components, with their type and port names so real RTS
 * files can be restored on our manager: ConsoleIn (a counter), ConsoleOut (counts and remembers
 * what it receives: status `received_count`, `last_value`, `received_values`), Sensor, Controller,
 * Motor, SeqOut, SeqIn, MyServiceProvider, MyServiceConsumer, ConfigSample.
 */
std::vector<ComponentFactory> builtinFactories();

std::vector<ComponentFactory> consoleFactories();
std::vector<ComponentFactory> controlLoopFactories();
std::vector<ComponentFactory> sequenceFactories();
std::vector<ComponentFactory> serviceFactories();
std::vector<ComponentFactory> configSampleFactories();

} // namespace Runtime
