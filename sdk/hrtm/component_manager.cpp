// SPDX-License-Identifier: MIT
// hrtm::ComponentManager: HRTM's names for the process's RTC::Manager.
#include <hrtm/component_manager.h>
#include <hrtm/data_flow_component.h>

#include "../rtm/sdkinternal.h"

#include <cstdlib>
#include <iostream>

namespace hrtm {
ModuleInitProc ComponentManager::initProc = nullptr;
ComponentManager *ComponentManager::manager = nullptr;
std::mutex ComponentManager::mutex;

DataFlowComponent *ComponentManager::create_component(const char *component_name)
{
    return dynamic_cast<hrtm::DataFlowComponent *>(RTC::Manager::createComponent(component_name));
}

void ComponentManager::set_init_proc(void (*init_proc)(hrtm::ComponentManager *))
{
    initProc = init_proc;
    setModuleInitProc(&ComponentManager::init_proc);
}

bool ComponentManager::activate()
{
    return activateManager();
}

void ComponentManager::run(bool non_block)
{
    runManager(non_block);
}

void ComponentManager::init_proc(RTC::Manager * /*mgr*/)
{
    if (initProc != nullptr)
        initProc(manager);
}

ComponentManager &ComponentManager::instance(int argc, char **argv)
{
    std::lock_guard<std::mutex> guard(mutex);
    if (manager != nullptr)
        return *manager;
    // This object must be the manager RTC::Manager::init() starts (and that components find
    // through RTC::Manager::instance()), so it is installed before init() runs.
    ComponentManager *created = new ComponentManager();
    if (!RTC::Sdk::adoptManager(created)) {
        std::cerr << (argc > 0 ? argv[0] : "hrtm") << ": hrtm::ComponentManager::instance(): the process "
                  << "already has an RTC::Manager; an HRTM program must create its manager first" << std::endl;
        std::exit(1);
    }
    manager = created;
    RTC::Manager::init(argc, argv);
    return *manager;
}

ComponentManager::ComponentManager()
    : RTC::Manager()
{ }

ComponentManager::~ComponentManager() = default;
} // namespace hrtm
