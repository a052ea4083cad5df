// SPDX-License-Identifier: MIT
// An InPort with PortCallback functors: OnRead before each read, OnReadConvert changing what the
// component gets (plus 1000), and the port's connection callbacks (PortBase::setOnConnected,
// setOnDisconnected) reporting the connector.
#include "StyleProfile.h"

#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/PortCallback.h>
#include <rtm/idl/BasicDataTypeSkel.h>

namespace {
SDKSTYLES_SPEC(CallbackSink);

class PlusThousand : public RTC::OnReadConvert<RTC::TimedLong>
{
public:
    RTC::TimedLong operator()(const RTC::TimedLong &value) override
    {
        RTC::TimedLong converted(value);
        converted.data = value.data + 1000;
        return converted;
    }
};

class ReadCounter : public RTC::OnRead<RTC::TimedLong>
{
public:
    ReadCounter() : count(0) {}
    void operator()() override { ++count; }
    long count;
};

class Connected : public RTC::ConnectionCallback
{
public:
    void operator()(RTC::ConnectorProfile &profile) override
    {
        std::cout << "CallbackSink connected " << profile.name << std::endl;
    }
};

class Disconnected : public RTC::ConnectionCallback
{
public:
    void operator()(RTC::ConnectorProfile &profile) override
    {
        std::cout << "CallbackSink disconnected " << profile.name << std::endl;
    }
};

class CallbackSink : public RTC::DataFlowComponentBase
{
public:
    explicit CallbackSink(RTC::Manager *manager) : RTC::DataFlowComponentBase(manager), m_inIn("in", m_in) {}

    RTC::ReturnCode_t onInitialize() override
    {
        m_inIn.setOnRead(&m_reads);
        m_inIn.setOnReadConvert(&m_convert);
        m_inIn.setOnConnected(&m_connected);
        m_inIn.setOnDisconnected(&m_disconnected);
        addInPort("in", m_inIn);
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        while (m_inIn.isNew()) {
            m_inIn.read();
            std::cout << "CallbackSink read " << m_in.data << " after " << m_reads.count << " reads" << std::endl;
        }
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_in;
    RTC::InPort<RTC::TimedLong> m_inIn;
    ReadCounter m_reads;
    PlusThousand m_convert;
    Connected m_connected;
    Disconnected m_disconnected;
};
} // namespace

extern "C" {
DLL_EXPORT void CallbackSinkInit(RTC::Manager *manager)
{
    registerStyle<CallbackSink>(manager, CallbackSink_spec);
}
}
