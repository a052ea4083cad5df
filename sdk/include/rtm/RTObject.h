// SPDX-License-Identifier: MIT
// The base class of every component: lifecycle callbacks, ports, configuration, logging.
#ifndef RTM_RTOBJECT_H
#define RTM_RTOBJECT_H

#include <rtm/ConfigAdmin.h>
#include <rtm/CorbaPort.h>
#include <rtm/Factory.h>
#include <rtm/FsmActionListener.h>
#include <rtm/InPortBase.h>
#include <rtm/OutPortBase.h>
#include <rtm/PortBase.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

#include <rtmruntime/rtobject.h>

#include <memory>
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

    /// Listeners called before the FSM state actions (see the pre/postOnFsm… hooks).
    void addPreFsmActionListener(PreFsmActionListenerType listener_type, PreFsmActionListener *listener,
                                 bool autoclean = true);
    /// @p memfunc of @p obj as a PreFsmActionListener (deleted with the component).
    template <class Listener>
    PreFsmActionListener *addPreFsmActionListener(PreFsmActionListenerType listener_type, Listener &obj,
                                                  void (Listener::*memfunc)(const char *state))
    {
        class Call : public PreFsmActionListener
        {
        public:
            Call(Listener &obj, void (Listener::*memfunc)(const char *))
                : m_obj(obj)
                , m_memfunc(memfunc)
            {
            }
            void operator()(const char *state) override { (m_obj.*m_memfunc)(state); }

        private:
            Listener &m_obj;
            void (Listener::*m_memfunc)(const char *);
        };
        Call *listener = new Call(obj, memfunc);
        addPreFsmActionListener(listener_type, listener, true);
        return listener;
    }
    void removePreFsmActionListener(PreFsmActionListenerType listener_type, PreFsmActionListener *listener);
    /// Listeners called after the FSM state actions, with their results.
    void addPostFsmActionListener(PostFsmActionListenerType listener_type, PostFsmActionListener *listener,
                                  bool autoclean = true);
    /// @p memfunc of @p obj as a PostFsmActionListener (deleted with the component).
    template <class Listener>
    PostFsmActionListener *addPostFsmActionListener(PostFsmActionListenerType listener_type, Listener &obj,
                                                    void (Listener::*memfunc)(const char *state, ReturnCode_t ret))
    {
        class Call : public PostFsmActionListener
        {
        public:
            Call(Listener &obj, void (Listener::*memfunc)(const char *, ReturnCode_t))
                : m_obj(obj)
                , m_memfunc(memfunc)
            {
            }
            void operator()(const char *state, ReturnCode_t ret) override { (m_obj.*m_memfunc)(state, ret); }

        private:
            Listener &m_obj;
            void (Listener::*m_memfunc)(const char *, ReturnCode_t);
        };
        Call *listener = new Call(obj, memfunc);
        addPostFsmActionListener(listener_type, listener, true);
        return listener;
    }
    void removePostFsmActionListener(PostFsmActionListenerType listener_type, PostFsmActionListener *listener);

    /**
     * FSM hooks, called by the states of an RTC::Machine of this component (rtm/StaticFSM.h)
     * around their actions; each calls the FSM action listeners of its kind. Entering a state
     * (postOnFsmStateChange) makes it the component's current FSM state: logged at DEBUG level
     * and shown as `fsm_state` in the component's status list.
     */
    void preOnFsmInit(const char *state);
    void preOnFsmEntry(const char *state);
    void preOnFsmDo(const char *state);
    void preOnFsmExit(const char *state);
    void preOnFsmStateChange(const char *state);
    void postOnFsmInit(const char *state, ReturnCode_t ret);
    void postOnFsmEntry(const char *state, ReturnCode_t ret);
    void postOnFsmDo(const char *state, ReturnCode_t ret);
    void postOnFsmExit(const char *state, ReturnCode_t ret);
    void postOnFsmStateChange(const char *state, ReturnCode_t ret);
    /// RT Studio: records @p state as the current FSM state without calling listeners (the
    /// machine's state right after its construction, which no hook reports).
    void setFsmState(const char *state);
    /// RT Studio: the current FSM state's name; empty when the component has no state machine.
    std::string getFsmState() const;

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
    struct FsmActions;
    std::unique_ptr<FsmActions> m_fsmActions;
    std::string m_instanceName;
    std::string m_typeName;
    std::string m_category;
};
} // namespace RTC

#endif // RTM_RTOBJECT_H
