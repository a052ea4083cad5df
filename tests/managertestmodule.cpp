// SPDX-License-Identifier: MIT
// A loadable module written against the runtime: rtmanager's load_module must find its init
// function, which registers the "ModuleCounter" component type.
#include "componentfactory.h"
#include "manager.h"
#include "rtobject.h"

namespace {

class ModuleCounter : public Runtime::RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        m_out = addOutPort<RTC::TimedLong>("out");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        RTC::TimedLong sample{};
        sample.data = ++m_count;
        m_out->write(sample);
        setStatus("sent_count", std::to_string(m_count));
        return RTC::RTC_OK;
    }

private:
    Runtime::OutPort<RTC::TimedLong> *m_out = nullptr;
    CORBA::Long m_count = 0;
};

} // namespace

extern "C" void ManagerTestModuleInit(Runtime::Manager *manager)
{
    Runtime::ComponentFactory factory;
    factory.profile = Runtime::exampleProfile("ModuleCounter", "Counter from a loaded module");
    factory.profile.set("vendor", "RTStudioTests");
    factory.create = [](PortableServer::POA_ptr poa) -> Runtime::RtObject * { return new ModuleCounter(poa); };
    manager->registerFactory(std::move(factory));
}
