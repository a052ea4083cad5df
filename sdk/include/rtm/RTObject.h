// SPDX-License-Identifier: MIT
// The base class of every component: lifecycle callbacks, ports, configuration, logging.
#ifndef RTM_RTOBJECT_H
#define RTM_RTOBJECT_H

#include <rtm/ComponentActionListener.h>
#include <rtm/ConfigAdmin.h>
#include <rtm/CorbaPort.h>
#include <rtm/Factory.h>
#include <rtm/FsmActionListener.h>
#include <rtm/InPortBase.h>
#include <rtm/OutPortBase.h>
#include <rtm/PortBase.h>
#include <rtm/PortConnectListener.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

#include <rtmruntime/rtobject.h>

#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace RTC
{
class Manager;
class SdoServiceConsumerBase;
class SdoServiceProviderBase;

namespace detail
{
/// A listener of class @p Base that calls @p Obj's member function with the listener's arguments.
template <class Base, class Obj, class... Args>
class MemberListener : public Base
{
public:
    MemberListener(Obj &obj, void (Obj::*memfunc)(Args...))
        : m_obj(obj)
        , m_memfunc(memfunc)
    {
    }
    void operator()(Args... args) override { (m_obj.*m_memfunc)(args...); }

private:
    Obj &m_obj;
    void (Obj::*m_memfunc)(Args...);
};
} // namespace detail

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

    // RTC::LightweightRTObject and ComponentAction, extended as OpenRTM-aist does: each action
    // calls the pre- and post-component action listeners around the on…() callback.
    ReturnCode_t initialize() override;
    ReturnCode_t on_initialize() override;
    ReturnCode_t on_finalize() override;
    ReturnCode_t on_startup(UniqueId exec_handle) override;
    ReturnCode_t on_shutdown(UniqueId exec_handle) override;
    ReturnCode_t on_activated(UniqueId exec_handle) override;
    ReturnCode_t on_deactivated(UniqueId exec_handle) override;
    ReturnCode_t on_aborting(UniqueId exec_handle) override;
    ReturnCode_t on_error(UniqueId exec_handle) override;
    ReturnCode_t on_reset(UniqueId exec_handle) override;
    ReturnCode_t on_execute(UniqueId exec_handle) override;
    ReturnCode_t on_state_update(UniqueId exec_handle) override;
    ReturnCode_t on_rate_changed(UniqueId exec_handle) override;
    /// Attaches @p exec_context and calls the EC_ATTACHED listeners with its id.
    UniqueId attach_context(ExecutionContext_ptr exec_context) override;
    /// Calls the EC_DETACHED listeners, then detaches the context.
    ReturnCode_t detach_context(UniqueId ec_id) override;

    const char *getInstanceName();
    void setInstanceName(const char *instance_name);
    const char *getTypeName();
    const char *getCategory();
    /// The profile's `description`, `version` and `vendor`.
    const char *getDescription();
    const char *getVersion();
    const char *getVendor();
    /// The names the component is registered under (`naming.names`, comma separated).
    std::vector<std::string> getNamingNames();
    /**
     * The component's reference is the runtime's own servant activation: @p rtobj must be that
     * reference; any other is refused with a logged error (the component keeps its own).
     */
    void setObjRef(RTObject_ptr rtobj);
    /// Registration under a corbaloc (INS) key is not supported: logged as an error.
    void setINSObjRef(RTC::LightweightRTObject_ptr obj);
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
    /// OpenRTM-aist 0.4 names of addPort / addInPort / addOutPort / removePort.
    void registerPort(PortBase &port);
    /// Lists @p port, a port of another object, among the component's.
    void registerPort(PortService_ptr port);
    void registerPort(CorbaPort &port);
    void registerInPort(const char *name, InPortBase &inport);
    void registerOutPort(const char *name, OutPortBase &outport);
    void deletePort(PortBase &port);
    /// Removes the port whose reference is @p port (one of the component's or one registered).
    void deletePort(PortService_ptr port);
    void deletePort(CorbaPort &port);
    void deletePortByName(const char *port_name);
    const std::vector<InPortBase *> &getInPorts() const { return m_inports; }
    const std::vector<OutPortBase *> &getOutPorts() const { return m_outports; }
    /// Disconnects and removes every port the component added.
    void finalizePorts();
    /// Stops and detaches the execution contexts the component owns (as when it finalizes).
    void finalizeContexts();

    /// The execution context known as @p ec_id (0: the component's own); nil when there is none.
    ExecutionContext_ptr getExecutionContext(UniqueId ec_id);
    double getExecutionRate(UniqueId ec_id);
    ReturnCode_t setExecutionRate(UniqueId ec_id, double rate);
    bool isOwnExecutionContext(UniqueId ec_id);
    ReturnCode_t activate(UniqueId ec_id);
    ReturnCode_t deactivate(UniqueId ec_id);
    ReturnCode_t reset(UniqueId ec_id);

    /**
     * Offers SDO service @p provider (not owned) under @p prof, whose id must be new: the
     * component's get_service_profiles() lists it and get_sdo_service(id) answers its reference
     * (the provider's own when @p prof names none). False for an id already offered.
     */
    bool addSdoServiceProvider(const SDOPackage::ServiceProfile &prof, SdoServiceProviderBase *provider);
    /// Withdraws the service @p id (its finalize() is called); false when there is none.
    bool removeSdoServiceProvider(const char *id);
    /**
     * Attaches the SDO service consumer SdoServiceConsumerFactory makes for the profile's
     * interface type and initialises it with @p prof (a known id re-initialises its consumer).
     * False, with a logged message naming the type, when no consumer of that type is registered
     * or it refuses the profile.
     */
    bool addSdoServiceConsumer(const SDOPackage::ServiceProfile &prof);
    /// Finalizes and deletes consumer @p id; false when there is none.
    bool removeSdoServiceConsumer(const char *id);
    void removeSdoServiceConsumerStartThread(const char *id);
    /// The component's service profiles: those given through SDO plus the providers added here.
    SDOPackage::ServiceProfileList *get_service_profiles() override;

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

    using PreCompActionListener = PreComponentActionListener;
    using PreCompActionListenerType = PreComponentActionListenerType;
    using PostCompActionListener = PostComponentActionListener;
    using PostCompActionListenerType = PostComponentActionListenerType;
    using ECActionListenerType = ExecutionContextActionListenerType;
    using ECActionListener = ExecutionContextActionListener;

    /// Calls @p listener before the component action @p listener_type names.
    void addPreComponentActionListener(PreComponentActionListenerType listener_type,
                                       PreComponentActionListener *listener, bool autoclean = true);
    /// @p memfunc of @p obj as a PreComponentActionListener (deleted with the component).
    template <class Listener>
    PreComponentActionListener *addPreComponentActionListener(PreCompActionListenerType listener_type,
                                                              Listener &obj, void (Listener::*memfunc)(UniqueId ec_id))
    {
        PreComponentActionListener *listener
            = new detail::MemberListener<PreComponentActionListener, Listener, UniqueId>(obj, memfunc);
        addPreComponentActionListener(listener_type, listener, true);
        return listener;
    }
    void removePreComponentActionListener(PreComponentActionListenerType listener_type,
                                          PreComponentActionListener *listener);

    /// Calls @p listener after the component action @p listener_type names, with its result.
    void addPostComponentActionListener(PostComponentActionListenerType listener_type,
                                        PostComponentActionListener *listener, bool autoclean = true);
    template <class Listener>
    PostComponentActionListener *addPostComponentActionListener(PostCompActionListenerType listener_type,
                                                                Listener &obj,
                                                                void (Listener::*memfunc)(UniqueId ec_id,
                                                                                          ReturnCode_t ret))
    {
        PostComponentActionListener *listener
            = new detail::MemberListener<PostComponentActionListener, Listener, UniqueId, ReturnCode_t>(obj, memfunc);
        addPostComponentActionListener(listener_type, listener, true);
        return listener;
    }
    void removePostComponentActionListener(PostComponentActionListenerType listener_type,
                                           PostComponentActionListener *listener);

    /// Calls @p listener with the profile of each port added (ADD_PORT) or removed (REMOVE_PORT).
    void addPortActionListener(PortActionListenerType listener_type, PortActionListener *listener,
                               bool autoclean = true);
    template <class Listener>
    PortActionListener *addPortActionListener(PortActionListenerType listener_type, Listener &obj,
                                              void (Listener::*memfunc)(const RTC::PortProfile &))
    {
        PortActionListener *listener
            = new detail::MemberListener<PortActionListener, Listener, const RTC::PortProfile &>(obj, memfunc);
        addPortActionListener(listener_type, listener, true);
        return listener;
    }
    void removePortActionListener(PortActionListenerType listener_type, PortActionListener *listener);

    /// Calls @p listener when an execution context is attached (EC_ATTACHED) or detached (EC_DETACHED).
    void addExecutionContextActionListener(ECActionListenerType listener_type,
                                           ExecutionContextActionListener *listener, bool autoclean = true);
    template <class Listener>
    ExecutionContextActionListener *addExecutionContextActionListener(ECActionListenerType listener_type,
                                                                      Listener &obj,
                                                                      void (Listener::*memfunc)(UniqueId))
    {
        ExecutionContextActionListener *listener
            = new detail::MemberListener<ExecutionContextActionListener, Listener, UniqueId>(obj, memfunc);
        addExecutionContextActionListener(listener_type, listener, true);
        return listener;
    }
    void removeExecutionContextActionListener(ECActionListenerType listener_type,
                                              ExecutionContextActionListener *listener);

    /// Calls @p listener at a step of connecting or disconnecting any port of the component.
    void addPortConnectListener(PortConnectListenerType listener_type, PortConnectListener *listener,
                                bool autoclean = true);
    template <class Listener>
    PortConnectListener *addPortConnectListener(PortConnectListenerType listener_type, Listener &obj,
                                                void (Listener::*memfunc)(const char *, ConnectorProfile &))
    {
        PortConnectListener *listener
            = new detail::MemberListener<PortConnectListener, Listener, const char *, ConnectorProfile &>(obj,
                                                                                                       memfunc);
        addPortConnectListener(listener_type, listener, true);
        return listener;
    }
    void removePortConnectListener(PortConnectListenerType listener_type, PortConnectListener *listener);

    /// Calls @p listener with the result of a step of connecting or disconnecting any port.
    void addPortConnectRetListener(PortConnectRetListenerType listener_type, PortConnectRetListener *listener,
                                   bool autoclean = true);
    template <class Listener>
    PortConnectRetListener *addPortConnectRetListener(PortConnectRetListenerType listener_type, Listener &obj,
                                                      void (Listener::*memfunc)(const char *, ConnectorProfile &,
                                                                                ReturnCode_t))
    {
        PortConnectRetListener *listener
            = new detail::MemberListener<PortConnectRetListener, Listener, const char *, ConnectorProfile &,
                                         ReturnCode_t>(obj, memfunc);
        addPortConnectRetListener(listener_type, listener, true);
        return listener;
    }
    void removePortConnectRetListener(PortConnectRetListenerType listener_type, PortConnectRetListener *listener);

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
     * Listeners of the component's FSM profile and structure; what serves the component's FSM
     * (an ExtendedFsmService provider) calls them through m_fsmActionListeners.
     */
    void addFsmProfileListener(FsmProfileListenerType listener_type, FsmProfileListener *listener,
                               bool autoclean = true);
    template <class Listener>
    FsmProfileListener *addFsmProfileListener(FsmProfileListenerType listener_type, Listener &obj,
                                              void (Listener::*memfunc)(const FsmProfile &))
    {
        FsmProfileListener *listener
            = new detail::MemberListener<FsmProfileListener, Listener, const FsmProfile &>(obj, memfunc);
        addFsmProfileListener(listener_type, listener, true);
        return listener;
    }
    void removeFsmProfileListener(FsmProfileListenerType listener_type, FsmProfileListener *listener);
    void addFsmStructureListener(FsmStructureListenerType listener_type, FsmStructureListener *listener,
                                 bool autoclean = true);
    template <class Listener>
    FsmStructureListener *addFsmStructureListener(FsmStructureListenerType listener_type, Listener &obj,
                                                  void (Listener::*memfunc)(FsmStructure &))
    {
        FsmStructureListener *listener
            = new detail::MemberListener<FsmStructureListener, Listener, FsmStructure &>(obj, memfunc);
        addFsmStructureListener(listener_type, listener, true);
        return listener;
    }
    void removeFsmStructureListener(FsmStructureListenerType listener_type, FsmStructureListener *listener);

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
    /// Finalizes the component now: its contexts stop, its ports and the component finalize.
    void shutdown();

    // The listener calls around each action, as the framework makes them; a subclass that runs
    // an action itself calls them the same way.
    void preOnInitialize(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_INITIALIZE, ec_id); }
    void preOnFinalize(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_FINALIZE, ec_id); }
    void preOnStartup(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_STARTUP, ec_id); }
    void preOnShutdown(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_SHUTDOWN, ec_id); }
    void preOnActivated(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_ACTIVATED, ec_id); }
    void preOnDeactivated(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_DEACTIVATED, ec_id); }
    void preOnAborting(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_ABORTING, ec_id); }
    void preOnError(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_ERROR, ec_id); }
    void preOnReset(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_RESET, ec_id); }
    void preOnExecute(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_EXECUTE, ec_id); }
    void preOnStateUpdate(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_STATE_UPDATE, ec_id); }
    void preOnRateChanged(UniqueId ec_id) { notifyPre(PreComponentActionListenerType::PRE_ON_RATE_CHANGED, ec_id); }
    void postOnInitialize(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_INITIALIZE, ec_id, ret);
    }
    void postOnFinalize(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_FINALIZE, ec_id, ret);
    }
    void postOnStartup(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_STARTUP, ec_id, ret);
    }
    void postOnShutdown(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_SHUTDOWN, ec_id, ret);
    }
    void postOnActivated(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_ACTIVATED, ec_id, ret);
    }
    void postOnDeactivated(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_DEACTIVATED, ec_id, ret);
    }
    void postOnAborting(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_ABORTING, ec_id, ret);
    }
    void postOnError(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_ERROR, ec_id, ret);
    }
    void postOnReset(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_RESET, ec_id, ret);
    }
    void postOnExecute(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_EXECUTE, ec_id, ret);
    }
    void postOnStateUpdate(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_STATE_UPDATE, ec_id, ret);
    }
    void postOnRateChanged(UniqueId ec_id, ReturnCode_t ret)
    {
        notifyPost(PostComponentActionListenerType::POST_ON_RATE_CHANGED, ec_id, ret);
    }
    void onAddPort(const PortProfile &pprof) { m_actionListeners.notify(PortActionListenerType::ADD_PORT, pprof); }
    void onRemovePort(const PortProfile &pprof)
    {
        m_actionListeners.notify(PortActionListenerType::REMOVE_PORT, pprof);
    }
    void onAttachExecutionContext(UniqueId ec_id)
    {
        m_actionListeners.notify(ExecutionContextActionListenerType::EC_ATTACHED, ec_id);
    }
    void onDetachExecutionContext(UniqueId ec_id)
    {
        m_actionListeners.notify(ExecutionContextActionListenerType::EC_DETACHED, ec_id);
    }

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
    ComponentActionListeners m_actionListeners;
    PortConnectListeners m_portconnListeners;
    FsmActionListeners m_fsmActionListeners;

private:
    friend class SdoServiceAdmin;

    void notifyPre(PreComponentActionListenerType type, UniqueId ec_id) { m_actionListeners.notify(type, ec_id); }
    void notifyPost(PostComponentActionListenerType type, UniqueId ec_id, ReturnCode_t ret)
    {
        m_actionListeners.notify(type, ec_id, ret);
    }

    /// False (logged) when @p port, or a port of its name, is listed already.
    bool attachPort(PortBase &port);
    bool detachPort(PortBase &port);
    template <typename Action>
    ReturnCode_t around(PreComponentActionListenerType pre, PostComponentActionListenerType post, UniqueId ec_id,
                        Action action);

    struct FsmActions;
    std::unique_ptr<FsmActions> m_fsmActions;
    std::string m_instanceName;
    std::string m_typeName;
    std::string m_category;
    std::vector<PortBase *> m_addedPorts;
    std::mutex m_sdoMutex;
    std::vector<std::pair<SDOPackage::ServiceProfile, SdoServiceProviderBase *>> m_sdoProviders;
    std::vector<SdoServiceConsumerBase *> m_sdoConsumers;
};
} // namespace RTC

#endif // RTM_RTOBJECT_H
