// SPDX-License-Identifier: MIT
// A loadable module written against the component SDK (OpenRTM-aist's C++ API): rtmanager's
// load_module must find its init function, which registers the "ModuleCounter" component type.
// A create request's init_delay_ms slows its initialisation down by that many milliseconds.
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/Manager.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

namespace {

const char *const moduleCounterSpec[] = {"implementation_id", "ModuleCounter",
                                         "type_name", "ModuleCounter",
                                         "description", "Counter from a loaded module",
                                         "version", "2.0.0",
                                         "vendor", "RTStudioTests",
                                         "category", "example",
                                         "activity_type", "PERIODIC",
                                         "kind", "DataFlowComponent",
                                         "max_instance", "0",
                                         "language", "C++",
                                         "lang_type", "compile",
                                         ""};

class ModuleCounter : public RTC::DataFlowComponentBase
{
public:
    explicit ModuleCounter(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_outOut("out", m_out)
    {
    }

    RTC::ReturnCode_t onInitialize() override
    {
        addOutPort("out", m_outOut);
        // A create request's init_delay_ms makes this one of the components that take a while to
        // start, for the tests of how long a client waits for a manager.
        const std::string delay = getProperties().getProperty("init_delay_ms");
        if (!delay.empty())
            std::this_thread::sleep_for(std::chrono::milliseconds(std::stoi(delay)));
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        m_out.data = ++m_count;
        setTimestamp(m_out);
        m_outOut.write();
        // The runtime's status list lets the tests see how far the counter got.
        setStatus("sent_count", std::to_string(m_count));
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_out;
    RTC::OutPort<RTC::TimedLong> m_outOut;
    CORBA::Long m_count = 0;
};

} // namespace

extern "C" DLL_EXPORT void ManagerTestModuleInit(RTC::Manager *manager)
{
    // A module whose init function hangs, for the tests of a manager that lists its modules.
    if (const char *delay = std::getenv("MANAGER_TEST_MODULE_INIT_DELAY_MS"))
        std::this_thread::sleep_for(std::chrono::milliseconds(std::atoi(delay)));
    coil::Properties profile(moduleCounterSpec);
    manager->registerFactory(profile, RTC::Create<ModuleCounter>, RTC::Delete<ModuleCounter>);
}
