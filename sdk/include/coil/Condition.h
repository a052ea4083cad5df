// SPDX-License-Identifier: MIT
/*!
 * @file Condition.h
 * @brief coil::Condition, a condition variable bound to a coil::Mutex.
 */
#ifndef COIL_CONDITION_H
#define COIL_CONDITION_H

#include <coil/Mutex.h>

#include <pthread.h>
#include <sys/time.h>
#include <time.h>

namespace coil {
/*!
 * A condition variable waiting on @p M, which must expose a pthread_mutex_t named mutex_
 * (coil::Mutex does). The mutex must be locked by the caller of wait().
 */
template<class M> class Condition
{
public:
    /*! Binds the condition to @p mutex. */
    explicit Condition(M &mutex)
        : m_mutex(mutex)
    {
        ::pthread_cond_init(&m_cond, 0);
    }
    ~Condition() { ::pthread_cond_destroy(&m_cond); }
    /*! Wakes one waiter. */
    void signal() { ::pthread_cond_signal(&m_cond); }
    /*! Wakes all waiters. */
    void broadcast() { ::pthread_cond_broadcast(&m_cond); }
    /*! Waits until signalled; true on success. */
    bool wait() { return ::pthread_cond_wait(&m_cond, &m_mutex.mutex_) == 0; }
    /*! Waits at most @p second seconds plus @p nano_second; false on timeout. */
    bool wait(long second, long nano_second = 0)
    {
        timeval now;
        ::gettimeofday(&now, 0);
        long long nsec = static_cast<long long>(now.tv_usec) * 1000 + nano_second;
        timespec deadline;
        deadline.tv_sec = now.tv_sec + second + static_cast<time_t>(nsec / 1000000000);
        deadline.tv_nsec = static_cast<long>(nsec % 1000000000);
        if (deadline.tv_nsec < 0) {
            deadline.tv_nsec += 1000000000;
            --deadline.tv_sec;
        }
        return ::pthread_cond_timedwait(&m_cond, &m_mutex.mutex_, &deadline) == 0;
    }

private:
    Condition(const Condition &);
    Condition &operator=(const Condition &);
    pthread_cond_t m_cond;
    M &m_mutex;
};
} // namespace coil

#endif // COIL_CONDITION_H
