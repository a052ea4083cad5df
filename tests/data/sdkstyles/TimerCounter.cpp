// SPDX-License-Identifier: MIT
// coil::Timer of coil 2.x: a periodic function and a delayed one, each ticked 10 ms per cycle of
// the component; what they counted goes out on a port (periodic runs times 1000 plus delayed runs).
#include "StyleProfile.h"

#include <coil/Timer.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/idl/BasicDataTypeSkel.h>

#include <atomic>
#include <chrono>

namespace {
SDKSTYLES_SPEC(TimerCounter);

class TimerCounter : public RTC::DataFlowComponentBase
{
public:
    explicit TimerCounter(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager), m_outOut("out", m_out), m_periodic(0), m_delayed(0)
    {
    }

    RTC::ReturnCode_t onInitialize() override
    {
        addOutPort("out", m_outOut);
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onActivated(RTC::UniqueId) override
    {
        // Every 20 ms of ticks: counted; once after 100 ms: reported.
        m_periodicTimer.emplace([this] { ++m_periodic; }, std::chrono::milliseconds(20));
        m_delayedTimer.emplace([this] { ++m_delayed; }, std::chrono::milliseconds(100));
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        m_periodicTimer.tick(std::chrono::milliseconds(10));
        m_delayedTimer.tick(std::chrono::milliseconds(10));
        m_out.data = m_periodic * 1000 + m_delayed;
        m_outOut.write();
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_out;
    RTC::OutPort<RTC::TimedLong> m_outOut;
    coil::Timer<coil::PeriodicFunction> m_periodicTimer;
    coil::Timer<coil::DelayedFunction> m_delayedTimer;
    std::atomic<long> m_periodic;
    std::atomic<long> m_delayed;
};
} // namespace

extern "C" {
DLL_EXPORT void TimerCounterInit(RTC::Manager *manager)
{
    registerStyle<TimerCounter>(manager, TimerCounter_spec);
}
}
