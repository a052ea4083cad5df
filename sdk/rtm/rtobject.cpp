// SPDX-License-Identifier: MIT
#include <rtm/DataFlowComponentBase.h>
#include <rtm/Manager.h>
#include <rtm/RTObject.h>
#include <rtm/LocalServiceBase.h>
#include <rtm/SdoServiceConsumerBase.h>
#include <rtm/SdoServiceProviderBase.h>

#include "fsmactions.h"
#include "sdkinternal.h"

#include <algorithm>

namespace RTC {

namespace {

PortableServer::POA_ptr poaOf(Manager *manager)
{
    return manager != nullptr ? manager->getPOA() : Sdk::rootPoa();
}

} // namespace

RTObject_impl::RTObject_impl(Manager *manager)
    : Runtime::RtObject(PortableServer::POA_var(poaOf(manager)).in())
    , m_pManager(manager)
    , m_pORB(manager != nullptr ? manager->getORB() : CORBA::ORB::_nil())
    , m_pPOA(poaOf(manager))
    , m_configsets(configuration())
    , m_readAll(false)
    , m_readAllCompletion(false)
    , m_writeAll(false)
    , m_writeAllCompletion(false)
    , m_fsmActions(new FsmActions)
{
}

RTObject_impl::RTObject_impl(CORBA::ORB_ptr orb, PortableServer::POA_ptr poa)
    : Runtime::RtObject(poa)
    , m_pManager(nullptr)
    , m_pORB(CORBA::ORB::_duplicate(orb))
    , m_pPOA(PortableServer::POA::_duplicate(poa))
    , m_configsets(configuration())
    , m_readAll(false)
    , m_readAllCompletion(false)
    , m_writeAll(false)
    , m_writeAllCompletion(false)
    , m_fsmActions(new FsmActions)
{
}

RTObject_impl::~RTObject_impl() = default;

ReturnCode_t RTObject_impl::initialize()
{
    // The manager has set the instance properties by now; user code reads them in onInitialize.
    m_properties << Sdk::toCoil(properties());
    m_instanceName = m_properties.getProperty("instance_name");
    m_typeName = m_properties.getProperty("type_name");
    m_category = m_properties.getProperty("category");
    rtclog.setName(m_instanceName.c_str());
    return Runtime::RtObject::initialize();
}

template <typename Action>
ReturnCode_t RTObject_impl::around(PreComponentActionListenerType pre, PostComponentActionListenerType post,
                                   UniqueId ec_id, Action action)
{
    m_actionListeners.notify(pre, ec_id);
    const ReturnCode_t result = action();
    m_actionListeners.notify(post, ec_id, result);
    return result;
}

// OpenRTM-aist reports on_initialize and on_finalize under execution context id 0.
ReturnCode_t RTObject_impl::on_initialize()
{
    return around(PreComponentActionListenerType::PRE_ON_INITIALIZE,
                  PostComponentActionListenerType::POST_ON_INITIALIZE, 0,
                  [this] { return Runtime::RtObject::on_initialize(); });
}

ReturnCode_t RTObject_impl::on_finalize()
{
    const ReturnCode_t result
        = around(PreComponentActionListenerType::PRE_ON_FINALIZE, PostComponentActionListenerType::POST_ON_FINALIZE,
                 0, [this] { return Runtime::RtObject::on_finalize(); });
    // The SDO services end with the component, while their owner (usually the component) lives.
    std::vector<std::pair<SDOPackage::ServiceProfile, SdoServiceProviderBase *>> providers;
    {
        std::lock_guard<std::mutex> lock(m_sdoMutex);
        providers.swap(m_sdoProviders);
    }
    for (auto &provider : providers)
        provider.second->finalize();
    std::vector<SdoServiceConsumerBase *> consumers;
    {
        std::lock_guard<std::mutex> lock(m_sdoMutex);
        consumers.swap(m_sdoConsumers);
    }
    for (SdoServiceConsumerBase *consumer : consumers) {
        consumer->finalize();
        SdoServiceConsumerFactory::instance().deleteObject(consumer);
    }
    return result;
}

ReturnCode_t RTObject_impl::on_startup(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_STARTUP, PostComponentActionListenerType::POST_ON_STARTUP,
                  exec_handle, [&] { return Runtime::RtObject::on_startup(exec_handle); });
}

ReturnCode_t RTObject_impl::on_shutdown(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_SHUTDOWN, PostComponentActionListenerType::POST_ON_SHUTDOWN,
                  exec_handle, [&] { return Runtime::RtObject::on_shutdown(exec_handle); });
}

ReturnCode_t RTObject_impl::on_activated(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_ACTIVATED,
                  PostComponentActionListenerType::POST_ON_ACTIVATED, exec_handle,
                  [&] { return Runtime::RtObject::on_activated(exec_handle); });
}

ReturnCode_t RTObject_impl::on_deactivated(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_DEACTIVATED,
                  PostComponentActionListenerType::POST_ON_DEACTIVATED, exec_handle,
                  [&] { return Runtime::RtObject::on_deactivated(exec_handle); });
}

ReturnCode_t RTObject_impl::on_aborting(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_ABORTING, PostComponentActionListenerType::POST_ON_ABORTING,
                  exec_handle, [&] { return Runtime::RtObject::on_aborting(exec_handle); });
}

ReturnCode_t RTObject_impl::on_error(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_ERROR, PostComponentActionListenerType::POST_ON_ERROR,
                  exec_handle, [&] { return Runtime::RtObject::on_error(exec_handle); });
}

ReturnCode_t RTObject_impl::on_reset(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_RESET, PostComponentActionListenerType::POST_ON_RESET,
                  exec_handle, [&] { return Runtime::RtObject::on_reset(exec_handle); });
}

ReturnCode_t RTObject_impl::on_execute(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_EXECUTE, PostComponentActionListenerType::POST_ON_EXECUTE,
                  exec_handle, [&] {
                      if (m_readAll)
                          readAll();
                      const ReturnCode_t result = Runtime::RtObject::on_execute(exec_handle);
                      if (m_writeAll)
                          writeAll();
                      return result;
                  });
}

ReturnCode_t RTObject_impl::on_state_update(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_STATE_UPDATE,
                  PostComponentActionListenerType::POST_ON_STATE_UPDATE, exec_handle,
                  [&] { return Runtime::RtObject::on_state_update(exec_handle); });
}

ReturnCode_t RTObject_impl::on_rate_changed(UniqueId exec_handle)
{
    return around(PreComponentActionListenerType::PRE_ON_RATE_CHANGED,
                  PostComponentActionListenerType::POST_ON_RATE_CHANGED, exec_handle,
                  [&] { return Runtime::RtObject::on_rate_changed(exec_handle); });
}

UniqueId RTObject_impl::attach_context(ExecutionContext_ptr exec_context)
{
    const UniqueId id = Runtime::RtObject::attach_context(exec_context);
    onAttachExecutionContext(id);
    return id;
}

ReturnCode_t RTObject_impl::detach_context(UniqueId ec_id)
{
    onDetachExecutionContext(ec_id);
    return Runtime::RtObject::detach_context(ec_id);
}

const char *RTObject_impl::getInstanceName()
{
    return m_instanceName.c_str();
}

void RTObject_impl::setInstanceName(const char *instance_name)
{
    m_instanceName = instance_name ? instance_name : "";
    m_properties.setProperty("instance_name", m_instanceName);
    Runtime::Properties name;
    name.set("instance_name", m_instanceName);
    Runtime::RtObject::setProperties(name);
}

const char *RTObject_impl::getTypeName()
{
    return m_typeName.c_str();
}

const char *RTObject_impl::getCategory()
{
    return m_category.c_str();
}

const char *RTObject_impl::getDescription()
{
    return m_properties["description"].c_str();
}

const char *RTObject_impl::getVersion()
{
    return m_properties["version"].c_str();
}

const char *RTObject_impl::getVendor()
{
    return m_properties["vendor"].c_str();
}

std::vector<std::string> RTObject_impl::getNamingNames()
{
    std::vector<std::string> names;
    for (const std::string &name : coil::split(m_properties.getProperty("naming.names"), ",", true))
        names.push_back(coil::eraseBlank(name));
    return names;
}

void RTObject_impl::setObjRef(RTObject_ptr rtobj)
{
    RTObject_var own = reference();
    if (CORBA::is_nil(rtobj) || !own->_is_equivalent(rtobj))
        RTC_ERROR(("setObjRef: a component's reference is its own servant's; another reference is refused"));
}

void RTObject_impl::setINSObjRef(LightweightRTObject_ptr)
{
    RTC_ERROR(("setINSObjRef: registration under a corbaloc (INS) key is not supported; the component is"
               " reached through its reference and the naming service"));
}

coil::Properties &RTObject_impl::getProperties()
{
    return m_properties;
}

void RTObject_impl::setProperties(const coil::Properties &prop)
{
    m_properties << prop;
    Runtime::RtObject::setProperties(Sdk::toRuntime(prop));
}

RTObject_ptr RTObject_impl::getObjRef() const
{
    return const_cast<RTObject_impl *>(this)->reference();
}

void RTObject_impl::updateParameters(const char *config_set)
{
    m_configsets.update(config_set);
}

namespace {

// OpenRTM-aist's names for the steps the runtime's ports report.
void notifyConnectStep(PortConnectListeners &listeners, Runtime::ConnectStep step, const char *port,
                       ConnectorProfile &profile, ReturnCode_t result)
{
    using Step = Runtime::ConnectStep;
    switch (step) {
    case Step::NotifyConnect:
        listeners.notify(PortConnectListenerType::ON_NOTIFY_CONNECT, port, profile);
        break;
    case Step::NotifyDisconnect:
        listeners.notify(PortConnectListenerType::ON_NOTIFY_DISCONNECT, port, profile);
        break;
    case Step::UnsubscribeInterfaces:
        listeners.notify(PortConnectListenerType::ON_UNSUBSCRIBE_INTERFACES, port, profile);
        break;
    case Step::PublishInterfaces:
        listeners.notify(PortConnectRetListenerType::ON_PUBLISH_INTERFACES, port, profile, result);
        break;
    case Step::ConnectNextPort:
        listeners.notify(PortConnectRetListenerType::ON_CONNECT_NEXTPORT, port, profile, result);
        break;
    case Step::SubscribeInterfaces:
        listeners.notify(PortConnectRetListenerType::ON_SUBSCRIBE_INTERFACES, port, profile, result);
        break;
    case Step::Connected:
        listeners.notify(PortConnectRetListenerType::ON_CONNECTED, port, profile, result);
        break;
    case Step::DisconnectNextPort:
        listeners.notify(PortConnectRetListenerType::ON_DISCONNECT_NEXT, port, profile, result);
        break;
    case Step::Disconnected:
        listeners.notify(PortConnectRetListenerType::ON_DISCONNECTED, port, profile, result);
        break;
    }
}

} // namespace

} // namespace RTC

void Runtime::PortBase::setPortConnectListenerHolder(RTC::PortConnectListeners *portconnListeners)
{
    if (portconnListeners == nullptr) {
        setConnectObserver({});
        return;
    }
    PortBase *self = this;
    setConnectObserver([self, portconnListeners](Runtime::ConnectStep step, RTC::ConnectorProfile &profile,
                                                 RTC::ReturnCode_t result) {
        RTC::notifyConnectStep(*portconnListeners, step, self->getName(), profile, result);
    });
}

namespace RTC {

bool RTObject_impl::attachPort(PortBase &port)
{
    // As OpenRTM-aist's port admin: a name is listed once (onInitialize() runs again on every
    // remote on_initialize()).
    if (std::find(m_addedPorts.begin(), m_addedPorts.end(), &port) != m_addedPorts.end()
        || findPort(port.shortName()) != nullptr) {
        RTC_ERROR(("a port named %s is listed already; it is not added again", port.shortName().c_str()));
        return false;
    }
    port.setPortConnectListenerHolder(&m_portconnListeners);
    // The listeners see the profile as it will be listed: under the component's instance name.
    RTObject_var self = reference();
    port.setOwner(self.in(), instanceName());
    onAddPort(port.getPortProfile());
    if (!addBorrowedPort(&port))
        return false;
    m_addedPorts.push_back(&port);
    return true;
}

bool RTObject_impl::detachPort(PortBase &port)
{
    if (std::find(m_addedPorts.begin(), m_addedPorts.end(), &port) == m_addedPorts.end())
        return false;
    onRemovePort(port.getPortProfile());
    m_addedPorts.erase(std::remove(m_addedPorts.begin(), m_addedPorts.end(), &port), m_addedPorts.end());
    const bool removed = Runtime::RtObject::removePort(&port);
    port.setConnectObserver({});
    return removed;
}

bool RTObject_impl::addPort(PortBase &port)
{
    return attachPort(port);
}

bool RTObject_impl::addPort(CorbaPort &port)
{
    return addPort(static_cast<PortBase &>(port));
}

namespace {

/**
 * rtc.conf's settings of a data port, as OpenRTM-aist's addInPort() gives them to the port:
 * `port.<kind>.dataport.*` for every port of the kind, then `port.<kind>.<name>.*`; the manager's
 * configuration (when the component has a manager) first, then the component's own properties.
 */
coil::Properties portSettings(Manager *manager, const coil::Properties &component, const char *kind,
                              const char *name)
{
    coil::Properties settings;
    const std::string prefix = std::string("port.") + kind + '.';
    const coil::Properties *config = manager != nullptr ? &manager->getConfig() : nullptr;
    for (const coil::Properties *source : {config, &component}) {
        for (const std::string &node : {prefix + "dataport", prefix + (name != nullptr ? name : "")}) {
            if (const coil::Properties *found = source != nullptr ? source->findNode(node) : nullptr)
                settings << *found;
        }
    }
    return settings;
}

} // namespace

bool RTObject_impl::addInPort(const char *name, InPortBase &inport)
{
    // The port keeps the name it was constructed with, as in OpenRTM-aist; @p name picks its settings.
    if (!attachPort(inport))
        return false;
    coil::Properties settings = portSettings(m_pManager, m_properties, "inport", name);
    inport.init(settings);
    m_inports.push_back(&inport);
    return true;
}

bool RTObject_impl::addOutPort(const char *name, OutPortBase &outport)
{
    if (!attachPort(outport))
        return false;
    coil::Properties settings = portSettings(m_pManager, m_properties, "outport", name);
    outport.init(settings);
    m_outports.push_back(&outport);
    return true;
}

void RTObject_impl::registerPort(PortBase &port)
{
    addPort(port);
}

void RTObject_impl::registerPort(PortService_ptr port)
{
    addPortReference(port);
}

void RTObject_impl::registerPort(CorbaPort &port)
{
    addPort(port);
}

void RTObject_impl::registerInPort(const char *name, InPortBase &inport)
{
    addInPort(name, inport);
}

void RTObject_impl::registerOutPort(const char *name, OutPortBase &outport)
{
    addOutPort(name, outport);
}

void RTObject_impl::deletePort(PortBase &port)
{
    removePort(port);
}

void RTObject_impl::deletePort(PortService_ptr port)
{
    if (CORBA::is_nil(port))
        return;
    const std::vector<PortBase *> ports = m_addedPorts;
    for (PortBase *added : ports) {
        PortService_ptr ref = added->getPortRef(); // borrowed
        if (!CORBA::is_nil(ref) && ref->_is_equivalent(port)) {
            removePort(*added);
            return;
        }
    }
    removePortReference(port);
}

void RTObject_impl::deletePort(CorbaPort &port)
{
    removePort(port);
}

void RTObject_impl::deletePortByName(const char *port_name)
{
    if (port_name == nullptr)
        return;
    const std::vector<PortBase *> ports = m_addedPorts;
    for (PortBase *port : ports) {
        if (std::string(port->getName()) == port_name) {
            if (auto *in = dynamic_cast<InPortBase *>(port))
                removeInPort(*in);
            else if (auto *out = dynamic_cast<OutPortBase *>(port))
                removeOutPort(*out);
            else
                removePort(*port);
            return;
        }
    }
}

void RTObject_impl::shutdown()
{
    shutdownComponent();
}

bool RTObject_impl::removePort(PortBase &port)
{
    return detachPort(port);
}

bool RTObject_impl::removePort(CorbaPort &port)
{
    return removePort(static_cast<PortBase &>(port));
}

bool RTObject_impl::removeInPort(InPortBase &port)
{
    m_inports.erase(std::remove(m_inports.begin(), m_inports.end(), &port), m_inports.end());
    return removePort(port);
}

bool RTObject_impl::removeOutPort(OutPortBase &port)
{
    m_outports.erase(std::remove(m_outports.begin(), m_outports.end(), &port), m_outports.end());
    return removePort(port);
}

void RTObject_impl::finalizePorts()
{
    m_inports.clear();
    m_outports.clear();
    const std::vector<PortBase *> ports = m_addedPorts;
    for (PortBase *port : ports)
        detachPort(*port);
}

void RTObject_impl::finalizeContexts()
{
    ExecutionContextList_var owned = get_owned_contexts();
    for (CORBA::ULong i = 0; i < owned->length(); ++i) {
        try {
            owned[i]->stop();
        } catch (const CORBA::Exception &) {
            // A context already stopped or gone: nothing left to stop.
        }
    }
}

ExecutionContext_ptr RTObject_impl::getExecutionContext(UniqueId ec_id)
{
    return get_context(ec_id);
}

double RTObject_impl::getExecutionRate(UniqueId ec_id)
{
    ExecutionContext_var context = get_context(ec_id);
    if (CORBA::is_nil(context))
        return 0.0;
    try {
        return context->get_rate();
    } catch (const CORBA::Exception &) {
        return 0.0;
    }
}

ReturnCode_t RTObject_impl::setExecutionRate(UniqueId ec_id, double rate)
{
    ExecutionContext_var context = get_context(ec_id);
    if (CORBA::is_nil(context))
        return RTC::BAD_PARAMETER;
    try {
        return context->set_rate(rate);
    } catch (const CORBA::Exception &) {
        return RTC::RTC_ERROR;
    }
}

bool RTObject_impl::isOwnExecutionContext(UniqueId ec_id)
{
    ExecutionContextList_var owned = get_owned_contexts();
    return ec_id >= 0 && CORBA::ULong(ec_id) < owned->length();
}

namespace {

template <typename Transition>
ReturnCode_t onContext(RTObject_impl &component, UniqueId ec_id, Transition transition)
{
    ExecutionContext_var context = component.get_context(ec_id);
    if (CORBA::is_nil(context))
        return RTC::BAD_PARAMETER;
    RTObject_var self = component.getObjRef();
    try {
        return transition(context.in(), self.in());
    } catch (const CORBA::Exception &) {
        return RTC::RTC_ERROR;
    }
}

} // namespace

ReturnCode_t RTObject_impl::activate(UniqueId ec_id)
{
    return onContext(*this, ec_id, [](ExecutionContext_ptr c, RTObject_ptr self) { return c->activate_component(self); });
}

ReturnCode_t RTObject_impl::deactivate(UniqueId ec_id)
{
    return onContext(*this, ec_id,
                     [](ExecutionContext_ptr c, RTObject_ptr self) { return c->deactivate_component(self); });
}

ReturnCode_t RTObject_impl::reset(UniqueId ec_id)
{
    return onContext(*this, ec_id, [](ExecutionContext_ptr c, RTObject_ptr self) { return c->reset_component(self); });
}

bool RTObject_impl::readAll()
{
    bool all = true;
    for (InPortBase *port : m_inports) {
        if (!port->read()) {
            all = false;
            if (m_readAllCompletion)
                return false;
        }
    }
    return all;
}

bool RTObject_impl::writeAll()
{
    bool all = true;
    for (OutPortBase *port : m_outports) {
        if (!port->write()) {
            all = false;
            if (m_writeAllCompletion)
                return false;
        }
    }
    return all;
}

void RTObject_impl::setReadAll(bool read, bool completion)
{
    m_readAll = read;
    m_readAllCompletion = completion;
}

void RTObject_impl::setWriteAll(bool write, bool completion)
{
    m_writeAll = write;
    m_writeAllCompletion = completion;
}

void RTObject_impl::addConfigurationParamListener(ConfigurationParamListenerType type,
                                                  ConfigurationParamListener *listener, bool autoclean)
{
    m_configsets.addConfigurationParamListener(type, listener, autoclean);
}

void RTObject_impl::removeConfigurationParamListener(ConfigurationParamListenerType type,
                                                     ConfigurationParamListener *listener)
{
    m_configsets.removeConfigurationParamListener(type, listener);
}

void RTObject_impl::addConfigurationSetListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener,
                                                bool autoclean)
{
    m_configsets.addConfigurationSetListener(type, listener, autoclean);
}

void RTObject_impl::removeConfigurationSetListener(ConfigurationSetListenerType type,
                                                   ConfigurationSetListener *listener)
{
    m_configsets.removeConfigurationSetListener(type, listener);
}

void RTObject_impl::addConfigurationSetNameListener(ConfigurationSetNameListenerType type,
                                                    ConfigurationSetNameListener *listener, bool autoclean)
{
    m_configsets.addConfigurationSetNameListener(type, listener, autoclean);
}

void RTObject_impl::removeConfigurationSetNameListener(ConfigurationSetNameListenerType type,
                                                       ConfigurationSetNameListener *listener)
{
    m_configsets.removeConfigurationSetNameListener(type, listener);
}

bool RTObject_impl::addSdoServiceProvider(const SDOPackage::ServiceProfile &prof, SdoServiceProviderBase *provider)
{
    if (provider == nullptr)
        return false;
    SDOPackage::ServiceProfile profile(prof);
    if (CORBA::is_nil(profile.service))
        profile.service = provider->_this();
    std::lock_guard<std::mutex> lock(m_sdoMutex);
    for (const auto &offered : m_sdoProviders) {
        if (std::string(offered.first.id) == std::string(prof.id))
            return false;
    }
    m_sdoProviders.emplace_back(profile, provider);
    return true;
}

bool RTObject_impl::removeSdoServiceProvider(const char *id)
{
    SdoServiceProviderBase *removed = nullptr;
    {
        std::lock_guard<std::mutex> lock(m_sdoMutex);
        for (auto it = m_sdoProviders.begin(); it != m_sdoProviders.end(); ++it) {
            if (id != nullptr && std::string(it->first.id) == id) {
                removed = it->second;
                m_sdoProviders.erase(it);
                break;
            }
        }
    }
    if (removed == nullptr)
        return false;
    removed->finalize();
    return true;
}

bool RTObject_impl::addSdoServiceConsumer(const SDOPackage::ServiceProfile &prof)
{
    const std::string id(prof.id);
    {
        std::lock_guard<std::mutex> lock(m_sdoMutex);
        for (SdoServiceConsumerBase *consumer : m_sdoConsumers) {
            if (id == static_cast<const char *>(consumer->getProfile().id))
                return consumer->reinit(prof);
        }
    }
    const std::string type(prof.interface_type);
    SdoServiceConsumerBase *consumer = SdoServiceConsumerFactory::instance().createObject(type);
    if (consumer == nullptr) {
        RTC_ERROR(("addSdoServiceConsumer(%s): no SDO service consumer of interface type '%s' is registered",
                   id.c_str(), type.c_str()));
        return false;
    }
    if (!consumer->init(*this, prof)) {
        RTC_WARN(("addSdoServiceConsumer(%s): the consumer of interface type '%s' refused the profile", id.c_str(),
                  type.c_str()));
        SdoServiceConsumerFactory::instance().deleteObject(consumer);
        return false;
    }
    std::lock_guard<std::mutex> lock(m_sdoMutex);
    m_sdoConsumers.push_back(consumer);
    return true;
}

bool RTObject_impl::removeSdoServiceConsumer(const char *id)
{
    SdoServiceConsumerBase *removed = nullptr;
    {
        std::lock_guard<std::mutex> lock(m_sdoMutex);
        for (auto it = m_sdoConsumers.begin(); it != m_sdoConsumers.end(); ++it) {
            if (id != nullptr && std::string((*it)->getProfile().id) == id) {
                removed = *it;
                m_sdoConsumers.erase(it);
                break;
            }
        }
    }
    if (removed == nullptr)
        return false;
    removed->finalize();
    SdoServiceConsumerFactory::instance().deleteObject(removed);
    return true;
}

void RTObject_impl::removeSdoServiceConsumerStartThread(const char *id)
{
    // OpenRTM-aist removes from a thread of its own so that a consumer may remove itself; the
    // removal here takes no lock the consumer could hold.
    removeSdoServiceConsumer(id);
}

SDOPackage::ServiceProfileList *RTObject_impl::get_service_profiles()
{
    SDOPackage::ServiceProfileList_var profiles = Runtime::RtObject::get_service_profiles();
    std::lock_guard<std::mutex> lock(m_sdoMutex);
    for (const auto &offered : m_sdoProviders) {
        const CORBA::ULong n = profiles->length();
        profiles->length(n + 1);
        profiles[n] = offered.first;
    }
    return profiles._retn();
}

void RTObject_impl::addPreComponentActionListener(PreComponentActionListenerType listener_type,
                                                  PreComponentActionListener *listener, bool autoclean)
{
    m_actionListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removePreComponentActionListener(PreComponentActionListenerType listener_type,
                                                     PreComponentActionListener *listener)
{
    m_actionListeners.removeListener(listener_type, listener);
}

void RTObject_impl::addPostComponentActionListener(PostComponentActionListenerType listener_type,
                                                   PostComponentActionListener *listener, bool autoclean)
{
    m_actionListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removePostComponentActionListener(PostComponentActionListenerType listener_type,
                                                      PostComponentActionListener *listener)
{
    m_actionListeners.removeListener(listener_type, listener);
}

void RTObject_impl::addPortActionListener(PortActionListenerType listener_type, PortActionListener *listener,
                                          bool autoclean)
{
    m_actionListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removePortActionListener(PortActionListenerType listener_type, PortActionListener *listener)
{
    m_actionListeners.removeListener(listener_type, listener);
}

void RTObject_impl::addExecutionContextActionListener(ECActionListenerType listener_type,
                                                      ExecutionContextActionListener *listener, bool autoclean)
{
    m_actionListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removeExecutionContextActionListener(ECActionListenerType listener_type,
                                                         ExecutionContextActionListener *listener)
{
    m_actionListeners.removeListener(listener_type, listener);
}

void RTObject_impl::addPortConnectListener(PortConnectListenerType listener_type, PortConnectListener *listener,
                                           bool autoclean)
{
    m_portconnListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removePortConnectListener(PortConnectListenerType listener_type, PortConnectListener *listener)
{
    m_portconnListeners.removeListener(listener_type, listener);
}

void RTObject_impl::addPortConnectRetListener(PortConnectRetListenerType listener_type,
                                              PortConnectRetListener *listener, bool autoclean)
{
    m_portconnListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removePortConnectRetListener(PortConnectRetListenerType listener_type,
                                                 PortConnectRetListener *listener)
{
    m_portconnListeners.removeListener(listener_type, listener);
}

SdoServiceProviderBase::~SdoServiceProviderBase() = default;

DataFlowComponentBase::DataFlowComponentBase(Manager *manager)
    : RTObject_impl(manager)
{
}

DataFlowComponentBase::~DataFlowComponentBase() = default;

} // namespace RTC

RTM::LocalServiceProfile::~LocalServiceProfile() = default;

namespace RTC {

void deleteRTObject(RTObject_impl *rtc)
{
    if (rtc != nullptr)
        static_cast<PortableServer::ServantBase *>(rtc)->_remove_ref();
}

FactoryBase::FactoryBase(const coil::Properties &profile)
    : m_Profile(profile)
    , m_Number(-1)
{
}

FactoryBase::~FactoryBase() = default;

coil::Properties &FactoryBase::profile()
{
    return m_Profile;
}

int FactoryBase::number()
{
    return m_Number;
}

FactoryCXX::FactoryCXX(const coil::Properties &profile, RtcNewFunc new_func, RtcDeleteFunc delete_func,
                       RTM::NumberingPolicyBase *policy)
    : FactoryBase(profile)
    , m_New(new_func)
    , m_Delete(delete_func)
    , m_policy(policy)
{
}

FactoryCXX::~FactoryCXX()
{
    delete m_policy;
}

RTObject_impl *FactoryCXX::create(Manager *mgr)
{
    RTObject_impl *rtobj = m_New != nullptr ? m_New(mgr) : nullptr;
    if (rtobj == nullptr)
        return nullptr;
    ++m_Number;
    rtobj->setProperties(profile());
    std::string instanceName(profile().getProperty("type_name"));
    if (m_policy != nullptr)
        instanceName += m_policy->onCreate(rtobj);
    rtobj->setInstanceName(instanceName.c_str());
    return rtobj;
}

void FactoryCXX::destroy(RTObject_impl *comp)
{
    if (comp == nullptr)
        return;
    --m_Number;
    if (m_policy != nullptr) {
        try {
            m_policy->onDelete(comp);
        } catch (...) {
            // not numbered by this factory's policy: nothing to free
        }
    }
    if (m_Delete != nullptr)
        m_Delete(comp);
}

} // namespace RTC
