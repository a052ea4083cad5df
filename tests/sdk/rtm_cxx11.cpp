// SPDX-License-Identifier: MIT
// The component API's public headers compile as C++11 (OpenRTP 2.0's templates force it): every
// header, and a component using the usual parts of each.
#include <rtm/BufferBase.h>
#include <rtm/BufferStatus.h>
#include <rtm/ByteData.h>
#include <rtm/ConfigAdmin.h>
#include <rtm/ConfigurationListener.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/CorbaConsumer.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>
#include <rtm/DataPortListeners.h>
#include <rtm/EventBase.h>
#include <rtm/EventPort.h>
#include <rtm/Factory.h>
#include <rtm/FsmActionListener.h>
#include <rtm/InPort.h>
#include <rtm/InPortBase.h>
#include <rtm/Macho.h>
#include <rtm/Manager.h>
#include <rtm/ManagerActionListener.h>
#include <rtm/OutPort.h>
#include <rtm/OutPortBase.h>
#include <rtm/PortBase.h>
#include <rtm/RTC.h>
#include <rtm/RTObject.h>
#include <rtm/RingBuffer.h>
#include <rtm/StaticFSM.h>
#include <rtm/SystemLogger.h>
#include <rtm/Timestamp.h>

#include <SimpleService.hh>

#include <string>
#include <vector>

namespace Cxx11Fsm {
struct Idle;
struct Busy;

FSM_TOPSTATE(Top)
{
    struct Box
    {
        Box()
            : jobs(0)
        {
        }
        long jobs;
    };
    FSM_STATE(Top);
    virtual void start(RTC::TimedLong /* job */) {}
    virtual void stop() {}

private:
    RTC::ReturnCode_t onInit() override
    {
        setState<Idle>();
        return RTC::RTC_OK;
    }
};

FSM_SUBSTATE(Idle, Top)
{
    FSM_STATE(Idle);
    void start(RTC::TimedLong job) override
    {
        TOP::box().jobs += job.data;
        setState<Busy>();
    }
};

FSM_SUBSTATE(Busy, Top)
{
    FSM_STATE(Busy);
    HISTORY();
    void stop() override
    {
        setState<Idle>();
        dispatch(Macho::Event(&TOP::start, RTC::TimedLong()));
    }
};
} // namespace Cxx11Fsm

FSM_INIT_VALUE(Cxx11Fsm::Top)
FSM_INIT_VALUE(Cxx11Fsm::Idle)
FSM_INIT_VALUE(Cxx11Fsm::Busy)

namespace {

class Cxx11Probe : public RTC::DataFlowComponentBase
{
public:
    explicit Cxx11Probe(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager), m_inIn("in", m_in), m_outOut("out", m_out), m_port("service"), m_gain(1.0),
          m_fsm(this), m_eventIn("event", m_fsm)
    {
    }
    RTC::ReturnCode_t onInitialize() override
    {
        addInPort("in", m_inIn);
        addOutPort("out", m_outOut);
        m_port.registerConsumer("service", "SimpleService::MyService", m_service);
        addPort(m_port);
        bindParameter("gain", m_gain, "1.0");
        bindParameter("name", m_name, "probe");
        RTC_INFO(("%s ready", getInstanceName()));
        addInPort("event", m_eventIn);
        m_eventIn.bindEvent("start", &Cxx11Fsm::Top::start);
        m_eventIn.bindEvent("stop", &Cxx11Fsm::Top::stop);
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        m_fsm.run_event();
        if (m_inIn.isNew()) {
            m_inIn.read();
            m_out.data = static_cast<CORBA::Double>(m_in.data) * m_gain;
            setTimestamp(m_out);
            m_outOut.write();
        }
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_in;
    RTC::InPort<RTC::TimedLong> m_inIn;
    RTC::TimedDouble m_out;
    RTC::OutPort<RTC::TimedDouble> m_outOut;
    RTC::CorbaPort m_port;
    RTC::CorbaConsumer<SimpleService::MyService> m_service;
    double m_gain;
    std::string m_name;
    RTC::Machine<Cxx11Fsm::Top> m_fsm;
    RTC::EventInPort<RTC::Machine<Cxx11Fsm::Top> > m_eventIn;
};

} // namespace

extern "C" DLL_EXPORT void Cxx11ProbeInit(RTC::Manager *manager)
{
    static const char *const spec[] = {"implementation_id", "Cxx11Probe", "type_name", "Cxx11Probe", ""};
    coil::Properties profile(spec);
    manager->registerFactory(profile, RTC::Create<Cxx11Probe>, RTC::Delete<Cxx11Probe>);
}
