// SPDX-License-Identifier: MIT
// The execution context of simulators: synchronous ticks and synchronous state changes.
#ifndef TEST_EC_H
#define TEST_EC_H

#include <mutex>
#include <rtm/RTC.h>
#include <rtm/ExecutionContextBase.h>
#include <rtm/OpenHRPExecutionContext.h>

namespace RTC
{
/**
 * OpenRTM-aist's SimulatorExecutionContext (type name `SimulatorExecutionContext`): an
 * OpenHRPExecutionContext whose activate / deactivate / reset make the change at once, in the
 * caller's thread, and return after it — whether the context runs or not.
 */
class SimulatorExecutionContext : public virtual RTC::OpenHRPExecutionContext
{
public:
    SimulatorExecutionContext();
    ~SimulatorExecutionContext() override;

    RTC::ReturnCode_t activate_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t deactivate_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t reset_component(RTC::LightweightRTObject_ptr comp) override;
};
} // namespace RTC

extern "C" {
/// Registers `SimulatorExecutionContext` with the manager's context factory.
void SimulatorExecutionContextInit(RTC::Manager *manager);
}

#endif // TEST_EC_H
