// SPDX-License-Identifier: MIT
#include "TrafficLightFsm.h"

#include <iostream>

FSM_INIT_VALUE(TrafficLightFsm::Top)
FSM_INIT_VALUE(TrafficLightFsm::Dark)
FSM_INIT_VALUE(TrafficLightFsm::Running)
FSM_INIT_VALUE(TrafficLightFsm::Red)
FSM_INIT_VALUE(TrafficLightFsm::Green)
FSM_INIT_VALUE(TrafficLightFsm::Flashing)

namespace TrafficLightFsm
{
RTC::ReturnCode_t Top::onInit()
{
    setState<Dark>();
    return RTC::RTC_OK;
}

void Dark::on()
{
    setState<Running>();
}

RTC::ReturnCode_t Running::onInit()
{
    setState<Red>();
    return RTC::RTC_OK;
}

void Running::off()
{
    setState<Dark>();
}

void Running::fault(RTC::TimedLong code)
{
    TOP::box().fault = code.data;
    setState<Flashing>();
}

void Red::go()
{
    setState<Green>();
}

RTC::ReturnCode_t Flashing::onEntry()
{
    std::cout << "[TrafficLight] flashing, fault " << TOP::box().fault << std::endl;
    return RTC::RTC_OK;
}

void Flashing::off()
{
    setState<Dark>();
}

void Flashing::repair()
{
    // Back to the light Running showed before the fault.
    setStateHistory<Running>();
}

void Flashing::fault(RTC::TimedLong code)
{
    TOP::box().fault = code.data;
}
} // namespace TrafficLightFsm
