// SPDX-License-Identifier: MIT
// The traffic light's state machine, a static FSM in OpenRTM-aist 2.x style.
//
//   Top (Box: the last fault code)
//   ├── Dark                     on → Running
//   ├── Running (HISTORY)        init → Red; off → Dark; fault(code) → Flashing
//   │   ├── Red                  go → Green
//   │   └── Green
//   └── Flashing                 repair → Running's history; off → Dark; fault(code) records it
#ifndef TRAFFICLIGHTFSM_H
#define TRAFFICLIGHTFSM_H

#include <rtm/idl/BasicDataTypeSkel.h>

#include <rtm/RTC.h>
#include <rtm/StaticFSM.h>

namespace TrafficLightFsm
{
FSM_TOPSTATE(Top)
{
    struct Box
    {
        Box()
            : fault(0)
        {
        }
        CORBA::Long fault;
    };

    FSM_STATE(Top);

    // The machine's events; a state handles the ones it overrides.
    virtual void on() {}
    virtual void off() {}
    virtual void go() {}
    virtual void fault(RTC::TimedLong /* code */) {}
    virtual void repair() {}

private:
    RTC::ReturnCode_t onInit() override;
};

FSM_SUBSTATE(Dark, Top)
{
    FSM_STATE(Dark);

    void on() override;
};

FSM_SUBSTATE(Running, Top)
{
    FSM_STATE(Running);
    HISTORY();

    void off() override;
    void fault(RTC::TimedLong code) override;

private:
    RTC::ReturnCode_t onInit() override;
};

FSM_SUBSTATE(Red, Running)
{
    FSM_STATE(Red);

    void go() override;
};

FSM_SUBSTATE(Green, Running)
{
    FSM_STATE(Green);
};

FSM_SUBSTATE(Flashing, Top)
{
    FSM_STATE(Flashing);

    void off() override;
    void repair() override;
    void fault(RTC::TimedLong code) override;

private:
    RTC::ReturnCode_t onEntry() override;
};
} // namespace TrafficLightFsm

#endif // TRAFFICLIGHTFSM_H
