// SPDX-License-Identifier: MIT
/*!
 * @file Time.h
 * @brief OpenRTM-aist 1.x time functions: coil::sleep, coil::usleep, coil::gettimeofday.
 */
#ifndef COIL_TIME_H
#define COIL_TIME_H

#include <coil/TimeValue.h>
#include <coil/config_coil.h>

#include <iostream>
#include <sys/select.h>
#include <sys/time.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

namespace coil {
/*! Sleeps @p seconds seconds; returns the seconds left when interrupted. */
inline unsigned int sleep(unsigned int seconds)
{
    return ::sleep(seconds);
}

/*! Sleeps for @p interval; returns 0, or -1 when interrupted or @p interval is negative. */
inline int sleep(TimeValue interval)
{
    if (interval.sign() < 0)
        return -1;
    timeval tv;
    tv.tv_sec = interval.sec();
    tv.tv_usec = interval.usec();
    return ::select(0, 0, 0, 0, &tv);
}

/*! Sleeps @p usec microseconds. */
inline int usleep(useconds_t usec)
{
    return ::usleep(usec);
}

/*! The system call itself. */
inline int gettimeofday(struct timeval *tv, struct timezone *tz)
{
    return ::gettimeofday(tv, tz);
}

/*! The current wall-clock time. */
inline TimeValue gettimeofday()
{
    timeval tv;
    ::gettimeofday(&tv, 0);
    return TimeValue(static_cast<long>(tv.tv_sec), static_cast<long>(tv.tv_usec));
}

/*! Stores the current wall-clock time in @p tv; returns 0. */
inline int gettimeofday(TimeValue &tv)
{
    tv = gettimeofday();
    return 0;
}

/*! Sets the system clock (needs privileges). */
inline int settimeofday(const struct timeval *tv, const struct timezone *tz)
{
    return ::settimeofday(tv, tz);
}
} // namespace coil

#endif // COIL_TIME_H
