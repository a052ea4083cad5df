// SPDX-License-Identifier: MIT
// TrafficLight as a standalone program.
#include "TrafficLight.h"

#include <rtm/Manager.h>

#include <iostream>

static void MyModuleInit(RTC::Manager *manager)
{
    TrafficLightInit(manager);
    RTC::RTObject_impl *comp = manager->createComponent("TrafficLight");
    if (comp == nullptr)
        std::cerr << "TrafficLight: the component could not be created" << std::endl;
}

int main(int argc, char **argv)
{
    RTC::Manager *manager = RTC::Manager::init(argc, argv);
    manager->setModuleInitProc(MyModuleInit);
    manager->activateManager();
    manager->runManager();
    return 0;
}
