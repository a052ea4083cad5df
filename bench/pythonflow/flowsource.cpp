// SPDX-License-Identifier: MIT
// bench_python's C++ source (FlowSource): on its first cycle after activation it writes every
// size's samples back to back (see flowprotocol.h), each stamped just before write().
#include "flowprotocol.h"

#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/Manager.h>

#include <cmath>

static const char *const flowsource_spec[] = {"implementation_id", "FlowSource", "type_name", "FlowSource",
                                              "description", "Writes bench_python's samples", "version", "1.0.0",
                                              "vendor", "RTStudioBench", "category", "bench",
                                              "activity_type", "PERIODIC", "kind", "DataFlowComponent",
                                              "max_instance", "0", "language", "C++", "lang_type", "compile", ""};

class FlowSource : public RTC::DataFlowComponentBase
{
public:
    explicit FlowSource(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_out("out", m_sample)
    {
    }

    RTC::ReturnCode_t onInitialize() override
    {
        addOutPort("out", m_out);
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onActivated(RTC::UniqueId) override
    {
        m_sent = false;
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        if (m_sent)
            return RTC::RTC_OK;
        m_sent = true;
        for (const unsigned elements : FlowBench::sizes) {
            m_sample.data.length(elements < 2 ? 2 : elements);
            for (int i = 0; i < FlowBench::warmUpSamples; ++i)
                send(FlowBench::warmUpMark);
            for (int i = 0; i < FlowBench::samplesFor(elements); ++i)
                send(i);
            m_sample.data.length(2);
            m_sample.data[1] = elements;
            send(FlowBench::endOfSizeMark);
        }
        return RTC::RTC_OK;
    }

private:
    void send(double first)
    {
        m_sample.data[0] = first;
        const double stamp = FlowBench::now();
        m_sample.tm.sec = CORBA::ULong(stamp);
        m_sample.tm.nsec = CORBA::ULong(std::lround((stamp - std::floor(stamp)) * 1e9) % 1000000000);
        m_out.write();
    }

    RTC::TimedDoubleSeq m_sample;
    RTC::OutPort<RTC::TimedDoubleSeq> m_out;
    bool m_sent = true;
};

extern "C" {
DLL_EXPORT void FlowSourceInit(RTC::Manager *manager)
{
    coil::Properties profile(flowsource_spec);
    manager->registerFactory(profile, RTC::Create<FlowSource>, RTC::Delete<FlowSource>);
}
}
