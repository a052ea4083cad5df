// SPDX-License-Identifier: MIT
/*!
 * @file Timer.h
 * @brief coil::Timer: a list of delayed or periodic calls advanced by an external clock.
 *
 * The timer has no thread of its own: its owner calls tick() with the time that passed (the
 * manager does so from its own periodic task), and every task counts down by that much.
 *
 * @code
 * coil::Timer<coil::PeriodicFunction> timer;
 * coil::Timer<coil::PeriodicFunction>::TaskId id =
 *     timer.emplace([] { poll(); }, std::chrono::milliseconds(100));
 * ...
 * timer.tick(std::chrono::milliseconds(10));   // from the owner's loop
 * id->stop();                                  // removed at the next tick
 * @endcode
 */
#ifndef Timer_h
#define Timer_h

#include <chrono>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <utility>

namespace coil {
/*! A function called once, after a delay. */
class DelayedFunction
{
public:
    DelayedFunction(std::function<void(void)> fn, std::chrono::nanoseconds delay) noexcept
        : m_fn(std::move(fn))
        , m_remains(delay)
    { }
    /*!
     * Counts @p interval off the delay and calls the function once it is used up.
     * @return true when the function has been called (the task is finished).
     */
    bool tick(std::chrono::nanoseconds interval);

private:
    std::function<void(void)> const m_fn;
    std::chrono::nanoseconds m_remains;
};

/*! A function called once per period until stop(). */
class PeriodicFunction
{
public:
    PeriodicFunction(std::function<void(void)> fn, std::chrono::nanoseconds period) noexcept
        : m_fn(std::move(fn))
        , m_remains(period)
        , m_period(period)
    { }
    /*!
     * Counts @p interval off the current period and calls the function when it is used up.
     * @return true once stop() was called (the task is to be removed).
     */
    bool tick(std::chrono::nanoseconds interval);
    /*! No more calls; the timer drops the task at its next tick. Safe from any thread. */
    void stop();

private:
    std::function<void(void)> const m_fn;
    std::chrono::nanoseconds m_remains;
    std::chrono::nanoseconds const m_period;
    bool m_isRemoved = false;
    std::mutex m_lock;
};

/*!
 * Tasks of type @p Function (DelayedFunction, PeriodicFunction, or a pointer / unique_ptr /
 * shared_ptr to one), each with a `bool tick(std::chrono::nanoseconds)` that returns true when
 * the task is done.
 */
template<class Function> class Timer
{
public:
    /*! Identifies a task: the address of the stored task (valid until the task finishes). */
    using TaskId = Function *;

    Timer() = default;
    Timer(Timer const &) = delete;
    Timer &operator=(Timer const &) = delete;
    Timer(Timer &&) = delete;
    Timer &operator=(Timer &&) = delete;

    /*! Adds a task built from @p args; may be called from any thread, also from a task. */
    template<class... Args> TaskId emplace(Args &&...args)
    {
        std::lock_guard<std::mutex> guard(m_lock);
        m_tasks.emplace_back(std::forward<Args>(args)...);
        return &m_tasks.back();
    }

    /*! Advances every task by @p interval and drops those that are done. */
    void tick(std::chrono::nanoseconds interval)
    {
        // The tasks run without the lock held, so that they can add tasks themselves; tasks added
        // meanwhile land in m_tasks and are put behind the current ones afterwards.
        std::list<Function> running;
        {
            std::lock_guard<std::mutex> guard(m_lock);
            running.swap(m_tasks);
        }
        typename std::list<Function>::iterator it = running.begin();
        while (it != running.end()) {
            if (deref(*it).tick(interval))
                it = running.erase(it);
            else
                ++it;
        }
        std::lock_guard<std::mutex> guard(m_lock);
        m_tasks.splice(m_tasks.begin(), running);
    }

private:
    template<class Fn> static Fn &deref(Fn &x) { return x; }
    template<class Fn> static Fn &deref(Fn *x) { return *x; }
    template<class Fn> static Fn &deref(std::unique_ptr<Fn> &x) { return *x; }
    template<class Fn> static Fn &deref(std::shared_ptr<Fn> &x) { return *x; }

    std::list<Function> m_tasks;
    std::mutex m_lock;
};
} // namespace coil

#endif // Timer_h
