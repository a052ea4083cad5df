// SPDX-License-Identifier: MIT
// An OutPort with PortCallback functors: OnWrite sees each value written, OnWriteConvert changes
// what is sent (ten times the count).
#include "StyleProfile.h"

#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/PortCallback.h>
#include <rtm/idl/BasicDataTypeSkel.h>

namespace {
SDKSTYLES_SPEC(CallbackSource);

class Tenfold : public RTC::OnWriteConvert<RTC::TimedLong>
{
public:
    RTC::TimedLong operator()(const RTC::TimedLong &value) override
    {
        RTC::TimedLong converted(value);
        converted.data = value.data * 10;
        return converted;
    }
};

class WriteReporter : public RTC::OnWrite<RTC::TimedLong>
{
public:
    void operator()(const RTC::TimedLong &value) override
    {
        std::cout << "CallbackSource OnWrite " << value.data << std::endl;
    }
};

class CallbackSource : public RTC::DataFlowComponentBase
{
public:
    explicit CallbackSource(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager), m_outOut("out", m_out), m_count(0)
    {
    }

    RTC::ReturnCode_t onInitialize() override
    {
        m_outOut.setOnWrite(&m_reporter);
        m_outOut.setOnWriteConvert(&m_tenfold);
        addOutPort("out", m_outOut);
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        m_out.data = ++m_count;
        m_outOut.write();
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_out;
    RTC::OutPort<RTC::TimedLong> m_outOut;
    Tenfold m_tenfold;
    WriteReporter m_reporter;
    long m_count;
};
} // namespace

extern "C" {
DLL_EXPORT void CallbackSourceInit(RTC::Manager *manager)
{
    registerStyle<CallbackSource>(manager, CallbackSource_spec);
}
}
