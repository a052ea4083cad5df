// SPDX-License-Identifier: MIT
#include <coil/TimeValue.h>

#include <cmath>

namespace coil {
namespace {
const long long kUsecPerSec = TIMEVALUE_ONE_SECOND_IN_USECS;
}

TimeValue::TimeValue(long sec, long usec)
    : m_sec(sec)
    , m_usec(usec)
{
    normalize();
}

TimeValue::TimeValue(int sec)
    : m_sec(sec)
    , m_usec(0)
{ }

TimeValue::TimeValue(double timeval)
    : m_sec(0)
    , m_usec(0)
{
    *this = timeval;
}

TimeValue &TimeValue::operator+=(const TimeValue &tm)
{
    *this = *this + tm;
    return *this;
}

TimeValue &TimeValue::operator-=(const TimeValue &tm)
{
    *this = *this - tm;
    return *this;
}

TimeValue TimeValue::operator=(double time)
{
    if (!std::isfinite(time))
        time = 0.0; // keep NaN and infinities out of the integer conversion
    const double whole = std::trunc(time);
    m_sec = static_cast<long>(whole);
    m_usec = static_cast<long>(std::llround((time - whole) * kUsecPerSec));
    normalize();
    return *this;
}

TimeValue::operator double() const
{
    return static_cast<double>(m_sec) + static_cast<double>(m_usec) / kUsecPerSec;
}

int TimeValue::sign() const
{
    if (m_sec != 0)
        return m_sec > 0 ? 1 : -1;
    if (m_usec != 0)
        return m_usec > 0 ? 1 : -1;
    return 0;
}

void TimeValue::normalize()
{
    // Integer division truncates toward zero, which gives both parts the sign of the total.
    const long long total = static_cast<long long>(m_sec) * kUsecPerSec + m_usec;
    m_sec = static_cast<long>(total / kUsecPerSec);
    m_usec = static_cast<long>(total % kUsecPerSec);
}
} // namespace coil
