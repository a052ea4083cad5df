// SPDX-License-Identifier: MIT
/*!
 * @file TimeMeasure.h
 * @brief coil::TimeMeasure: records tick-to-tack intervals and their statistics.
 */
#ifndef COIL_TIMEMEASURE_H
#define COIL_TIMEMEASURE_H

#include <chrono>
#include <vector>

namespace coil {
/*!
 * Measures durations: tick() starts one, tack() ends it and records it. The last
 * @p buflen recorded durations make up the statistics.
 */
class TimeMeasure
{
public:
    /*! Summary of the recorded intervals, in seconds. */
    struct Statistics
    {
        double max_interval;
        double min_interval;
        double mean_interval;
        double std_deviation;
    };

    /*! Keeps up to @p buflen intervals (at least one). */
    explicit TimeMeasure(unsigned long buflen = 100);
    /*! Starts an interval. */
    void tick();
    /*! Ends the interval started by tick() and records it (nothing without a tick()). */
    void tack();
    /*! The last recorded interval. */
    std::chrono::nanoseconds interval();
    /*! Forgets all recorded intervals. */
    void reset();
    /*! The number of intervals the statistics are based on. */
    unsigned long int count() const;
    /*! The statistics in seconds; false when nothing has been recorded. */
    bool getStatistics(double &max_interval, double &min_interval, double &mean_interval,
                       double &stddev);
    /*! The statistics in seconds (all zero when nothing has been recorded). */
    Statistics getStatistics();

private:
    std::vector<std::chrono::nanoseconds> m_record;
    std::chrono::steady_clock::time_point m_begin;
    std::chrono::nanoseconds m_interval;
    unsigned long int m_count;
    const unsigned long int m_countMax;
    bool m_recurred;
    bool m_ticking;
};
} // namespace coil

#endif // COIL_TIMEMEASURE_H
