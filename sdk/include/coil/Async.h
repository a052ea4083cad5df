// SPDX-License-Identifier: MIT
/*!
 * @file Async.h
 * @brief coil::AsyncInvoker: calls a function on an object in a new thread.
 *
 * @code
 * coil::Async* call = coil::AsyncInvoker(&robot, [](Robot* r) { r->home(); });
 * call->invoke();
 * ...
 * if (call->finished()) call->exit();   // exit() waits and deletes the call
 * @endcode
 */
#ifndef COIL_ASYNC_H
#define COIL_ASYNC_H

#include <coil/PeriodicTask.h>
#include <coil/Task.h>

#include <iostream>
#include <mutex>
#include <utility>
#include <vector>

namespace coil {
/*! An asynchronous call running in its own thread. */
class Async : public coil::Task
{
public:
    Async() { }
    virtual ~Async() { }
    /*! Starts the call. */
    virtual void invoke() = 0;
    /*! True once the call has returned. */
    virtual bool finished() = 0;
    /*! Waits for the call to return and deletes this object. */
    virtual void exit() = 0;
};

/*!
 * Deletes finished calls in the background: add() a call that is to go once it has returned
 * (the calls made with auto_delete delete themselves and need not be added).
 */
class DeleteAsyncThread
{
public:
    DeleteAsyncThread();
    /*! Stops the background sweep and deletes the calls that are still listed, waiting for them. */
    ~DeleteAsyncThread();
    /*! Starts the background sweep (add() does so too). */
    void activate();
    /*! One sweep: deletes the listed calls that have finished. */
    int svc();
    /*! Lists @p thread for deletion once it has finished. */
    void add(Async *thread);
    /*! The shared instance (instance() creates it). */
    static DeleteAsyncThread *delasync;
    /*! Guards the creation of the shared instance. */
    static std::mutex mutex;
    /*! The shared instance, created on the first call. */
    static DeleteAsyncThread *instance();

private:
    std::vector<Async *> m_threads;
    std::mutex m_mutex;
    PeriodicTask m_task;
    bool m_active;
};

namespace detail {
// The common part of the two invoker kinds; Func is either a value or a reference type.
template<typename Object, typename Func> class AsyncCall : public Async
{
public:
    AsyncCall(Object *obj, Func func, bool auto_delete)
        : m_obj(obj)
        , m_func(func)
        , m_finished(false)
        , m_autodelete(auto_delete)
    { }
    int svc()
    {
        m_func(m_obj);
        std::lock_guard<std::mutex> lock(m_mutex);
        m_finished = true;
        return 0;
    }
    void finalize()
    {
        Task::finalize();
        // The thread ends right after this call and touches nothing of the object, so
        // a call that owns itself can go now.
        if (m_autodelete)
            delete this;
    }
    void invoke() { activate(); }
    bool finished()
    {
        bool done;
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            done = m_finished;
        }
        if (done)
            Task::wait();
        return done;
    }
    void exit()
    {
        Task::wait();
        delete this;
    }

private:
    Object *m_obj;
    Func m_func;
    bool m_finished;
    const bool m_autodelete;
    std::mutex m_mutex;
};
} // namespace detail

/*! An asynchronous call holding a copy of the function. */
template<typename Object, typename Func> class Async_t : public detail::AsyncCall<Object, Func>
{
public:
    /*! Calls @p func(@p obj) when invoked; with @p auto_delete the call deletes itself. */
    Async_t(Object *obj, Func func, bool auto_delete = false)
        : detail::AsyncCall<Object, Func>(obj, func, auto_delete)
    { }
};

/*! An asynchronous call referring to a function object the caller keeps alive. */
template<typename Object, typename Func>
class Async_ref_t : public detail::AsyncCall<Object, Func &>
{
public:
    /*! Calls @p func(@p obj) when invoked; with @p auto_delete the call deletes itself. */
    Async_ref_t(Object *obj, Func &func, bool auto_delete = false)
        : detail::AsyncCall<Object, Func &>(obj, func, auto_delete)
    { }
};

/*! A new call of @p func(@p obj) (not started: call invoke()). */
template<typename Object, typename Func>
inline Async_t<Object, Func> *AsyncInvoker(Object *obj, Func func, bool auto_delete = false)
{
    return new Async_t<Object, Func>(obj, func, auto_delete);
}

/*! A new call of (*@p func)(@p obj), using the caller's function object. */
template<typename Object, typename Func>
inline Async_ref_t<Object, Func> *AsyncInvoker(Object *obj, Func *func, bool auto_delete = false)
{
    return new Async_ref_t<Object, Func>(obj, *func, auto_delete);
}
} // namespace coil

#endif // COIL_ASYNC_H
