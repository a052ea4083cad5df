// SPDX-License-Identifier: MIT
#pragma once

#include "configadmin.h"
#include "inport.h"
#include "outport.h"
#include "properties.h"
#include "serviceport.h"

#include <OpenRTM.hh>

#include <functional>
#include <initializer_list>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace Runtime {

class ExecutionContext;
class SdoConfiguration;

/**
 * A data-flow RT-Component servant (OpenRTM::DataFlowComponent: RTObject, LightweightRTObject,
 * SDO, DataFlowComponentAction), the base class of every component the runtime hosts. Subclasses
 * add ports and bind configuration parameters in onInitialize() and do their work in onExecute().
 * initialize() creates the owned execution context of type `exec_cxt.periodic.type` at
 * `exec_cxt.periodic.rate` (see ExecutionContextFactory) and starts it.
 */
class RtObject : public virtual POA_OpenRTM::DataFlowComponent
{
public:
    explicit RtObject(PortableServer::POA_ptr poa);
    ~RtObject() override;

    /// Profile and instance properties (`instance_name`, `type_name`, `conf.*`, `exec_cxt.*`, …).
    void setProperties(const Properties &properties);
    Properties properties();
    std::string instanceName();
    /// The component's reference (activates the servant on first use).
    RTC::RTObject_ptr reference();
    /// Called once when the component exits (the manager forgets it there).
    void setExitHandler(std::function<void(RtObject *)> handler);
    /// A value shown by SDO get_status_list / get_status (e.g. what a sink received).
    void setStatus(const std::string &name, const std::string &value);
    /// Several values at once: a reader of the status list sees all of them or none.
    void setStatus(std::initializer_list<std::pair<std::string, std::string>> values);
    std::string status(const std::string &name);
    ConfigAdmin &configuration() { return m_config; }
    /// Why the last initialize() failed: an unknown context type, or what onInitialize() recorded
    /// with setInitializeError(); empty otherwise.
    std::string initializeError();
    /**
     * Makes @p context one of the component's own (OpenRTM's bindContext): the component takes
     * it over (it goes with the component) and answers with its handle, or -1 once finalized.
     */
    RTC::ExecutionContextHandle_t bindContext(ExecutionContext *context);
    /// The contexts the component owns (its handle 0 first).
    std::vector<ExecutionContext *> ownedContexts();
    /// Finalizes without exit handler — used by the manager on shutdown.
    void shutdownComponent();
    /**
     * Lists another component's port among this one's (get_ports, the profile's port_profiles),
     * as a composite does with its members' exported ports: the port stays its owner's.
     */
    void addPortReference(RTC::PortService_ptr port);
    /// Unlists a port added by addPortReference(); false when it is not listed.
    bool removePortReference(RTC::PortService_ptr port);

    // RTC::ComponentAction
    RTC::ReturnCode_t on_initialize() override;
    RTC::ReturnCode_t on_finalize() override;
    RTC::ReturnCode_t on_startup(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_shutdown(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_activated(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_deactivated(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_aborting(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_error(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_reset(RTC::ExecutionContextHandle_t exec_handle) override;
    // RTC::DataFlowComponentAction
    RTC::ReturnCode_t on_execute(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_state_update(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ReturnCode_t on_rate_changed(RTC::ExecutionContextHandle_t exec_handle) override;
    // RTC::LightweightRTObject
    RTC::ReturnCode_t initialize() override;
    RTC::ReturnCode_t finalize() override;
    CORBA::Boolean is_alive(RTC::ExecutionContext_ptr exec_context) override;
    RTC::ReturnCode_t exit() override;
    RTC::ExecutionContextHandle_t attach_context(RTC::ExecutionContext_ptr exec_context) override;
    RTC::ReturnCode_t detach_context(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ExecutionContext_ptr get_context(RTC::ExecutionContextHandle_t exec_handle) override;
    RTC::ExecutionContextList *get_owned_contexts() override;
    RTC::ExecutionContextList *get_participating_contexts() override;
    RTC::ExecutionContextHandle_t get_context_handle(RTC::ExecutionContext_ptr cxt) override;
    // RTC::RTObject
    RTC::ComponentProfile *get_component_profile() override;
    RTC::PortServiceList *get_ports() override;
    // SDOPackage::SDOSystemElement, SDOPackage::SDO
    SDOPackage::OrganizationList *get_owned_organizations() override;
    char *get_sdo_id() override;
    char *get_sdo_type() override;
    SDOPackage::DeviceProfile *get_device_profile() override;
    SDOPackage::ServiceProfileList *get_service_profiles() override;
    SDOPackage::ServiceProfile *get_service_profile(const char *id) override;
    SDOPackage::SDOService_ptr get_sdo_service(const char *id) override;
    SDOPackage::Configuration_ptr get_configuration() override;
    SDOPackage::Monitoring_ptr get_monitoring() override;
    SDOPackage::OrganizationList *get_organizations() override;
    SDOPackage::NVList *get_status_list() override;
    CORBA::Any *get_status(const char *nme) override;

protected:
    virtual RTC::ReturnCode_t onInitialize() { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onFinalize() { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onStartup(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onShutdown(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onActivated(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onDeactivated(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onAborting(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onError(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onReset(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onStateUpdate(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onRateChanged(RTC::ExecutionContextHandle_t) { return RTC::RTC_OK; }

    PortableServer::POA_ptr poa() const { return m_poa.in(); }
    /**
     * Takes ownership of @p port and lists it in the profile; false (and @p port deleted) when a
     * port of its name is listed already, as OpenRTM-aist's port admin refuses one: onInitialize()
     * runs again whenever a peer calls on_initialize(), and its ports must not pile up.
     */
    bool addPort(PortBase *port);
    /**
     * Lists @p port, which the component object owns (a member): on finalize the runtime
     * disconnects and deactivates it but leaves its deletion to the owner. False when it, or a
     * port of its name, is listed already.
     */
    bool addBorrowedPort(PortBase *port);
    /// Disconnects, deactivates and unlists @p port (deleting it when the runtime owns it).
    bool removePort(PortBase *port);
    /// The listed port named @p name (without the instance name), or nullptr.
    PortBase *findPort(const std::string &name);
    /// A new port named @p name, or the one listed under that name when its type is the same (nullptr otherwise).
    template <typename T>
    InPort<T> *addInPort(const std::string &name)
    {
        return addPortOnce<InPort<T>>(name);
    }
    template <typename T>
    OutPort<T> *addOutPort(const std::string &name)
    {
        return addPortOnce<OutPort<T>>(name);
    }
    ServicePort *addServicePort(const std::string &name);
    /// Records why onInitialize() refuses, for initializeError() (the manager's refusal names it).
    void setInitializeError(const std::string &reason);

private:
    template <typename Port>
    Port *addPortOnce(const std::string &name)
    {
        if (PortBase *listed = findPort(name))
            return dynamic_cast<Port *>(listed);
        auto *port = new Port(name, m_poa);
        return addPort(port) ? port : nullptr;
    }
    /// Lists @p port unless it, or a port of its name, is listed already.
    bool listPort(PortBase *port, bool borrowed);
    bool createOwnedContext();
    /// Activates the configuration set that configuration.active_config names, when there is one.
    void activateConfiguredSet();
    void releaseOwnedContexts();
    /// Deactivates and releases the SDO configuration servant, when there is one.
    void releaseSdoConfiguration();
    void releaseAll();
    void releasePort(PortBase *port, bool borrowed);
    std::vector<PortBase *> portList();
    std::vector<RTC::PortService_var> portReferences();

    PortableServer::POA_var m_poa;
    std::mutex m_mutex;
    Properties m_properties;
    ConfigAdmin m_config;
    SdoConfiguration *m_sdoConfig = nullptr;
    std::vector<PortBase *> m_ports;
    std::set<PortBase *> m_borrowedPorts;
    std::vector<ExecutionContext *> m_ownedContexts;
    std::string m_initError;
    std::vector<RTC::PortService_var> m_portReferences;
    std::map<RTC::ExecutionContextHandle_t, RTC::ExecutionContext_var> m_participating;
    RTC::ExecutionContextHandle_t m_nextParticipatingHandle = 1000;
    std::map<std::string, std::string> m_status;
    std::function<void(RtObject *)> m_exitHandler;
    RTC::RTObject_var m_self;
    bool m_created = true;
    bool m_finalized = false;
};

} // namespace Runtime
