// SPDX-License-Identifier: MIT
#pragma once

#include "executioncontext.h"

#include <OpenRTM.hh>

namespace Runtime {

/**
 * An execution context whose cycles are driven from outside through
 * OpenRTM::ExtTrigExecutionContextService::tick(): OpenRTM's ExtTrigExecutionContext
 * (asynchronous: tick() returns at once and the context's thread runs one cycle per tick, none
 * lost when they come faster than the cycles) and OpenHRPExecutionContext /
 * SimulatorExecutionContext (synchronous: tick() returns after the cycle, run in the caller's
 * thread). State changes happen at once in the caller's thread, between cycles. As OpenRTM's
 * ExtTrigExecutionContext wakes its thread while it waits for a requested state change, an
 * asynchronous context runs one cycle of its own after each activation, deactivation or reset:
 * an activated component executes once before the first tick. A tick while the context is
 * stopped runs nothing.
 */
class TriggeredExecutionContext : public ExecutionContext, public virtual POA_OpenRTM::ExtTrigExecutionContextService
{
public:
    enum class Tick { Asynchronous, Synchronous };

    TriggeredExecutionContext(const std::string &typeName, Tick mode, double rate,
                              double transitionTimeoutSeconds = 0.5);
    ~TriggeredExecutionContext() override;

    Tick tickMode() const { return m_mode; }
    /// Ticks asked for and not yet run (always 0 for a synchronous context).
    unsigned long pendingTicks();

    // OpenRTM::ExtTrigExecutionContextService
    void tick() override;

protected:
    RTC::ReturnCode_t requestTransition(const ParticipantPtr &p, RTC::LifeCycleState from, Request request) override;
    void started() override;
    void run() override;

private:
    Tick m_mode;
    unsigned long m_pending = 0;
};

} // namespace Runtime
