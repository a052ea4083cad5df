// SPDX-License-Identifier: MIT
// ConsoleIn / ConsoleOut: OpenRTM-aist's first example pair, with the console replaced by a
// counter (source) and by counting and remembering (sink) so that tests can observe the data flow.
#include "builtins.h"
#include "factorytemplate.h"

#include <BasicDataType.hh>

#include <chrono>
#include <deque>

namespace Runtime {

namespace {

RTC::Time now()
{
    const auto since = std::chrono::system_clock::now().time_since_epoch();
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(since).count();
    return RTC::Time{CORBA::ULong(ns / 1000000000), CORBA::ULong(ns % 1000000000)};
}

class ConsoleIn : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        m_out = addOutPort<RTC::TimedLong>("out");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        RTC::TimedLong sample;
        sample.tm = now();
        sample.data = ++m_counter;
        m_out->write(sample);
        setStatus("sent_count", std::to_string(m_counter));
        return RTC::RTC_OK;
    }

private:
    OutPort<RTC::TimedLong> *m_out = nullptr;
    CORBA::Long m_counter = 0;
};

class ConsoleOut : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        m_in = addInPort<RTC::TimedLong>("in");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        bool received = false;
        RTC::TimedLong sample;
        while (m_in->isNew() && m_in->read(&sample)) {
            received = true;
            ++m_count;
            m_recent.push_back(sample.data);
            if (m_recent.size() > 16)
                m_recent.pop_front();
        }
        // Pull connections deliver only when asked.
        if (!received && m_in->connectorCount() > 0 && m_in->read(&sample)) {
            received = true;
            ++m_count;
            m_recent.push_back(sample.data);
            if (m_recent.size() > 16)
                m_recent.pop_front();
        }
        if (received)
            publish();
        return RTC::RTC_OK;
    }

private:
    void publish()
    {
        std::string values;
        for (CORBA::Long value : m_recent)
            values += (values.empty() ? "" : ",") + std::to_string(value);
        setStatus({{"received_count", std::to_string(m_count)},
                   {"last_value", std::to_string(m_recent.back())},
                   {"received_values", values}});
    }

    InPort<RTC::TimedLong> *m_in = nullptr;
    long long m_count = 0;
    std::deque<CORBA::Long> m_recent;
};

} // namespace

std::vector<ComponentFactory> consoleFactories()
{
    return {builtinFactory<ConsoleIn>("ConsoleIn", "Console input component"),
            builtinFactory<ConsoleOut>("ConsoleOut", "Console output component")};
}

} // namespace Runtime
