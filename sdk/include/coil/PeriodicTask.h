// SPDX-License-Identifier: MIT
/*!
 * @file PeriodicTask.h
 * @brief coil::PeriodicTask: calls a function in its own thread once per period.
 */
#ifndef COIL_PERIODICTASK_H
#define COIL_PERIODICTASK_H

#include <coil/PeriodicTaskBase.h>
#include <coil/TimeMeasure.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace coil {
/*!
 * Calls the function given to setTask() once per period in its own thread, from activate()
 * until finalize(). A waiting period is cut short by finalize(), so finalize() and wait()
 * return promptly. The destructor stops and joins the thread.
 */
class PeriodicTask : public coil::PeriodicTaskBase
{
public:
    PeriodicTask();
    virtual ~PeriodicTask();
    void activate();
    void finalize();
    int suspend();
    int resume();
    void signal();
    void setTask(std::function<void(void)> func);
    void setPeriod(std::chrono::nanoseconds period);
    void executionMeasure(bool value);
    void executionMeasureCount(unsigned int n);
    void periodicMeasure(bool value);
    void periodicMeasureCount(unsigned int n);
    TimeMeasure::Statistics getExecStat();
    TimeMeasure::Statistics getPeriodStat();

protected:
    /*! The loop of the thread. */
    int svc();
    /*! Waits for the rest of the period (or until finalize()). */
    virtual void sleep();
    /*! Publishes the call-duration statistics every executionMeasureCount() calls. */
    virtual void updateExecStat();
    /*! Publishes the period statistics every periodicMeasureCount() periods. */
    virtual void updatePeriodStat();

private:
    bool waitWhileSuspended();

    std::function<void(void)> m_func;
    std::mutex m_mutex; // guards the state below and wakes the thread through m_wake
    std::condition_variable m_wake;
    bool m_alive;
    bool m_suspended;
    bool m_signalled;
    std::chrono::nanoseconds m_period;
    std::atomic<bool> m_resetMeasures;

    std::atomic<bool> m_execMeasure;
    std::atomic<unsigned int> m_execCountMax;
    unsigned int m_execCount;
    TimeMeasure m_execTime;
    std::atomic<bool> m_periodMeasure;
    std::atomic<unsigned int> m_periodCountMax;
    unsigned int m_periodCount;
    TimeMeasure m_periodTime;
    std::mutex m_statMutex;
    TimeMeasure::Statistics m_execStat;
    TimeMeasure::Statistics m_periodStat;
};
} // namespace coil

#endif // COIL_PERIODICTASK_H
