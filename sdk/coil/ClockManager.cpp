// SPDX-License-Identifier: MIT
#include <coil/ClockManager.h>

namespace coil {
namespace {
std::chrono::nanoseconds sinceEpoch(std::chrono::system_clock::time_point t)
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch());
}

std::chrono::nanoseconds steadyNow()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::steady_clock::now().time_since_epoch());
}
} // namespace

IClock::~IClock() = default;

SystemClock::~SystemClock() = default;

std::chrono::nanoseconds SystemClock::gettime() const
{
    return sinceEpoch(std::chrono::system_clock::now());
}

bool SystemClock::settime(std::chrono::nanoseconds)
{
    return false; // changing the machine's clock is not a component's business
}

LogicalClock::LogicalClock()
    : m_currentTime(0)
{ }

LogicalClock::~LogicalClock() = default;

std::chrono::nanoseconds LogicalClock::gettime() const
{
    std::lock_guard<std::mutex> lock(m_currentTimeMutex);
    return m_currentTime;
}

bool LogicalClock::settime(std::chrono::nanoseconds clocktime)
{
    std::lock_guard<std::mutex> lock(m_currentTimeMutex);
    m_currentTime = clocktime;
    return true;
}

// The offset maps steady time to the adjusted time, so the clock never jumps on its own.
AdjustedClock::AdjustedClock()
    : m_offset(sinceEpoch(std::chrono::system_clock::now()) - steadyNow())
{ }

AdjustedClock::~AdjustedClock() = default;

std::chrono::nanoseconds AdjustedClock::gettime() const
{
    std::lock_guard<std::mutex> lock(m_offsetMutex);
    return steadyNow() + m_offset;
}

bool AdjustedClock::settime(std::chrono::nanoseconds clocktime)
{
    std::lock_guard<std::mutex> lock(m_offsetMutex);
    m_offset = clocktime - steadyNow();
    return true;
}

IClock &ClockManager::getClock(const std::string &clocktype)
{
    if (clocktype == "logical")
        return m_logicalClock;
    if (clocktype == "adjusted")
        return m_adjustedClock;
    return m_systemClock;
}
} // namespace coil
