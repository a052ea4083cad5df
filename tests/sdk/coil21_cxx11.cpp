// SPDX-License-Identifier: MIT
// Compiled as C++11 (gnu++11) by tests/sdkcoil.cmake: coil 2.1's Timer, Factory, Logger, Affinity,
// SharedMemory and Routing headers, with their templates instantiated as component code does.
#include <coil/Affinity.h>
#include <coil/Factory.h>
#include <coil/Logger.h>
#include <coil/Routing.h>
#include <coil/SharedMemory.h>
#include <coil/Timer.h>

#include <chrono>
#include <memory>
#include <string>

#if __cplusplus != 201103L
#error "this file checks the coil headers as C++11"
#endif

namespace {
class Plugin
{
public:
    virtual ~Plugin() { }
};
class Concrete : public Plugin
{
};
} // namespace

int sdkcoil21_cxx11_check()
{
    coil::Timer<coil::PeriodicFunction> timer;
    coil::Timer<coil::PeriodicFunction>::TaskId id = timer.emplace([] { }, std::chrono::milliseconds(10));
    timer.tick(std::chrono::milliseconds(10));
    id->stop();
    coil::Timer<std::unique_ptr<coil::DelayedFunction> > delayed;
    delayed.emplace(new coil::DelayedFunction([] { }, std::chrono::milliseconds(1)));
    delayed.tick(std::chrono::milliseconds(1));

    typedef coil::GlobalFactory<Plugin> PluginFactory;
    PluginFactory::instance().addFactory("c", coil::Creator<Plugin, Concrete>, coil::Destructor<Plugin, Concrete>);
    Plugin *plugin = PluginFactory::instance().createObject("c");
    const bool made = PluginFactory::instance().deleteObject(plugin) == coil::FactoryReturn::OK;

    coil::CpuMask mask;
    coil::getThreadCpuAffinity(mask);
    coil::SharedMemory memory;
    std::string endpoint;
    coil::dest_to_endpoint("127.0.0.1", endpoint);
    coil::LogStreamBuffer buffer;
    return made && !mask.empty() && memory.get_data() == 0 && buffer.getBuffers().empty() ? 0 : 1;
}
