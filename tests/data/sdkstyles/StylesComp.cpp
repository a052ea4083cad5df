// SPDX-License-Identifier: MIT
// A component program in the <Name>Comp style: registers every style component in its module
// init procedure and creates those the environment variable STYLES_CREATE names (comma separated,
// each may carry ?key=value parameters as create arguments do), then runs the manager.
#include <rtm/Manager.h>
#include <rtm/RTObject.h>

#include <coil/stringutil.h>

#include <cstdlib>
#include <iostream>
#include <string>

extern "C" {
void CallbackSourceInit(RTC::Manager *manager);
void CallbackSinkInit(RTC::Manager *manager);
void ConnectorWatcherInit(RTC::Manager *manager);
void TimerCounterInit(RTC::Manager *manager);
void TaskProducerInit(RTC::Manager *manager);
void TickCounterInit(RTC::Manager *manager);
void LoggingCompInit(RTC::Manager *manager);
}

namespace {
void stylesInit(RTC::Manager *manager)
{
    CallbackSourceInit(manager);
    CallbackSinkInit(manager);
    ConnectorWatcherInit(manager);
    TimerCounterInit(manager);
    TaskProducerInit(manager);
    TickCounterInit(manager);
    LoggingCompInit(manager);
    const char *names = std::getenv("STYLES_CREATE");
    for (const std::string &name : coil::split(names ? names : "", ",")) {
        RTC::RtcBase *component = manager->createComponent(name.c_str());
        if (component == nullptr) {
            std::cerr << "StylesComp: cannot create " << name << std::endl;
            std::exit(1);
        }
        std::cout << "StylesComp created " << component->getInstanceName() << std::endl;
    }
}
} // namespace

int main(int argc, char **argv)
{
    RTC::Manager *manager = RTC::Manager::init(argc, argv);
    manager->setModuleInitProc(stylesInit);
    manager->activateManager();
    manager->runManager();
    return 0;
}
