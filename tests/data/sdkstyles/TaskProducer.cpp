// SPDX-License-Identifier: MIT
// A component with an activity of its own (coil::Task): the task's svc() produces numbers into a
// guarded queue; onExecute sends what it finds there.
#include "StyleProfile.h"

#include <coil/Task.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/idl/BasicDataTypeSkel.h>

#include <atomic>
#include <chrono>
#include <deque>
#include <mutex>
#include <thread>

namespace {
SDKSTYLES_SPEC(TaskProducer);

class Producer : public coil::Task
{
public:
    Producer() : m_running(false), m_next(0) {}

    void start()
    {
        m_running = true;
        open(nullptr);
        activate();
    }
    void stop()
    {
        m_running = false;
        wait();
    }
    bool take(long &value)
    {
        std::lock_guard<std::mutex> guard(m_lock);
        if (m_queue.empty())
            return false;
        value = m_queue.front();
        m_queue.pop_front();
        return true;
    }
    int svc() override
    {
        while (m_running) {
            {
                std::lock_guard<std::mutex> guard(m_lock);
                m_queue.push_back(++m_next * 7);
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return 0;
    }

private:
    std::atomic<bool> m_running;
    std::mutex m_lock;
    std::deque<long> m_queue;
    long m_next;
};

class TaskProducer : public RTC::DataFlowComponentBase
{
public:
    explicit TaskProducer(RTC::Manager *manager) : RTC::DataFlowComponentBase(manager), m_outOut("out", m_out) {}

    RTC::ReturnCode_t onInitialize() override
    {
        addOutPort("out", m_outOut);
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onActivated(RTC::UniqueId) override
    {
        m_producer.start();
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onDeactivated(RTC::UniqueId) override
    {
        m_producer.stop();
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        long value = 0;
        while (m_producer.take(value)) {
            m_out.data = value;
            m_outOut.write();
        }
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_out;
    RTC::OutPort<RTC::TimedLong> m_outOut;
    Producer m_producer;
};
} // namespace

extern "C" {
DLL_EXPORT void TaskProducerInit(RTC::Manager *manager)
{
    registerStyle<TaskProducer>(manager, TaskProducer_spec);
}
}
