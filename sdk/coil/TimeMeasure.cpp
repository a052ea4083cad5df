// SPDX-License-Identifier: MIT
#include <coil/TimeMeasure.h>

#include <algorithm>
#include <cmath>

namespace coil {
TimeMeasure::TimeMeasure(unsigned long buflen)
    : m_interval(0)
    , m_count(0)
    , m_countMax(std::max(buflen, 1UL))
    , m_recurred(false)
    , m_ticking(false)
{
    m_record.reserve(m_countMax);
}

void TimeMeasure::tick()
{
    m_begin = std::chrono::steady_clock::now();
    m_ticking = true;
}

void TimeMeasure::tack()
{
    if (!m_ticking)
        return;
    m_interval = std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::steady_clock::now() - m_begin);
    // A ring buffer of the last m_countMax intervals.
    if (m_record.size() < m_countMax)
        m_record.push_back(m_interval);
    else
        m_record[m_count] = m_interval;
    ++m_count;
    if (m_count >= m_countMax) {
        m_count = 0;
        m_recurred = true;
    }
}

std::chrono::nanoseconds TimeMeasure::interval()
{
    return m_interval;
}

void TimeMeasure::reset()
{
    m_record.clear();
    m_count = 0;
    m_recurred = false;
    m_ticking = false;
    m_interval = std::chrono::nanoseconds(0);
}

unsigned long int TimeMeasure::count() const
{
    return m_recurred ? m_countMax : m_count;
}

bool TimeMeasure::getStatistics(double &max_interval, double &min_interval, double &mean_interval,
                                double &stddev)
{
    max_interval = min_interval = mean_interval = stddev = 0.0;
    if (m_record.empty())
        return false;
    double sum = 0.0, sumOfSquares = 0.0;
    max_interval = 0.0;
    min_interval = HUGE_VAL;
    for (const std::chrono::nanoseconds &ns : m_record) {
        const double seconds = std::chrono::duration<double>(ns).count();
        max_interval = std::max(max_interval, seconds);
        min_interval = std::min(min_interval, seconds);
        sum += seconds;
        sumOfSquares += seconds * seconds;
    }
    const double n = static_cast<double>(m_record.size());
    // Rounding can put the mean of equal values a hair outside them.
    mean_interval = std::min(std::max(sum / n, min_interval), max_interval);
    stddev = std::sqrt(std::max(0.0, sumOfSquares / n - mean_interval * mean_interval));
    return true;
}

TimeMeasure::Statistics TimeMeasure::getStatistics()
{
    Statistics s = {0.0, 0.0, 0.0, 0.0};
    getStatistics(s.max_interval, s.min_interval, s.mean_interval, s.std_deviation);
    return s;
}
} // namespace coil
