// SPDX-License-Identifier: MIT
#include <coil/Timer.h>

namespace coil {
bool DelayedFunction::tick(std::chrono::nanoseconds interval)
{
    m_remains -= interval;
    if (m_remains > std::chrono::nanoseconds::zero())
        return false;
    m_fn();
    return true;
}

bool PeriodicFunction::tick(std::chrono::nanoseconds interval)
{
    {
        std::lock_guard<std::mutex> guard(m_lock);
        if (m_isRemoved)
            return true;
        m_remains -= interval;
        if (m_remains > std::chrono::nanoseconds::zero())
            return false;
        // Carry the overshoot into the next period so that the average rate stays right, but
        // never more than a period: a late tick must not cause a burst of calls.
        m_remains += m_period;
        if (m_remains <= std::chrono::nanoseconds::zero())
            m_remains = m_period;
    }
    // Called without the lock: the function may stop its own task.
    m_fn();
    return false;
}

void PeriodicFunction::stop()
{
    std::lock_guard<std::mutex> guard(m_lock);
    m_isRemoved = true;
}
} // namespace coil
