// SPDX-License-Identifier: MIT
// The component API's public headers compile as C++11 (OpenRTP 2.0's templates force it): every
// header, and a component using the usual parts of each.
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
#include <rtm/Factory.h>
#include <rtm/InPort.h>
#include <rtm/InPortBase.h>
#include <rtm/Manager.h>
#include <rtm/ManagerActionListener.h>
#include <rtm/OutPort.h>
#include <rtm/OutPortBase.h>
#include <rtm/PortBase.h>
#include <rtm/RTC.h>
#include <rtm/RTObject.h>
#include <rtm/SystemLogger.h>
#include <rtm/Timestamp.h>

#include <SimpleService.hh>

#include <string>
#include <vector>

namespace {

class Cxx11Probe : public RTC::DataFlowComponentBase
{
public:
    explicit Cxx11Probe(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager), m_inIn("in", m_in), m_outOut("out", m_out), m_port("service"), m_gain(1.0)
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
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
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
};

} // namespace

extern "C" DLL_EXPORT void Cxx11ProbeInit(RTC::Manager *manager)
{
    static const char *const spec[] = {"implementation_id", "Cxx11Probe", "type_name", "Cxx11Probe", ""};
    coil::Properties profile(spec);
    manager->registerFactory(profile, RTC::Create<Cxx11Probe>, RTC::Delete<Cxx11Probe>);
}
