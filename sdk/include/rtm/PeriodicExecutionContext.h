// SPDX-License-Identifier: MIT
// The execution context that runs its components' cycles at a fixed rate in a thread of its own.
#ifndef RTC_PERIODICEXECUTIONCONTEXT2_H
#define RTC_PERIODICEXECUTIONCONTEXT2_H

#include <coil/Task.h>
#include <condition_variable>
#include <rtm/ExecutionContextBase.h>
#include <vector>
#include <iostream>

#include <rtmruntime/executioncontext.h>

#define NUM_OF_LIFECYCLESTATE 4

namespace RTC_exp
{
/**
 * OpenRTM-aist's PeriodicExecutionContext (type name `PeriodicExecutionContext`): a thread runs
 * a cycle `exec_cxt.periodic.rate` times a second; activate / deactivate / reset wait until the
 * context's thread has made the change (bounded by `exec_cxt.transition_timeout`).
 */
class PeriodicExecutionContext : public ::Runtime::PeriodicExecutionContext, public RTC::ExecutionContextBase
{
public:
    PeriodicExecutionContext();
    ~PeriodicExecutionContext() override;

    void init(coil::Properties &props) override;
    // Both bases name these: the CORBA operations are the ones that count.
    RTC::ReturnCode_t start() override;
    RTC::ReturnCode_t stop() override;
};
} // namespace RTC_exp

namespace RTC
{
/// OpenRTM-aist 1.x code names the periodic context in this namespace.
using PeriodicExecutionContext = RTC_exp::PeriodicExecutionContext;
} // namespace RTC

extern "C" {
/// Registers `PeriodicExecutionContext` with the manager's context factory.
void PeriodicExecutionContextInit(RTC::Manager *manager);
}

#endif // RTC_PERIODICEXECUTIONCONTEXT2_H
