// SPDX-License-Identifier: MIT
/*!
 * @file Guard.h
 * @brief coil::Guard: locks a mutex for the lifetime of a scope.
 */
#ifndef COIL_GUARD_H
#define COIL_GUARD_H

#include <coil/Mutex.h>

namespace coil {
/*! Locks @p M (anything with lock() and unlock()) on construction, unlocks on destruction. */
template<class M> class Guard
{
public:
    /*! Locks @p mutex. */
    explicit Guard(M &mutex)
        : m_mutex(mutex)
    {
        m_mutex.lock();
    }
    /*! Unlocks the mutex. */
    ~Guard() { m_mutex.unlock(); }

private:
    Guard(const Guard &);
    Guard &operator=(const Guard &);
    M &m_mutex;
};
} // namespace coil

#endif // COIL_GUARD_H
