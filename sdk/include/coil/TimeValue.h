// SPDX-License-Identifier: MIT
/*!
 * @file TimeValue.h
 * @brief coil::TimeValue, OpenRTM-aist 1.x's seconds + microseconds time type.
 */
#ifndef COIL_TIMEVALUE_H
#define COIL_TIMEVALUE_H

/*! Microseconds in one second. */
#define TIMEVALUE_ONE_SECOND_IN_USECS 1000000

namespace coil {
namespace detail {
// Lets the TimeValue operators take only TimeValue operands, so that mixing a TimeValue
// with a number keeps using operator double(), as in OpenRTM-aist 1.x.
template<class T, class U, class R> struct EnableIfSame
{
};
template<class T, class R> struct EnableIfSame<T, T, R>
{
    typedef R type;
};
} // namespace detail

class TimeValue;

/*!
 * A time or a duration as whole seconds plus microseconds. After normalize() (which every
 * operation applies) the microseconds are below one second in magnitude and have the same
 * sign as the seconds.
 */
class TimeValue
{
public:
    /*! @p sec seconds plus @p usec microseconds (either may be out of range or negative). */
    TimeValue(long sec = 0, long usec = 0);
    /*! Whole seconds. */
    TimeValue(int sec);
    /*! @p timeval seconds, rounded to the nearest microsecond. */
    TimeValue(double timeval);

    /*! The whole seconds. */
    long int sec() const { return m_sec; }
    /*! The microseconds beyond sec(). */
    long int usec() const { return m_usec; }

    /*! The difference of two time values. */
    template<class T>
    typename detail::EnableIfSame<T, TimeValue, TimeValue>::type operator-(const T &tm) const
    {
        return TimeValue(m_sec - tm.m_sec, m_usec - tm.m_usec);
    }
    /*! The sum of two time values. */
    template<class T>
    typename detail::EnableIfSame<T, TimeValue, TimeValue>::type operator+(const T &tm) const
    {
        return TimeValue(m_sec + tm.m_sec, m_usec + tm.m_usec);
    }
    /*! Adds @p tm. */
    TimeValue &operator+=(const TimeValue &tm);
    /*! Subtracts @p tm. */
    TimeValue &operator-=(const TimeValue &tm);
    /*! Assigns @p time seconds. */
    TimeValue operator=(double time);
    /*! The value in seconds. */
    operator double() const;
    /*! 1, 0 or -1 for a positive, zero or negative value. */
    int sign() const;
    /*! Brings the microseconds into range and gives them the sign of the seconds. */
    void normalize();

private:
    long int m_sec;
    long int m_usec;
};

/*! Exact comparisons of two time values. */
template<class T>
typename detail::EnableIfSame<T, TimeValue, bool>::type operator==(const T &a, const T &b)
{
    return a.sec() == b.sec() && a.usec() == b.usec();
}
template<class T>
typename detail::EnableIfSame<T, TimeValue, bool>::type operator!=(const T &a, const T &b)
{
    return !(a == b);
}
template<class T>
typename detail::EnableIfSame<T, TimeValue, bool>::type operator<(const T &a, const T &b)
{
    return a.sec() < b.sec() || (a.sec() == b.sec() && a.usec() < b.usec());
}
template<class T>
typename detail::EnableIfSame<T, TimeValue, bool>::type operator>(const T &a, const T &b)
{
    return b < a;
}
template<class T>
typename detail::EnableIfSame<T, TimeValue, bool>::type operator<=(const T &a, const T &b)
{
    return !(b < a);
}
template<class T>
typename detail::EnableIfSame<T, TimeValue, bool>::type operator>=(const T &a, const T &b)
{
    return !(a < b);
}
} // namespace coil

#endif // COIL_TIMEVALUE_H
