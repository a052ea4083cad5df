// SPDX-License-Identifier: MIT
// Registers the factories the manager starts with.
#ifndef RTM_FACTORYINIT_H
#define RTM_FACTORYINIT_H

namespace RTM
{
/**
 * Registers the built-in execution contexts (PeriodicExecutionContext, ExtTrigExecutionContext,
 * OpenHRPExecutionContext, SimulatorExecutionContext) and numbering policies (process_unique,
 * node_unique, ns_unique). Types already known stay as they are; calling it twice is harmless.
 */
void FactoryInit();
} // namespace RTM

#endif // RTM_FACTORYINIT_H
