// SPDX-License-Identifier: MIT
#include "triggeredexecutioncontext.h"

namespace Runtime {

TriggeredExecutionContext::TriggeredExecutionContext(const std::string &typeName, Tick mode, double rate,
                                                     double transitionTimeoutSeconds)
    : ExecutionContext(typeName, RTC::PERIODIC, rate, transitionTimeoutSeconds)
    , m_mode(mode)
{
}

TriggeredExecutionContext::~TriggeredExecutionContext()
{
    // Before the members run() uses are gone.
    halt(true);
}

unsigned long TriggeredExecutionContext::pendingTicks()
{
    std::lock_guard lock(m_mutex);
    return m_pending;
}

void TriggeredExecutionContext::tick()
{
    if (m_mode == Tick::Synchronous) {
        if (is_running())
            runCycle();
        return;
    }
    {
        std::lock_guard lock(m_mutex);
        if (!m_running)
            return;
        ++m_pending;
    }
    m_wake.notify_all();
}

RTC::ReturnCode_t TriggeredExecutionContext::requestTransition(const ParticipantPtr &p, RTC::LifeCycleState from,
                                                               Request request)
{
    const RTC::ReturnCode_t result = ExecutionContext::requestTransition(p, from, request);
    if (result == RTC::RTC_OK && m_mode == Tick::Asynchronous)
        tick();
    return result;
}

void TriggeredExecutionContext::started()
{
    if (m_mode == Tick::Asynchronous)
        startThread();
}

void TriggeredExecutionContext::run()
{
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return !m_running || m_pending > 0; });
            if (!m_running)
                return;
            --m_pending;
        }
        runCycle();
    }
}

} // namespace Runtime
