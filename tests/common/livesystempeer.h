// SPDX-License-Identifier: MIT
#pragma once

// Servants of the live-test peer (rtstudio_livepeer): a small OpenRTM-compatible process with a
// manager and the well-known example component types, for tests of CORBA clients.

#include <Manager.hh>
#include <OpenRTM.hh>
#include <omniORB4/Naming.hh>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace LivePeer {

class Component;
class Manager;

/// Process-wide state of the peer: ORB, POA, naming root, host context name.
struct Context
{
    CORBA::ORB_var orb;
    PortableServer::POA_var poa;
    CosNaming::NamingContext_var naming;
    std::string host;
    std::recursive_mutex mutex;
    Manager *manager = nullptr;
    std::thread shutdownThread; ///< stops the ORB after Manager::shutdown() replied; joined by main

    /// Binds `object` at `<host>.host_cxt/<id>.<kind>`.
    void bind(const std::string &id, const std::string &kind, CORBA::Object_ptr object);
    void unbind(const std::string &id, const std::string &kind);
};

/// One execution context owned by one component; state changes take effect at once.
class ExecutionContext : public POA_RTC::ExecutionContextService
{
public:
    explicit ExecutionContext(Context &context)
        : m_context(context)
    { }
    void setOwner(Component *owner) { m_owner = owner; }

    CORBA::Boolean is_running() override;
    RTC::ReturnCode_t start() override;
    RTC::ReturnCode_t stop() override;
    CORBA::Double get_rate() override;
    RTC::ReturnCode_t set_rate(CORBA::Double rate) override;
    RTC::ReturnCode_t add_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t remove_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t activate_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t deactivate_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t reset_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::LifeCycleState get_component_state(RTC::LightweightRTObject_ptr comp) override;
    RTC::ExecutionKind get_kind() override { return RTC::PERIODIC; }
    RTC::ExecutionContextProfile *get_profile() override;

    RTC::LifeCycleState state() const { return m_state; }

private:
    RTC::ReturnCode_t transition(RTC::LifeCycleState from, RTC::LifeCycleState to);

    Context &m_context;
    Component *m_owner = nullptr;
    bool m_running = true;
    double m_rate = 1000.0;
    RTC::LifeCycleState m_state = RTC::INACTIVE_STATE;
};

/// A port that keeps connector profiles; connect() notifies every port of the connector.
class Port : public POA_RTC::PortService
{
public:
    Port(Context &context, RTC::PortProfile profile)
        : m_context(context)
        , m_profile(std::move(profile))
    { }
    void setReference(RTC::PortService_ptr self, RTC::RTObject_ptr owner);

    RTC::PortProfile *get_port_profile() override;
    RTC::ConnectorProfileList *get_connector_profiles() override;
    RTC::ConnectorProfile *get_connector_profile(const char *connector_id) override;
    RTC::ReturnCode_t connect(RTC::ConnectorProfile &connector_profile) override;
    RTC::ReturnCode_t disconnect(const char *connector_id) override;
    RTC::ReturnCode_t disconnect_all() override;
    RTC::ReturnCode_t notify_connect(RTC::ConnectorProfile &connector_profile) override;
    RTC::ReturnCode_t notify_disconnect(const char *connector_id) override;

private:
    Context &m_context;
    RTC::PortProfile m_profile;
};

/// SDO configuration with named sets and one active set.
class Configuration : public POA_SDOPackage::Configuration
{
public:
    explicit Configuration(Context &context)
        : m_context(context)
    { }
    void addSet(const std::string &id,
                const std::vector<std::pair<std::string, std::string>> &values);
    void setActive(const std::string &id) { m_active = id; }

    CORBA::Boolean set_device_profile(const SDOPackage::DeviceProfile &) override { return false; }
    CORBA::Boolean add_service_profile(const SDOPackage::ServiceProfile &) override
    {
        return false;
    }
    CORBA::Boolean add_organization(SDOPackage::Organization_ptr) override { return false; }
    CORBA::Boolean remove_service_profile(const char *) override { return false; }
    CORBA::Boolean remove_organization(const char *) override { return false; }
    SDOPackage::ParameterList *get_configuration_parameters() override;
    SDOPackage::NVList *get_configuration_parameter_values() override;
    CORBA::Any *get_configuration_parameter_value(const char *name) override;
    CORBA::Boolean set_configuration_parameter(const char *name, const CORBA::Any &value) override;
    SDOPackage::ConfigurationSetList *get_configuration_sets() override;
    SDOPackage::ConfigurationSet *get_configuration_set(const char *config_id) override;
    CORBA::Boolean set_configuration_set_values(const SDOPackage::ConfigurationSet &set) override;
    SDOPackage::ConfigurationSet *get_active_configuration_set() override;
    CORBA::Boolean add_configuration_set(const SDOPackage::ConfigurationSet &set) override;
    CORBA::Boolean remove_configuration_set(const char *config_id) override;
    CORBA::Boolean activate_configuration_set(const char *config_id) override;

private:
    SDOPackage::ConfigurationSet *find(const std::string &id);

    Context &m_context;
    std::vector<SDOPackage::ConfigurationSet> m_sets;
    std::string m_active;
};

/// A component of one of the example types (ConsoleIn, ConsoleOut, MyServiceProvider, ...).
class Component : public POA_OpenRTM::DataFlowComponent
{
public:
    /// Creates, activates and binds a component; nullptr for an unknown type.
    static Component *create(Context &context, const std::string &type,
                             const std::string &instance);

    std::string instanceName() const { return m_instance; }
    RTC::RTObject_ptr reference() const { return m_self.in(); }
    /// Unbinds and deactivates the component (its servants are released by the POA).
    void destroy();

    RTC::ReturnCode_t initialize() override { return RTC::RTC_OK; }
    RTC::ReturnCode_t finalize() override { return RTC::PRECONDITION_NOT_MET; }
    CORBA::Boolean is_alive(RTC::ExecutionContext_ptr) override { return !m_destroyed; }
    RTC::ReturnCode_t exit() override;
    RTC::ExecutionContextHandle_t attach_context(RTC::ExecutionContext_ptr) override { return -1; }
    RTC::ReturnCode_t detach_context(RTC::ExecutionContextHandle_t) override
    {
        return RTC::BAD_PARAMETER;
    }
    RTC::ExecutionContext_ptr get_context(RTC::ExecutionContextHandle_t handle) override;
    RTC::ExecutionContextList *get_owned_contexts() override;
    RTC::ExecutionContextList *get_participating_contexts() override;
    RTC::ExecutionContextHandle_t get_context_handle(RTC::ExecutionContext_ptr cxt) override;
    RTC::ReturnCode_t on_initialize() override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_finalize() override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_startup(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_shutdown(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_activated(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_deactivated(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_aborting(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_error(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_reset(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_execute(RTC::ExecutionContextHandle_t) override { return RTC::RTC_OK; }
    RTC::ReturnCode_t on_state_update(RTC::ExecutionContextHandle_t) override
    {
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t on_rate_changed(RTC::ExecutionContextHandle_t) override
    {
        return RTC::RTC_OK;
    }
    SDOPackage::OrganizationList *get_owned_organizations() override;
    char *get_sdo_id() override { return CORBA::string_dup(m_instance.c_str()); }
    char *get_sdo_type() override { return CORBA::string_dup(m_type.c_str()); }
    SDOPackage::DeviceProfile *get_device_profile() override;
    SDOPackage::ServiceProfileList *get_service_profiles() override;
    SDOPackage::ServiceProfile *get_service_profile(const char *id) override;
    SDOPackage::SDOService_ptr get_sdo_service(const char *id) override;
    SDOPackage::Configuration_ptr get_configuration() override;
    SDOPackage::Monitoring_ptr get_monitoring() override;
    SDOPackage::OrganizationList *get_organizations() override;
    SDOPackage::NVList *get_status_list() override;
    CORBA::Any *get_status(const char *name) override;
    RTC::ComponentProfile *get_component_profile() override;
    RTC::PortServiceList *get_ports() override;

private:
    Component(Context &context, std::string type, std::string instance);
    void addPort(const std::string &name, RTC::PortProfile profile);

    Context &m_context;
    std::string m_type;
    std::string m_instance;
    RTC::RTObject_var m_self;
    RTC::ExecutionContextService_var m_ec;
    SDOPackage::Configuration_var m_configuration;
    std::vector<RTC::PortService_var> m_ports;
    bool m_destroyed = false;
};

/// The RTM::Manager of the peer: creates and deletes example components, records modules.
class Manager : public POA_RTM::Manager
{
public:
    explicit Manager(Context &context)
        : m_context(context)
    { }
    void add(Component *component) { m_components.push_back(component); }
    void remove(Component *component);
    /// Creates a component from `Type[?instance_name=NAME&...]`; nullptr on failure.
    Component *createFromArgument(const std::string &argument);

    RTC::ReturnCode_t load_module(const char *pathname, const char *initfunc) override;
    RTC::ReturnCode_t unload_module(const char *pathname) override;
    RTM::ModuleProfileList *get_loadable_modules() override;
    RTM::ModuleProfileList *get_loaded_modules() override;
    RTM::ModuleProfileList *get_factory_profiles() override;
    RTC::RTObject_ptr create_component(const char *module_name) override;
    RTC::ReturnCode_t delete_component(const char *instance_name) override;
    RTC::RTCList *get_components() override;
    RTC::ComponentProfileList *get_component_profiles() override;
    RTC::RTCList *get_components_by_name(const char *name) override;
    RTM::ManagerProfile *get_profile() override;
    RTM::NVList *get_configuration() override;
    RTC::ReturnCode_t set_configuration(const char *name, const char *value) override;
    CORBA::Boolean is_master() override { return true; }
    RTM::ManagerList *get_master_managers() override;
    RTC::ReturnCode_t add_master_manager(RTM::Manager_ptr mgr) override;
    RTC::ReturnCode_t remove_master_manager(RTM::Manager_ptr mgr) override;
    RTM::ManagerList *get_slave_managers() override;
    RTC::ReturnCode_t add_slave_manager(RTM::Manager_ptr mgr) override;
    RTC::ReturnCode_t remove_slave_manager(RTM::Manager_ptr mgr) override;
    RTC::ReturnCode_t fork() override { return RTC::UNSUPPORTED; }
    RTC::ReturnCode_t shutdown() override;
    RTC::ReturnCode_t restart() override { return RTC::UNSUPPORTED; }
    CORBA::Object_ptr get_service(const char *name) override;

private:
    Context &m_context;
    std::vector<Component *> m_components;
    std::vector<std::string> m_loaded;
    std::vector<std::pair<std::string, std::string>> m_configuration {{"manager.name", "manager"},
                                                                      {"manager.is_master", "YES"}};
    std::vector<RTM::Manager_var> m_masters;
    std::vector<RTM::Manager_var> m_slaves;
};

} // namespace LivePeer
