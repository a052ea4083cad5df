// SPDX-License-Identifier: MIT
/*!
 * @file Task.h
 * @brief coil::Task: an object whose svc() runs in its own thread.
 */
#ifndef COIL_TASK_H
#define COIL_TASK_H

#include <thread>

namespace coil {
/*!
 * Override svc() and call activate() to run it in a new thread; wait() joins that thread.
 * After svc() returns, finalize() runs in the same thread. A task runs at most one thread
 * at a time: activate() does nothing while svc() is still running, and starts a new run
 * once it has returned.
 *
 * Join the thread (wait()) before the derived object is destroyed: svc() of a destroyed
 * object cannot run.
 */
class Task
{
public:
    Task();
    /*! Joins a thread that was never joined (the subclass should have stopped svc()). */
    virtual ~Task();
    /*! Hook for subclasses to prepare the task; returns 0. */
    virtual int open(void *args = 0);
    /*! Hook for subclasses to shut the task down; returns 0. */
    virtual int close(unsigned long flags = 0);
    /*! The thread body; returns 0 unless overridden. */
    virtual int svc();
    /*! Starts svc() in a new thread unless one is running. */
    virtual void activate();
    /*! Waits until the thread has finished; returns 0. Does nothing from the task's own thread. */
    virtual int wait();
    /*! No effect (kept for compatibility); returns 0. */
    virtual int suspend();
    /*! No effect (kept for compatibility); returns 0. */
    virtual int resume();
    /*! Marks the task as not running so that activate() can start it again. */
    virtual void reset();
    /*! Called in the task's thread after svc() returns; calls reset(). */
    virtual void finalize();
    /*! Runs svc() then finalize() of the coil::Task @p args points to. */
    static void *svc_run(void *args = 0);

private:
    Task(const Task &);
    Task &operator=(const Task &);
    struct Thread;
    Thread *m_thread;
};
} // namespace coil

#endif // COIL_TASK_H
