// SPDX-License-Identifier: MIT
/*!
 * @file Mutex.h
 * @brief coil::Mutex, OpenRTM-aist 1.x's non-recursive mutex.
 */
#ifndef COIL_MUTEX_H
#define COIL_MUTEX_H

#include <pthread.h>

namespace coil {
/*! A non-recursive mutex; use it with coil::Guard for scoped locking. */
class Mutex
{
public:
    /*! @p name is accepted for compatibility and ignored. */
    Mutex(const char *const name = 0)
    {
        (void)name;
        ::pthread_mutex_init(&mutex_, 0);
    }
    ~Mutex() { ::pthread_mutex_destroy(&mutex_); }
    /*! Blocks until the mutex is locked. */
    void lock() { ::pthread_mutex_lock(&mutex_); }
    /*!
     * Tries to lock without blocking. As in OpenRTM-aist 1.x on POSIX, the result is the
     * failure flag: false means the lock was taken, true means another holder has it.
     */
    bool trylock() { return ::pthread_mutex_trylock(&mutex_) != 0; }
    /*! Releases the mutex. */
    void unlock() { ::pthread_mutex_unlock(&mutex_); }

    /*! The underlying POSIX mutex (coil::Condition waits on it). */
    pthread_mutex_t mutex_;

private:
    Mutex(const Mutex &);
    Mutex &operator=(const Mutex &);
};
} // namespace coil

#endif // COIL_MUTEX_H
