// SPDX-License-Identifier: MIT
// MyServiceProvider / MyServiceConsumer: OpenRTM-aist's service port example over
// SimpleService::MyService, interface instance "myservice" on port "MyService" as there. Like
// OpenRTM-aist's consumer it has no configuration; instead of reading commands from the console it
// calls echo() every hundredth execution once connected (status `echo_count`, `last_reply`).
#include "builtins.h"
#include "factorytemplate.h"

#include <SimpleService.hh>

#include <mutex>
#include <vector>

namespace Runtime {

namespace {

class MyServiceServant : public virtual POA_SimpleService::MyService
{
public:
    char *echo(const char *msg) override
    {
        std::lock_guard lock(m_mutex);
        m_echoes.emplace_back(msg);
        return CORBA::string_dup(msg);
    }
    SimpleService::EchoList *get_echo_history() override
    {
        std::lock_guard lock(m_mutex);
        auto *list = new SimpleService::EchoList;
        list->length(CORBA::ULong(m_echoes.size()));
        for (CORBA::ULong i = 0; i < list->length(); ++i)
            (*list)[i] = m_echoes[i].c_str();
        return list;
    }
    void set_value(CORBA::Float value) override
    {
        std::lock_guard lock(m_mutex);
        m_values.push_back(value);
    }
    CORBA::Float get_value() override
    {
        std::lock_guard lock(m_mutex);
        return m_values.empty() ? 0.0f : m_values.back();
    }
    SimpleService::ValueList *get_value_history() override
    {
        std::lock_guard lock(m_mutex);
        auto *list = new SimpleService::ValueList;
        list->length(CORBA::ULong(m_values.size()));
        for (CORBA::ULong i = 0; i < list->length(); ++i)
            (*list)[i] = m_values[i];
        return list;
    }

private:
    std::mutex m_mutex;
    std::vector<std::string> m_echoes;
    std::vector<CORBA::Float> m_values;
};

class MyServiceProvider : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        ServicePort *port = addServicePort("MyService");
        port->registerProvider("myservice", "SimpleService::MyService", new MyServiceServant);
        return RTC::RTC_OK;
    }
};

class MyServiceConsumer : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        ServicePort *port = addServicePort("MyService");
        m_service = port->registerConsumer("myservice", "SimpleService::MyService");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        if (++m_ticks % kCallInterval != 0)
            return RTC::RTC_OK;
        CORBA::Object_var object = m_service->object();
        if (CORBA::is_nil(object))
            return RTC::RTC_OK;
        try {
            SimpleService::MyService_var service = SimpleService::MyService::_narrow(object);
            const std::string message = "echo " + std::to_string(++m_calls);
            CORBA::String_var reply = service->echo(message.c_str());
            setStatus({{"echo_count", std::to_string(m_calls)}, {"last_reply", std::string(reply.in())}});
        } catch (const CORBA::Exception &) {
            setStatus("last_error", "provider unreachable");
        }
        return RTC::RTC_OK;
    }

private:
    std::shared_ptr<ConsumerSlot> m_service;
    static constexpr long kCallInterval = 100;
    long m_ticks = 0;
    long m_calls = 0;
};

} // namespace

std::vector<ComponentFactory> serviceFactories()
{
    return {builtinFactory<MyServiceProvider>("MyServiceProvider", "MyService Provider Sample component"),
            builtinFactory<MyServiceConsumer>("MyServiceConsumer", "MyService Consumer Sample component")};
}

} // namespace Runtime
