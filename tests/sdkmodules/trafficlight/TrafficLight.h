// SPDX-License-Identifier: MIT
// TrafficLight: a static FSM component. Its events arrive at the EventInPort "event" (one
// connection per event, named by the connector property fsm_event_name or by the connector's
// name); onExecute runs them and writes the light on the OutPort "state": 0 dark, 1 red,
// 2 green, 1000 + the fault code while flashing.
#ifndef TRAFFICLIGHT_H
#define TRAFFICLIGHT_H

// The data types first: OpenRTM-aist's port templates need their CORBA::Any operators declared.
#include <rtm/idl/BasicDataTypeSkel.h>

#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/EventPort.h>
#include <rtm/Manager.h>

#include "TrafficLightFsm.h"

class TrafficLight : public RTC::DataFlowComponentBase
{
public:
    explicit TrafficLight(RTC::Manager *manager);
    ~TrafficLight() override;

    RTC::ReturnCode_t onInitialize() override;
    RTC::ReturnCode_t onExecute(RTC::UniqueId ec_id) override;

private:
    void stateChanged(const char *state, RTC::ReturnCode_t ret);
    CORBA::Long lightCode();

    RTC::Machine<TrafficLightFsm::Top> m_fsm;
    RTC::EventInPort<RTC::Machine<TrafficLightFsm::Top> > m_eventIn;
    RTC::TimedLong m_state;
    RTC::OutPort<RTC::TimedLong> m_stateOut;
};

extern "C" {
DLL_EXPORT void TrafficLightInit(RTC::Manager *manager);
}

#endif // TRAFFICLIGHT_H
