// SPDX-License-Identifier: MIT
#include "livesystempeer.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <thread>

namespace LivePeer {

using Lock = std::lock_guard<std::recursive_mutex>;

namespace {

void setNV(SDOPackage::NVList &list, const std::string &name, const std::string &value)
{
    const CORBA::ULong n = list.length();
    list.length(n + 1);
    list[n].name = name.c_str();
    list[n].value <<= value.c_str();
}

RTC::PortProfile dataPort(const std::string &direction, const std::string &dataType)
{
    RTC::PortProfile profile;
    setNV(profile.properties, "port.port_type", direction);
    setNV(profile.properties, "dataport.data_type", dataType);
    setNV(profile.properties, "dataport.dataflow_type", "push, pull");
    setNV(profile.properties, "dataport.interface_type", "corba_cdr");
    setNV(profile.properties, "dataport.subscription_type", "flush, new, periodic");
    return profile;
}

RTC::PortProfile servicePort(bool provided)
{
    RTC::PortProfile profile;
    setNV(profile.properties, "port.port_type", "CorbaPort");
    profile.interfaces.length(1);
    profile.interfaces[0].instance_name = "myservice";
    profile.interfaces[0].type_name = "SimpleService::MyService";
    profile.interfaces[0].polarity = provided ? RTC::PROVIDED : RTC::REQUIRED;
    return profile;
}

const char *const timedLong = "IDL:RTC/TimedLong:1.0";
const char *const timedDouble = "IDL:RTC/TimedDouble:1.0";
const std::set<std::string> knownTypes {"ConsoleIn",   "ConsoleOut",        "SeqIn",
                                        "Motor",       "MyServiceProvider", "MyServiceConsumer",
                                        "ConfigSample"};

void deactivate(Context &context, PortableServer::Servant servant)
{
    try {
        PortableServer::ObjectId_var id = context.poa->servant_to_id(servant);
        context.poa->deactivate_object(id.in());
    } catch (const CORBA::Exception &) {
        // Already deactivated.
    }
}

} // namespace

// Component --------------------------------------------------------------------------------------

Component::Component(Context &context, std::string type, std::string instance)
    : m_context(context)
    , m_type(std::move(type))
    , m_instance(std::move(instance))
{ }

void Component::addPort(const std::string &name, RTC::PortProfile profile)
{
    profile.name = (m_instance + "." + name).c_str();
    auto *port = new Port(m_context, profile);
    RTC::PortService_var reference = port->_this();
    port->setReference(reference.in(), m_self.in());
    port->_remove_ref();
    m_ports.push_back(reference);
}

Component *Component::create(Context &context, const std::string &type, const std::string &instance)
{
    if (!knownTypes.count(type))
        return nullptr;
    auto *component = new Component(context, type, instance);
    component->m_self = component->_this();
    // The POA holds the component from here on; destroy() deactivates it, which deletes it.
    component->_remove_ref();
    auto *ec = new ExecutionContext(context);
    ec->setOwner(component);
    component->m_ec = ec->_this();
    ec->_remove_ref();
    auto *configuration = new Configuration(context);
    configuration->addSet("default", {});
    if (type == "ConsoleIn" || type == "Motor")
        component->addPort("out", dataPort("DataOutPort", timedLong));
    if (type == "ConsoleOut" || type == "Motor")
        component->addPort("in", dataPort("DataInPort", timedLong));
    if (type == "SeqIn") {
        component->addPort("Long", dataPort("DataInPort", timedLong));
        component->addPort("Double", dataPort("DataInPort", timedDouble));
    }
    if (type == "MyServiceProvider" || type == "MyServiceConsumer")
        component->addPort("MyService", servicePort(type == "MyServiceProvider"));
    if (type == "Motor")
        configuration->addSet("default", {{"motor_id", "0"}});
    if (type == "ConfigSample") {
        configuration = new Configuration(context);
        configuration->addSet(
            "default", {{"int_param0", "0"}, {"double_param0", "0.11"}, {"str_param0", "hoge"}});
        configuration->addSet(
            "mode0", {{"int_param0", "12345"}, {"double_param0", "3.14"}, {"str_param0", "foo"}});
        configuration->addSet("__widget__", {{"int_param0", "slider.1"}});
    }
    configuration->setActive("default");
    component->m_configuration = configuration->_this();
    configuration->_remove_ref();
    context.bind(instance, "rtc", component->m_self.in());
    return component;
}

void Component::destroy()
{
    if (m_destroyed)
        return;
    m_destroyed = true;
    m_context.unbind(m_instance, "rtc");
    for (auto &port : m_ports) {
        if (PortableServer::ServantBase *servant = m_context.poa->reference_to_servant(port.in())) {
            deactivate(m_context, servant);
            servant->_remove_ref();
        }
    }
    for (CORBA::Object_ptr object :
         {CORBA::Object_ptr(m_ec.in()), CORBA::Object_ptr(m_configuration.in())}) {
        if (PortableServer::ServantBase *servant = m_context.poa->reference_to_servant(object)) {
            deactivate(m_context, servant);
            servant->_remove_ref();
        }
    }
    deactivate(m_context, this);
}

RTC::ReturnCode_t Component::exit()
{
    Lock lock(m_context.mutex);
    if (m_context.manager)
        m_context.manager->remove(this);
    destroy();
    return RTC::RTC_OK;
}

RTC::ExecutionContext_ptr Component::get_context(RTC::ExecutionContextHandle_t handle)
{
    return handle == 0 ? RTC::ExecutionContext::_duplicate(m_ec.in())
                       : RTC::ExecutionContext::_nil();
}

RTC::ExecutionContextList *Component::get_owned_contexts()
{
    auto *list = new RTC::ExecutionContextList;
    list->length(1);
    (*list)[0] = RTC::ExecutionContext::_duplicate(m_ec.in());
    return list;
}

RTC::ExecutionContextList *Component::get_participating_contexts()
{
    return new RTC::ExecutionContextList;
}

RTC::ExecutionContextHandle_t Component::get_context_handle(RTC::ExecutionContext_ptr cxt)
{
    return cxt->_is_equivalent(m_ec.in()) ? 0 : -1;
}

SDOPackage::OrganizationList *Component::get_owned_organizations()
{
    return new SDOPackage::OrganizationList;
}

SDOPackage::DeviceProfile *Component::get_device_profile()
{
    return new SDOPackage::DeviceProfile;
}

SDOPackage::ServiceProfileList *Component::get_service_profiles()
{
    return new SDOPackage::ServiceProfileList;
}

SDOPackage::ServiceProfile *Component::get_service_profile(const char *)
{
    throw SDOPackage::InvalidParameter("no service profiles");
}

SDOPackage::SDOService_ptr Component::get_sdo_service(const char *)
{
    throw SDOPackage::InvalidParameter("no SDO services");
}

SDOPackage::Configuration_ptr Component::get_configuration()
{
    return SDOPackage::Configuration::_duplicate(m_configuration.in());
}

SDOPackage::Monitoring_ptr Component::get_monitoring()
{
    throw SDOPackage::InterfaceNotImplemented("no monitoring");
}

SDOPackage::OrganizationList *Component::get_organizations()
{
    return new SDOPackage::OrganizationList;
}

SDOPackage::NVList *Component::get_status_list()
{
    return new SDOPackage::NVList;
}

CORBA::Any *Component::get_status(const char *)
{
    throw SDOPackage::InvalidParameter("no status");
}

RTC::ComponentProfile *Component::get_component_profile()
{
    auto *profile = new RTC::ComponentProfile;
    profile->instance_name = m_instance.c_str();
    profile->type_name = m_type.c_str();
    profile->description = (m_type + " example component").c_str();
    profile->version = "1.0.0";
    profile->vendor = "AIST";
    profile->category = "example";
    profile->parent = RTC::RTObject::_nil();
    setNV(profile->properties, "implementation_id", m_type);
    setNV(profile->properties, "instance_name", m_instance);
    profile->port_profiles.length(CORBA::ULong(m_ports.size()));
    for (size_t i = 0; i < m_ports.size(); ++i) {
        RTC::PortProfile_var port = m_ports[i]->get_port_profile();
        profile->port_profiles[CORBA::ULong(i)] = port.in();
    }
    return profile;
}

RTC::PortServiceList *Component::get_ports()
{
    auto *list = new RTC::PortServiceList;
    list->length(CORBA::ULong(m_ports.size()));
    for (size_t i = 0; i < m_ports.size(); ++i)
        (*list)[CORBA::ULong(i)] = RTC::PortService::_duplicate(m_ports[i].in());
    return list;
}

// Manager ----------------------------------------------------------------------------------------

void Manager::remove(Component *component)
{
    Lock lock(m_context.mutex);
    m_components.erase(std::remove(m_components.begin(), m_components.end(), component),
                       m_components.end());
}

// `Type?instance_name=NAME&k=v`; keys other than instance_name are accepted and ignored.
Component *Manager::createFromArgument(const std::string &argument)
{
    Lock lock(m_context.mutex);
    const size_t question = argument.find('?');
    const std::string type = argument.substr(0, question);
    std::string instance;
    if (question != std::string::npos) {
        const std::string query = argument.substr(question + 1);
        if (query.find('?') != std::string::npos)
            return nullptr;
        size_t start = 0;
        while (start <= query.size()) {
            const size_t end = std::min(query.find('&', start), query.size());
            const std::string pair = query.substr(start, end - start);
            if (pair.rfind("instance_name=", 0) == 0)
                instance = pair.substr(14);
            start = end + 1;
        }
    }
    for (int n = 0; instance.empty(); ++n) {
        const std::string candidate = type + std::to_string(n);
        const bool taken = std::any_of(m_components.begin(), m_components.end(), [&](Component *c) {
            return c->instanceName() == candidate;
        });
        if (!taken)
            instance = candidate;
    }
    for (Component *existing : m_components) {
        if (existing->instanceName() == instance)
            return nullptr;
    }
    Component *component = Component::create(m_context, type, instance);
    if (component)
        add(component);
    return component;
}

RTC::ReturnCode_t Manager::load_module(const char *pathname, const char *)
{
    Lock lock(m_context.mutex);
    if (std::string(pathname).empty())
        return RTC::BAD_PARAMETER;
    m_loaded.push_back(pathname);
    return RTC::RTC_OK;
}

RTC::ReturnCode_t Manager::unload_module(const char *pathname)
{
    Lock lock(m_context.mutex);
    const auto it = std::find(m_loaded.begin(), m_loaded.end(), std::string(pathname));
    if (it == m_loaded.end())
        return RTC::BAD_PARAMETER;
    m_loaded.erase(it);
    return RTC::RTC_OK;
}

RTM::ModuleProfileList *Manager::get_loadable_modules()
{
    auto *list = new RTM::ModuleProfileList;
    for (const std::string &type : knownTypes) {
        list->length(list->length() + 1);
        setNV((*list)[list->length() - 1].properties, "module_file_name", type + ".so");
    }
    return list;
}

RTM::ModuleProfileList *Manager::get_loaded_modules()
{
    Lock lock(m_context.mutex);
    auto *list = new RTM::ModuleProfileList;
    for (const std::string &path : m_loaded) {
        list->length(list->length() + 1);
        setNV((*list)[list->length() - 1].properties, "file_path", path);
    }
    return list;
}

RTM::ModuleProfileList *Manager::get_factory_profiles()
{
    auto *list = new RTM::ModuleProfileList;
    for (const std::string &type : knownTypes) {
        list->length(list->length() + 1);
        setNV((*list)[list->length() - 1].properties, "implementation_id", type);
    }
    return list;
}

RTC::RTObject_ptr Manager::create_component(const char *module_name)
{
    Component *component = createFromArgument(module_name);
    return component ? RTC::RTObject::_duplicate(component->reference()) : RTC::RTObject::_nil();
}

RTC::ReturnCode_t Manager::delete_component(const char *instance_name)
{
    Lock lock(m_context.mutex);
    for (Component *component : m_components) {
        if (component->instanceName() == instance_name) {
            remove(component);
            component->destroy();
            return RTC::RTC_OK;
        }
    }
    return RTC::BAD_PARAMETER;
}

RTC::RTCList *Manager::get_components()
{
    Lock lock(m_context.mutex);
    auto *list = new RTC::RTCList;
    list->length(CORBA::ULong(m_components.size()));
    for (size_t i = 0; i < m_components.size(); ++i)
        (*list)[CORBA::ULong(i)] = RTC::RTObject::_duplicate(m_components[i]->reference());
    return list;
}

RTC::ComponentProfileList *Manager::get_component_profiles()
{
    Lock lock(m_context.mutex);
    auto *list = new RTC::ComponentProfileList;
    list->length(CORBA::ULong(m_components.size()));
    for (size_t i = 0; i < m_components.size(); ++i) {
        RTC::ComponentProfile_var profile = m_components[i]->get_component_profile();
        (*list)[CORBA::ULong(i)] = profile.in();
    }
    return list;
}

RTC::RTCList *Manager::get_components_by_name(const char *name)
{
    Lock lock(m_context.mutex);
    auto *list = new RTC::RTCList;
    for (Component *component : m_components) {
        if (component->instanceName() == name) {
            list->length(list->length() + 1);
            (*list)[list->length() - 1] = RTC::RTObject::_duplicate(component->reference());
        }
    }
    return list;
}

RTM::ManagerProfile *Manager::get_profile()
{
    auto *profile = new RTM::ManagerProfile;
    setNV(profile->properties, "name", "manager");
    setNV(profile->properties, "instance_name", "manager");
    return profile;
}

RTM::NVList *Manager::get_configuration()
{
    Lock lock(m_context.mutex);
    auto *list = new RTM::NVList;
    for (const auto &entry : m_configuration)
        setNV(*list, entry.first, entry.second);
    return list;
}

RTC::ReturnCode_t Manager::set_configuration(const char *name, const char *value)
{
    Lock lock(m_context.mutex);
    for (auto &entry : m_configuration) {
        if (entry.first == name) {
            entry.second = value;
            return RTC::RTC_OK;
        }
    }
    m_configuration.emplace_back(name, value);
    return RTC::RTC_OK;
}

namespace {

RTM::ManagerList *copyList(const std::vector<RTM::Manager_var> &managers)
{
    auto *list = new RTM::ManagerList;
    list->length(CORBA::ULong(managers.size()));
    for (size_t i = 0; i < managers.size(); ++i)
        (*list)[CORBA::ULong(i)] = RTM::Manager::_duplicate(managers[i].in());
    return list;
}

RTC::ReturnCode_t removeFrom(std::vector<RTM::Manager_var> &managers, RTM::Manager_ptr manager)
{
    for (auto it = managers.begin(); it != managers.end(); ++it) {
        if ((*it)->_is_equivalent(manager)) {
            managers.erase(it);
            return RTC::RTC_OK;
        }
    }
    return RTC::BAD_PARAMETER;
}

} // namespace

RTM::ManagerList *Manager::get_master_managers()
{
    Lock lock(m_context.mutex);
    return copyList(m_masters);
}

RTC::ReturnCode_t Manager::add_master_manager(RTM::Manager_ptr mgr)
{
    Lock lock(m_context.mutex);
    m_masters.push_back(RTM::Manager::_duplicate(mgr));
    return RTC::RTC_OK;
}

RTC::ReturnCode_t Manager::remove_master_manager(RTM::Manager_ptr mgr)
{
    Lock lock(m_context.mutex);
    return removeFrom(m_masters, mgr);
}

RTM::ManagerList *Manager::get_slave_managers()
{
    Lock lock(m_context.mutex);
    return copyList(m_slaves);
}

RTC::ReturnCode_t Manager::add_slave_manager(RTM::Manager_ptr mgr)
{
    Lock lock(m_context.mutex);
    m_slaves.push_back(RTM::Manager::_duplicate(mgr));
    return RTC::RTC_OK;
}

RTC::ReturnCode_t Manager::remove_slave_manager(RTM::Manager_ptr mgr)
{
    Lock lock(m_context.mutex);
    return removeFrom(m_slaves, mgr);
}

// The reply must leave before the ORB stops, so the shutdown runs on its own thread.
RTC::ReturnCode_t Manager::shutdown()
{
    {
        Lock lock(m_context.mutex);
        for (Component *component : m_components)
            component->destroy();
        m_components.clear();
        m_context.unbind("manager", "mgr");
    }
    std::lock_guard<std::recursive_mutex> lock(m_context.mutex);
    if (!m_context.shutdownThread.joinable()) {
        CORBA::ORB_var orb = CORBA::ORB::_duplicate(m_context.orb.in());
        m_context.shutdownThread = std::thread([orb] {
            try {
                orb->shutdown(true);
            } catch (const CORBA::Exception &e) {
                std::fprintf(stderr, "rtstudio_livepeer: %s in shutdown\n", e._name());
            }
        });
    }
    return RTC::RTC_OK;
}

CORBA::Object_ptr Manager::get_service(const char *)
{
    return CORBA::Object::_nil();
}

} // namespace LivePeer
