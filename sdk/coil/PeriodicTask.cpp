// SPDX-License-Identifier: MIT
#include <coil/PeriodicTask.h>

namespace coil {
PeriodicTask::PeriodicTask()
    : m_alive(false)
    , m_suspended(false)
    , m_signalled(false)
    , m_period(0)
    , m_resetMeasures(false)
    , m_execMeasure(false)
    , m_execCountMax(1000)
    , m_execCount(0)
    , m_periodMeasure(false)
    , m_periodCountMax(1000)
    , m_periodCount(0)
    , m_execStat {0.0, 0.0, 0.0, 0.0}
    , m_periodStat {0.0, 0.0, 0.0, 0.0}
{ }

PeriodicTask::~PeriodicTask()
{
    finalize();
    wait();
}

void PeriodicTask::activate()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (!m_func || m_alive)
            return;
    }
    // A run that finalize() stopped may still be ending: collect it before starting anew.
    wait();
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_alive)
            return;
        m_alive = true;
    }
    Task::activate();
}

void PeriodicTask::finalize()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_alive = false;
        m_suspended = false;
    }
    m_wake.notify_all();
    Task::reset();
}

int PeriodicTask::suspend()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_suspended = true;
    return 0;
}

int PeriodicTask::resume()
{
    m_resetMeasures = true;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_suspended = false;
    }
    m_wake.notify_all();
    return 0;
}

void PeriodicTask::signal()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_signalled = true;
    }
    m_wake.notify_all();
}

void PeriodicTask::setTask(std::function<void(void)> func)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_func = std::move(func);
}

void PeriodicTask::setPeriod(std::chrono::nanoseconds period)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_period = period;
}

void PeriodicTask::executionMeasure(bool value)
{
    m_execMeasure = value;
}

void PeriodicTask::executionMeasureCount(unsigned int n)
{
    m_execCountMax = n;
}

void PeriodicTask::periodicMeasure(bool value)
{
    m_periodMeasure = value;
}

void PeriodicTask::periodicMeasureCount(unsigned int n)
{
    m_periodCountMax = n;
}

TimeMeasure::Statistics PeriodicTask::getExecStat()
{
    std::lock_guard<std::mutex> lock(m_statMutex);
    return m_execStat;
}

TimeMeasure::Statistics PeriodicTask::getPeriodStat()
{
    std::lock_guard<std::mutex> lock(m_statMutex);
    return m_periodStat;
}

bool PeriodicTask::waitWhileSuspended()
{
    std::unique_lock<std::mutex> lock(m_mutex);
    m_wake.wait(lock, [this] { return !m_alive || !m_suspended || m_signalled; });
    m_signalled = false;
    return m_alive;
}

int PeriodicTask::svc()
{
    std::function<void(void)> func;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        func = m_func;
    }
    while (waitWhileSuspended()) {
        if (m_resetMeasures.exchange(false)) {
            m_execTime.reset();
            m_periodTime.reset();
        }
        if (m_periodMeasure) {
            m_periodTime.tack();
            m_periodTime.tick();
        }
        if (m_execMeasure)
            m_execTime.tick();
        func();
        if (m_execMeasure)
            m_execTime.tack();
        updateExecStat();
        sleep();
        updatePeriodStat();
    }
    return 0;
}

void PeriodicTask::sleep()
{
    std::unique_lock<std::mutex> lock(m_mutex);
    const std::chrono::nanoseconds rest
        = m_period - (m_execMeasure ? m_execTime.interval() : std::chrono::nanoseconds(0));
    if (rest > std::chrono::nanoseconds(0))
        m_wake.wait_for(lock, rest, [this] { return !m_alive; });
}

void PeriodicTask::updateExecStat()
{
    if (!m_execMeasure || ++m_execCount < m_execCountMax)
        return;
    m_execCount = 0;
    std::lock_guard<std::mutex> lock(m_statMutex);
    m_execStat = m_execTime.getStatistics();
}

void PeriodicTask::updatePeriodStat()
{
    if (!m_periodMeasure || ++m_periodCount < m_periodCountMax)
        return;
    m_periodCount = 0;
    std::lock_guard<std::mutex> lock(m_statMutex);
    m_periodStat = m_periodTime.getStatistics();
}
} // namespace coil
