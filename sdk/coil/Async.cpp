// SPDX-License-Identifier: MIT
#include <coil/Async.h>

#include <chrono>

namespace coil {
DeleteAsyncThread *DeleteAsyncThread::delasync = nullptr;
std::mutex DeleteAsyncThread::mutex;

DeleteAsyncThread::DeleteAsyncThread()
    : m_active(false)
{
    m_task.setTask([this] { svc(); });
    // Finished calls only hold a joined thread object: a tenth of a second is soon enough.
    m_task.setPeriod(std::chrono::milliseconds(100));
}

DeleteAsyncThread::~DeleteAsyncThread()
{
    m_task.finalize();
    m_task.wait();
    std::lock_guard<std::mutex> guard(m_mutex);
    for (Async *thread : m_threads)
        thread->exit();
    m_threads.clear();
}

void DeleteAsyncThread::activate()
{
    std::lock_guard<std::mutex> guard(m_mutex);
    if (m_active)
        return;
    m_active = true;
    m_task.activate();
}

int DeleteAsyncThread::svc()
{
    std::lock_guard<std::mutex> guard(m_mutex);
    std::vector<Async *> running;
    for (Async *thread : m_threads) {
        if (thread->finished())
            thread->exit();
        else
            running.push_back(thread);
    }
    m_threads.swap(running);
    return 0;
}

void DeleteAsyncThread::add(Async *thread)
{
    if (thread == nullptr)
        return;
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_threads.push_back(thread);
    }
    activate();
}

DeleteAsyncThread *DeleteAsyncThread::instance()
{
    std::lock_guard<std::mutex> guard(mutex);
    if (delasync == nullptr)
        delasync = new DeleteAsyncThread();
    return delasync;
}
} // namespace coil
