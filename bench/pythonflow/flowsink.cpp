// SPDX-License-Identifier: MIT
// bench_python's C++ sink (FlowSink): its ON_BUFFER_WRITE listener takes each measured sample's
// one-way latency (arrival minus the source's stamp) and arrival time; at a size's end mark it
// prints `flow <instance> <elements> <samples> <mean us> <median us> <MiB/s>` on standard output.
#include "flowprotocol.h"

#include <rtm/ConnectorListener.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/Manager.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

static const char *const flowsink_spec[] = {"implementation_id", "FlowSink", "type_name", "FlowSink",
                                            "description", "Measures bench_python's samples", "version", "1.0.0",
                                            "vendor", "RTStudioBench", "category", "bench",
                                            "activity_type", "PERIODIC", "kind", "DataFlowComponent",
                                            "max_instance", "0", "language", "C++", "lang_type", "compile", ""};

class FlowListener : public RTC::ConnectorDataListenerT<RTC::TimedDoubleSeq>
{
public:
    explicit FlowListener(std::string instance)
        : m_instance(std::move(instance))
    {
    }

    ReturnCode operator()(RTC::ConnectorInfo &, RTC::TimedDoubleSeq &sample) override
    {
        const double arrival = FlowBench::now();
        if (sample.data.length() < 2)
            return NO_CHANGE;
        if (sample.data[0] == FlowBench::endOfSizeMark)
            report(unsigned(sample.data[1]));
        else if (sample.data[0] >= 0) {
            m_latencies.push_back((arrival - (sample.tm.sec + sample.tm.nsec * 1e-9)) * 1e6);
            m_arrivals.push_back(arrival);
            m_bytes = sample.data.length() * sizeof(double);
        }
        return NO_CHANGE;
    }

private:
    void report(unsigned elements)
    {
        if (m_latencies.empty())
            return;
        std::vector<double> sorted = m_latencies;
        std::sort(sorted.begin(), sorted.end());
        const double mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / double(sorted.size());
        const double span = m_arrivals.back() - m_arrivals.front();
        const double mibPerSecond =
            span > 0 ? double(m_bytes) * double(m_arrivals.size() - 1) / span / (1024.0 * 1024.0) : 0.0;
        std::printf("flow %s %u %zu %.1f %.1f %.2f\n", m_instance.c_str(), elements, sorted.size(), mean,
                    sorted[sorted.size() / 2], mibPerSecond);
        std::fflush(stdout);
        m_latencies.clear();
        m_arrivals.clear();
    }

    std::string m_instance;
    std::vector<double> m_latencies;
    std::vector<double> m_arrivals;
    size_t m_bytes = 0;
};

class FlowSink : public RTC::DataFlowComponentBase
{
public:
    explicit FlowSink(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_in("in", m_sample)
    {
    }

    RTC::ReturnCode_t onInitialize() override
    {
        addInPort("in", m_in);
        m_in.addConnectorDataListener(RTC::ConnectorDataListenerType::ON_BUFFER_WRITE,
                                      new FlowListener(getInstanceName()));
        return RTC::RTC_OK;
    }

private:
    RTC::TimedDoubleSeq m_sample;
    RTC::InPort<RTC::TimedDoubleSeq> m_in;
};

extern "C" {
DLL_EXPORT void FlowSinkInit(RTC::Manager *manager)
{
    coil::Properties profile(flowsink_spec);
    manager->registerFactory(profile, RTC::Create<FlowSink>, RTC::Delete<FlowSink>);
}
}
