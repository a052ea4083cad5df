// SPDX-License-Identifier: MIT
// The base class of every component: lifecycle callbacks, ports, configuration, logging.
#ifndef RTM_RTOBJECT_H
#define RTM_RTOBJECT_H

#include <rtm/ConfigAdmin.h>
#include <rtm/CorbaPort.h>
#include <rtm/Factory.h>
#include <rtm/InPortBase.h>
#include <rtm/OutPortBase.h>
#include <rtm/PortBase.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

#include <rtmruntime/rtobject.h>

#include <string>
#include <vector>

namespace RTC
{
class Manager;

/**
 * An RT-Component (RTC::RTObject, OpenRTM::DataFlowComponent servant). Subclasses add ports and
 * bind configuration parameters in onInitialize() and do their work in the on…() callbacks,
 * which the execution context calls as OpenRTM-aist does: onActivated / onExecute /
 * onDeactivated / onError / onReset / onAborting with the context's UniqueId, onStateUpdate
 * after each onExecute (the configuration is applied there), onRateChanged when the rate changes.
 */
class RTObject_impl : public ::Runtime::RtObject
{
public:
    explicit RTObject_impl(Manager *manager);
    RTObject_impl(CORBA::ORB_ptr orb, PortableServer::POA_ptr poa);
    ~RTObject_impl() override;

    using ::Runtime::RtObject::setProperties;

    // RTC::LightweightRTObject and ComponentAction, extended as OpenRTM-aist does.
    ReturnCode_t initialize() override;
    ReturnCode_t on_execute(UniqueId exec_handle) override;

    const char *getInstanceName();
    void setInstanceName(const char *instance_name);
    const char *getTypeName();
    const char *getCategory();
    /// The component's properties (profile, `conf.*`, `exec_cxt.*`, instance_name, …).
    coil::Properties &getProperties();
    /// Merges @p prop into the component's properties.
    void setProperties(const coil::Properties &prop);
    RTObject_ptr getObjRef() const;

    /// Binds @p var to configuration parameter @p param_name (see ConfigAdmin::bindParameter).
    template <typename VarType>
    bool bindParameter(const char *param_name, VarType &var, const char *def_val,
                       bool (*trans)(VarType &, const char *) = coil::stringTo)
    {
        return m_configsets.bindParameter(param_name, var, def_val, trans);
    }
    ConfigAdmin &getConfigService() { return m_configsets; }
    /// Applies configuration set @p config_set to the bound variables when it is the active one.
    void updateParameters(const char *config_set);

    bool addPort(PortBase &port);
    bool addPort(CorbaPort &port);
    /// Adds @p inport (a member of the component) under @p name.
    bool addInPort(const char *name, InPortBase &inport);
    bool addOutPort(const char *name, OutPortBase &outport);
    bool removePort(PortBase &port);
    bool removePort(CorbaPort &port);
    bool removeInPort(InPortBase &port);
    bool removeOutPort(OutPortBase &port);

    /// The execution context known as @p ec_id (0: the component's own); nil when there is none.
    ExecutionContext_ptr getExecutionContext(UniqueId ec_id);
    double getExecutionRate(UniqueId ec_id);
    ReturnCode_t setExecutionRate(UniqueId ec_id, double rate);
    bool isOwnExecutionContext(UniqueId ec_id);
    ReturnCode_t activate(UniqueId ec_id);
    ReturnCode_t deactivate(UniqueId ec_id);
    ReturnCode_t reset(UniqueId ec_id);

    /// Reads every InPort (before onExecute when setReadAll(true) was called).
    bool readAll();
    /// Writes every OutPort (after onExecute when setWriteAll(true) was called).
    bool writeAll();
    void setReadAll(bool read = true, bool completion = false);
    void setWriteAll(bool write = true, bool completion = false);

    void addConfigurationParamListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener,
                                       bool autoclean = true);
    void removeConfigurationParamListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener);
    void addConfigurationSetListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener,
                                     bool autoclean = true);
    void removeConfigurationSetListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener);
    void addConfigurationSetNameListener(ConfigurationSetNameListenerType type, ConfigurationSetNameListener *listener,
                                         bool autoclean = true);
    void removeConfigurationSetNameListener(ConfigurationSetNameListenerType type,
                                            ConfigurationSetNameListener *listener);

protected:
    Manager *m_pManager;
    CORBA::ORB_var m_pORB;
    PortableServer::POA_var m_pPOA;
    coil::Properties m_properties;
    ConfigAdmin m_configsets;
    std::vector<InPortBase *> m_inports;
    std::vector<OutPortBase *> m_outports;
    bool m_readAll;
    bool m_readAllCompletion;
    bool m_writeAll;
    bool m_writeAllCompletion;
    mutable Logger rtclog;

private:
    std::string m_instanceName;
    std::string m_typeName;
    std::string m_category;
};
} // namespace RTC

#endif // RTM_RTOBJECT_H
