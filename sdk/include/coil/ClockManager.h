// SPDX-License-Identifier: MIT
/*!
 * @file ClockManager.h
 * @brief OpenRTM-aist 2.x clocks: "system", "logical" (set by hand) and "adjusted".
 */
#ifndef COIL_CLOCKMANAGER_H
#define COIL_CLOCKMANAGER_H

#include <coil/Singleton.h>

#include <chrono>
#include <mutex>
#include <string>

namespace coil {
/*! A clock reporting time since the epoch. */
class IClock
{
public:
    virtual ~IClock();
    /*! The current time of this clock. */
    virtual std::chrono::nanoseconds gettime() const = 0;
    /*! Sets the clock; false when this clock cannot be set. */
    virtual bool settime(std::chrono::nanoseconds clocktime) = 0;
};

/*! The system's wall clock (cannot be set from here). */
class SystemClock : public IClock
{
public:
    ~SystemClock() override;
    std::chrono::nanoseconds gettime() const override;
    bool settime(std::chrono::nanoseconds clocktime) override;
};

/*! A clock that only moves when settime() is called (simulation time). */
class LogicalClock : public IClock
{
public:
    LogicalClock();
    ~LogicalClock() override;
    std::chrono::nanoseconds gettime() const override;
    bool settime(std::chrono::nanoseconds clocktime) override;

private:
    std::chrono::nanoseconds m_currentTime;
    mutable std::mutex m_currentTimeMutex;
};

/*! A steadily running clock that settime() shifts to a given time. */
class AdjustedClock : public IClock
{
public:
    AdjustedClock();
    ~AdjustedClock() override;
    std::chrono::nanoseconds gettime() const override;
    bool settime(std::chrono::nanoseconds clocktime) override;

private:
    std::chrono::nanoseconds m_offset;
    mutable std::mutex m_offsetMutex;
};

/*! The process-wide set of clocks. */
class ClockManager : public coil::Singleton<ClockManager>
{
public:
    /*! "logical", "adjusted" or (for any other name) "system". */
    IClock &getClock(const std::string &clocktype);

private:
    SystemClock m_systemClock;
    LogicalClock m_logicalClock;
    AdjustedClock m_adjustedClock;
};
} // namespace coil

#endif // COIL_CLOCKMANAGER_H
