// SPDX-License-Identifier: MIT
#include <coil/Task.h>

#include <atomic>
#include <mutex>
#include <thread>

namespace coil {
struct Task::Thread
{
    std::mutex mutex; // guards thread
    std::thread thread;
    std::atomic<bool> running {false};
};

Task::Task()
    : m_thread(new Thread)
{ }

Task::~Task()
{
    // A joinable std::thread aborts the program when destroyed. Join it, so that the
    // finalize() still running in it cannot touch freed memory; a task deleted from its own
    // thread (finalize() doing `delete this`) can only detach.
    if (m_thread->thread.joinable()) {
        if (m_thread->thread.get_id() == std::this_thread::get_id())
            m_thread->thread.detach();
        else
            m_thread->thread.join();
    }
    delete m_thread;
}

int Task::open(void *)
{
    return 0;
}

int Task::close(unsigned long)
{
    return 0;
}

int Task::svc()
{
    return 0;
}

void Task::activate()
{
    std::lock_guard<std::mutex> lock(m_thread->mutex);
    if (m_thread->running.exchange(true))
        return;
    // A previous run has finished (running was false): collect its thread first.
    if (m_thread->thread.joinable()) {
        if (m_thread->thread.get_id() == std::this_thread::get_id())
            m_thread->thread.detach();
        else
            m_thread->thread.join();
    }
    m_thread->thread = std::thread(&Task::svc_run, static_cast<void *>(this));
}

int Task::wait()
{
    std::thread finished;
    {
        std::lock_guard<std::mutex> lock(m_thread->mutex);
        if (!m_thread->thread.joinable() || m_thread->thread.get_id() == std::this_thread::get_id())
            return 0;
        finished = std::move(m_thread->thread);
    }
    finished.join();
    return 0;
}

int Task::suspend()
{
    return 0;
}

int Task::resume()
{
    return 0;
}

void Task::reset()
{
    m_thread->running = false;
}

void Task::finalize()
{
    reset();
}

void *Task::svc_run(void *args)
{
    Task *task = static_cast<Task *>(args);
    if (task != nullptr) {
        // activate() holds the lock until it has stored this thread; a svc() or finalize()
        // that deletes the task must not start before that.
        {
            std::lock_guard<std::mutex> published(task->m_thread->mutex);
        }
        task->svc();
        task->finalize();
    }
    return nullptr;
}
} // namespace coil
