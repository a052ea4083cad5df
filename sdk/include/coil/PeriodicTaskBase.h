// SPDX-License-Identifier: MIT
/*!
 * @file PeriodicTaskBase.h
 * @brief coil::PeriodicTaskBase: the interface of tasks that call a function periodically.
 */
#ifndef COIL_PERIODICTASKBASE_H
#define COIL_PERIODICTASKBASE_H

#include <coil/Task.h>
#include <coil/TimeMeasure.h>

#include <chrono>
#include <functional>

namespace coil {
/*! A thread that calls a function once per period (see coil::PeriodicTask). */
class PeriodicTaskBase : public coil::Task
{
public:
    virtual ~PeriodicTaskBase() { }
    /*! Starts calling the function. */
    virtual void activate() = 0;
    /*! Stops the thread (join it with wait()). */
    virtual void finalize() = 0;
    /*! Pauses the calls after the current one. */
    virtual int suspend() = 0;
    /*! Continues periodic calls. */
    virtual int resume() = 0;
    /*! While suspended, lets exactly one more call happen. */
    virtual void signal() = 0;
    /*! The function to call (set it before activate()). */
    virtual void setTask(std::function<void(void)> func) = 0;
    /*! The time from the start of one call to the start of the next. */
    virtual void setPeriod(std::chrono::nanoseconds period) = 0;
    /*! Turns measuring the duration of each call on or off. */
    virtual void executionMeasure(bool value) = 0;
    /*! The statistics of call durations are refreshed every @p n calls. */
    virtual void executionMeasureCount(unsigned int n) = 0;
    /*! Turns measuring the actual period on or off. */
    virtual void periodicMeasure(bool value) = 0;
    /*! The period statistics are refreshed every @p n periods. */
    virtual void periodicMeasureCount(unsigned int n) = 0;
    /*! The latest statistics of call durations. */
    virtual coil::TimeMeasure::Statistics getExecStat() = 0;
    /*! The latest statistics of the actual period. */
    virtual coil::TimeMeasure::Statistics getPeriodStat() = 0;
};
} // namespace coil

#endif // COIL_PERIODICTASKBASE_H
