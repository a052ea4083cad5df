// SPDX-License-Identifier: MIT
#include "TrafficLight.h"

static const char *const trafficlight_spec[] = {"implementation_id", "TrafficLight",
                                                "type_name", "TrafficLight",
                                                "description", "A traffic light as a static FSM component",
                                                "version", "1.0.0",
                                                "vendor", "RTStudioTests",
                                                "category", "test",
                                                "activity_type", "PERIODIC",
                                                "kind", "DataFlowComponent",
                                                "max_instance", "0",
                                                "language", "C++",
                                                "lang_type", "compile",
                                                ""};

TrafficLight::TrafficLight(RTC::Manager *manager)
    : RTC::DataFlowComponentBase(manager)
    , m_fsm(this)
    , m_eventIn("event", m_fsm)
    , m_stateOut("state", m_state)
{
}

TrafficLight::~TrafficLight() = default;

RTC::ReturnCode_t TrafficLight::onInitialize()
{
    addInPort("event", m_eventIn);
    addOutPort("state", m_stateOut);
    m_eventIn.bindEvent("on", &TrafficLightFsm::Top::on);
    m_eventIn.bindEvent("off", &TrafficLightFsm::Top::off);
    m_eventIn.bindEvent("go", &TrafficLightFsm::Top::go);
    m_eventIn.bindEvent("fault", &TrafficLightFsm::Top::fault);
    m_eventIn.bindEvent("repair", &TrafficLightFsm::Top::repair);
    addPostFsmActionListener(RTC::PostFsmActionListenerType::POST_ON_STATE_CHANGE, *this,
                             &TrafficLight::stateChanged);
    return RTC::RTC_OK;
}

RTC::ReturnCode_t TrafficLight::onExecute(RTC::UniqueId /* ec_id */)
{
    m_fsm.run_event();
    m_state.data = lightCode();
    setTimestamp(m_state);
    m_stateOut.write();
    return RTC::RTC_OK;
}

void TrafficLight::stateChanged(const char *state, RTC::ReturnCode_t /* ret */)
{
    RTC_INFO(("light: %s", state));
}

CORBA::Long TrafficLight::lightCode()
{
    using namespace TrafficLightFsm;
    if (Flashing::isCurrent(m_fsm))
        return 1000 + m_fsm.box().fault;
    if (Green::isCurrent(m_fsm))
        return 2;
    if (Red::isCurrent(m_fsm))
        return 1;
    return 0;
}

extern "C" {
void TrafficLightInit(RTC::Manager *manager)
{
    coil::Properties profile(trafficlight_spec);
    manager->registerFactory(profile, RTC::Create<TrafficLight>, RTC::Delete<TrafficLight>);
}
}
