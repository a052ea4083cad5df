// SPDX-License-Identifier: MIT
// The execution context a simulator drives: tick() runs one cycle and returns when it is over.
#ifndef RTC_OPENHRPEXECUTIONCONTEXT_H
#define RTC_OPENHRPEXECUTIONCONTEXT_H

#include <mutex>
#include <rtm/RTC.h>
#include <rtm/ExecutionContextBase.h>

#include <rtmruntime/triggeredexecutioncontext.h>

namespace RTC
{
/**
 * OpenRTM-aist's OpenHRPExecutionContext (type name `OpenHRPExecutionContext`), served as
 * OpenRTM::ExtTrigExecutionContextService: tick() runs one cycle in the caller's thread and
 * returns after it, so a simulator steps its components in lock step with its own clock.
 */
class OpenHRPExecutionContext : public ::Runtime::TriggeredExecutionContext, public RTC::ExecutionContextBase
{
public:
    OpenHRPExecutionContext();
    ~OpenHRPExecutionContext() override;

    void init(coil::Properties &props) override;
    RTC::ReturnCode_t start() override;
    RTC::ReturnCode_t stop() override;

protected:
    /// For SimulatorExecutionContext: the same engine under another type name.
    explicit OpenHRPExecutionContext(const char *typeName);

    std::mutex m_tickmutex;
};
} // namespace RTC

extern "C" {
/// Registers `OpenHRPExecutionContext` with the manager's context factory.
void OpenHRPExecutionContextInit(RTC::Manager *manager);
}

#endif // RTC_OPENHRPEXECUTIONCONTEXT_H
