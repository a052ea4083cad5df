// SPDX-License-Identifier: MIT
// The execution context that runs one cycle per external tick().
#ifndef RTC_EXTTRIGEXECUTIONCONTEXT_H
#define RTC_EXTTRIGEXECUTIONCONTEXT_H

#include <rtm/RTC.h>
#include <condition_variable>
#include <coil/Task.h>
#include <rtm/ExecutionContextBase.h>

#include <rtmruntime/triggeredexecutioncontext.h>

namespace RTC
{
/**
 * OpenRTM-aist's ExtTrigExecutionContext (type name `ExtTrigExecutionContext`), served as
 * OpenRTM::ExtTrigExecutionContextService: each tick() — local or remote — makes the context's
 * thread run one cycle; tick() itself returns at once. Ticks that come faster than the cycles
 * are queued, not merged. A tick while the context is stopped does nothing.
 */
class ExtTrigExecutionContext : public ::Runtime::TriggeredExecutionContext, public RTC::ExecutionContextBase
{
public:
    ExtTrigExecutionContext();
    ~ExtTrigExecutionContext() override;

    void init(coil::Properties &props) override;
    RTC::ReturnCode_t start() override;
    RTC::ReturnCode_t stop() override;

    /// OpenRTM-aist's thread body and its start/end: the runtime's engine owns the thread, so
    /// each is refused (logged, -1); start(), stop() and tick() drive the context.
    int open(void *args);
    int svc();
    int close(unsigned long flags);
};
} // namespace RTC

extern "C" {
/// Registers `ExtTrigExecutionContext` with the manager's context factory.
void ExtTrigExecutionContextInit(RTC::Manager *manager);
}

#endif // RTC_EXTTRIGEXECUTIONCONTEXT_H
