// SPDX-License-Identifier: MIT
#include "rtobject.h"

#include "corbautil.h"
#include "executioncontext.h"
#include "executioncontextfactory.h"
#include "sdoconfiguration.h"

#include <algorithm>
#include <iostream>

namespace Runtime {

RtObject::RtObject(PortableServer::POA_ptr poa)
    : m_poa(PortableServer::POA::_duplicate(poa))
{
}

RtObject::~RtObject() = default;

void RtObject::setProperties(const Properties &properties)
{
    std::lock_guard lock(m_mutex);
    m_properties.merge(properties);
}

Properties RtObject::properties()
{
    std::lock_guard lock(m_mutex);
    return m_properties;
}

std::string RtObject::instanceName()
{
    std::lock_guard lock(m_mutex);
    return m_properties.value("instance_name");
}

RTC::RTObject_ptr RtObject::reference()
{
    std::lock_guard lock(m_mutex);
    if (CORBA::is_nil(m_self)) {
        PortableServer::ObjectId_var id = m_poa->activate_object(this);
        CORBA::Object_var object = m_poa->id_to_reference(id);
        m_self = RTC::RTObject::_narrow(object);
    }
    return RTC::RTObject::_duplicate(m_self);
}

void RtObject::setExitHandler(std::function<void(RtObject *)> handler)
{
    std::lock_guard lock(m_mutex);
    m_exitHandler = std::move(handler);
}

void RtObject::setStatus(const std::string &name, const std::string &value)
{
    std::lock_guard lock(m_mutex);
    m_status[name] = value;
}

void RtObject::setStatus(std::initializer_list<std::pair<std::string, std::string>> values)
{
    std::lock_guard lock(m_mutex);
    for (const auto &[name, value] : values)
        m_status[name] = value;
}

std::string RtObject::status(const std::string &name)
{
    std::lock_guard lock(m_mutex);
    auto it = m_status.find(name);
    return it == m_status.end() ? std::string() : it->second;
}

bool RtObject::listPort(PortBase *port, bool borrowed)
{
    const std::string name = instanceName() + '.' + port->shortName();
    {
        std::lock_guard lock(m_mutex);
        for (PortBase *listed : m_ports) {
            if (listed == port || listed->profileName() == name)
                return false;
        }
    }
    RTC::RTObject_var self = reference();
    port->setOwner(self, instanceName());
    RTC::PortService_var activated = port->reference();
    std::lock_guard lock(m_mutex);
    m_ports.push_back(port);
    if (borrowed)
        m_borrowedPorts.insert(port);
    return true;
}

bool RtObject::addPort(PortBase *port)
{
    if (listPort(port, false))
        return true;
    std::cerr << programName() << ": " << instanceName() << ": a port named " << port->shortName()
              << " is listed already; the new one is not added" << std::endl;
    releaseServant(m_poa, port);
    return false;
}

bool RtObject::addBorrowedPort(PortBase *port)
{
    return listPort(port, true);
}

PortBase *RtObject::findPort(const std::string &name)
{
    const std::string profileName = instanceName() + '.' + name;
    std::lock_guard lock(m_mutex);
    for (PortBase *listed : m_ports) {
        if (listed->profileName() == profileName)
            return listed;
    }
    return nullptr;
}

bool RtObject::removePort(PortBase *port)
{
    bool borrowed = false;
    {
        std::lock_guard lock(m_mutex);
        auto it = std::find(m_ports.begin(), m_ports.end(), port);
        if (it == m_ports.end())
            return false;
        m_ports.erase(it);
        borrowed = m_borrowedPorts.erase(port) > 0;
    }
    port->disconnect_all();
    port->releaseInterfaces();
    releasePort(port, borrowed);
    return true;
}

void RtObject::releasePort(PortBase *port, bool borrowed)
{
    // A borrowed port keeps its creator's reference: only its owner deletes it.
    if (borrowed)
        port->_add_ref();
    releaseServant(m_poa, port);
}

void RtObject::addPortReference(RTC::PortService_ptr port)
{
    if (CORBA::is_nil(port))
        return;
    std::lock_guard lock(m_mutex);
    m_portReferences.emplace_back(RTC::PortService::_duplicate(port));
}

bool RtObject::removePortReference(RTC::PortService_ptr port)
{
    std::lock_guard lock(m_mutex);
    for (auto it = m_portReferences.begin(); it != m_portReferences.end(); ++it) {
        try {
            if (!(*it)->_is_equivalent(port))
                continue;
        } catch (const CORBA::Exception &) {
            continue;
        }
        m_portReferences.erase(it);
        return true;
    }
    return false;
}

void RtObject::setInitializeError(const std::string &reason)
{
    std::lock_guard lock(m_mutex);
    m_initError = reason;
}

ServicePort *RtObject::addServicePort(const std::string &name)
{
    return addPortOnce<ServicePort>(name);
}

std::vector<PortBase *> RtObject::portList()
{
    std::lock_guard lock(m_mutex);
    return m_ports;
}

std::vector<RTC::PortService_var> RtObject::portReferences()
{
    std::lock_guard lock(m_mutex);
    return m_portReferences;
}

// --- ComponentAction: the CORBA callbacks run the user hooks, as RTObject_impl does. ---

RTC::ReturnCode_t RtObject::on_initialize() { return onInitialize(); }
RTC::ReturnCode_t RtObject::on_finalize() { return onFinalize(); }
RTC::ReturnCode_t RtObject::on_startup(RTC::ExecutionContextHandle_t h) { return onStartup(h); }
RTC::ReturnCode_t RtObject::on_shutdown(RTC::ExecutionContextHandle_t h) { return onShutdown(h); }
RTC::ReturnCode_t RtObject::on_aborting(RTC::ExecutionContextHandle_t h) { return onAborting(h); }
RTC::ReturnCode_t RtObject::on_error(RTC::ExecutionContextHandle_t h) { return onError(h); }
RTC::ReturnCode_t RtObject::on_reset(RTC::ExecutionContextHandle_t h) { return onReset(h); }
RTC::ReturnCode_t RtObject::on_execute(RTC::ExecutionContextHandle_t h) { return onExecute(h); }
RTC::ReturnCode_t RtObject::on_rate_changed(RTC::ExecutionContextHandle_t h) { return onRateChanged(h); }

RTC::ReturnCode_t RtObject::on_activated(RTC::ExecutionContextHandle_t h)
{
    // Configuration changes reach the variables in the EC thread, as in OpenRTM.
    m_config.update();
    const RTC::ReturnCode_t result = onActivated(h);
    // As OpenRTM-aist: service providers answer only while the component is active (they are
    // offered even when the user's hook failed; the context then moves on to Error).
    for (PortBase *port : portList())
        port->activateInterfaces();
    return result;
}

RTC::ReturnCode_t RtObject::on_deactivated(RTC::ExecutionContextHandle_t h)
{
    for (PortBase *port : portList())
        port->deactivateInterfaces();
    return onDeactivated(h);
}

RTC::ReturnCode_t RtObject::on_state_update(RTC::ExecutionContextHandle_t h)
{
    const RTC::ReturnCode_t result = onStateUpdate(h);
    m_config.update();
    return result;
}

// --- LightweightRTObject ---

RTC::ReturnCode_t RtObject::initialize()
{
    {
        std::lock_guard lock(m_mutex);
        if (!m_created)
            return RTC::PRECONDITION_NOT_MET;
    }
    m_config.applyProperties(properties());
    if (m_sdoConfig == nullptr) {
        m_sdoConfig = new SdoConfiguration(m_config);
        PortableServer::ObjectId_var id = m_poa->activate_object(m_sdoConfig);
    }
    // The owned context exists before onInitialize (which may ask for it) and refuses an unknown
    // type before any user code runs.
    if (!createOwnedContext()) {
        releaseSdoConfiguration();
        return RTC::BAD_PARAMETER;
    }
    // Through the ComponentAction operation, which subclasses may wrap (the SDK calls its action
    // listeners around it).
    const RTC::ReturnCode_t result = on_initialize();
    if (result != RTC::RTC_OK) {
        releaseOwnedContexts();
        releaseSdoConfiguration();
        return result;
    }
    activateConfiguredSet();
    m_config.update();
    std::vector<ExecutionContext *> contexts;
    {
        std::lock_guard lock(m_mutex);
        m_created = false;
        contexts = m_ownedContexts;
    }
    for (ExecutionContext *context : contexts)
        context->start();
    return RTC::RTC_OK;
}

void RtObject::activateConfiguredSet()
{
    // As OpenRTM-aist: a component's configuration file may name the set it starts with
    // (configuration.active_config); without one, or naming a set it does not define, nothing changes.
    const std::string configured = properties().value("configuration.active_config");
    if (!configured.empty() && configured != m_config.activeSetId() && m_config.hasSet(configured))
        m_config.activate(configured);
}

RTC::ExecutionContextHandle_t RtObject::bindContext(ExecutionContext *context)
{
    if (context == nullptr)
        return -1;
    {
        std::lock_guard lock(m_mutex);
        if (m_finalized)
            return -1;
    }
    try {
        PortableServer::ObjectId_var id = m_poa->activate_object(context);
    } catch (const PortableServer::POA::ServantAlreadyActive &) {
        // The caller asked for its reference already.
    }
    RTC::RTObject_var self = reference();
    RTC::ExecutionContextHandle_t handle = 0;
    {
        std::lock_guard lock(m_mutex);
        handle = RTC::ExecutionContextHandle_t(m_ownedContexts.size());
        m_ownedContexts.push_back(context);
    }
    context->addOwner(self, handle);
    return handle;
}

bool RtObject::createOwnedContext()
{
    const Properties props = properties();
    const std::string type = ExecutionContextFactory::typeOf(props);
    std::string error;
    ExecutionContext *context = ExecutionContextFactory::instance().create(type, props, &error);
    if (context == nullptr) {
        std::cerr << instanceName() << ": " << error << std::endl;
        std::lock_guard lock(m_mutex);
        m_initError = error;
        return false;
    }
    bindContext(context);
    return true;
}

void RtObject::releaseOwnedContexts()
{
    std::vector<ExecutionContext *> contexts;
    {
        std::lock_guard lock(m_mutex);
        contexts.swap(m_ownedContexts);
    }
    for (ExecutionContext *context : contexts) {
        context->halt(true);
        releaseServant(m_poa, context);
    }
}

std::string RtObject::initializeError()
{
    std::lock_guard lock(m_mutex);
    return m_initError;
}

std::vector<ExecutionContext *> RtObject::ownedContexts()
{
    std::lock_guard lock(m_mutex);
    return m_ownedContexts;
}

RTC::ReturnCode_t RtObject::finalize()
{
    {
        std::lock_guard lock(m_mutex);
        if (m_created)
            return RTC::PRECONDITION_NOT_MET;
        // The OMG spec forbids finalizing while still attached to someone else's context.
        if (!m_participating.empty())
            return RTC::PRECONDITION_NOT_MET;
        if (m_finalized)
            return RTC::RTC_OK;
    }
    releaseAll();
    return RTC::RTC_OK;
}

void RtObject::releaseAll()
{
    std::vector<ExecutionContext *> contexts;
    std::vector<PortBase *> ports;
    std::set<PortBase *> borrowed;
    {
        std::lock_guard lock(m_mutex);
        if (m_finalized)
            return;
        m_finalized = true;
        contexts.swap(m_ownedContexts);
        ports.swap(m_ports);
        borrowed.swap(m_borrowedPorts);
    }
    for (ExecutionContext *context : contexts)
        context->halt(false);
    for (PortBase *port : ports) {
        port->disconnect_all();
        port->releaseInterfaces();
    }
    on_finalize();
    for (ExecutionContext *context : contexts)
        releaseServant(m_poa, context);
    for (PortBase *port : ports)
        releasePort(port, borrowed.count(port) > 0);
    releaseSdoConfiguration();
}

void RtObject::releaseSdoConfiguration()
{
    releaseServant(m_poa, m_sdoConfig);
    m_sdoConfig = nullptr;
}

CORBA::Boolean RtObject::is_alive(RTC::ExecutionContext_ptr exec_context)
{
    return get_context_handle(exec_context) >= 0;
}

RTC::ReturnCode_t RtObject::exit()
{
    std::map<RTC::ExecutionContextHandle_t, RTC::ExecutionContext_var> participating;
    {
        std::lock_guard lock(m_mutex);
        if (m_created)
            return RTC::PRECONDITION_NOT_MET;
        participating.swap(m_participating);
    }
    RTC::RTObject_var self = reference();
    for (auto &[handle, context] : participating) {
        try {
            context->deactivate_component(self);
            context->remove_component(self);
        } catch (const CORBA::Exception &) {
            // A context that went away no longer holds us.
        }
    }
    // As OpenRTM-aist's exit(), the component leaves the Active state in its own contexts too before
    // they stop: onDeactivated runs (and closes what onActivated opened). Refused where it is not active.
    for (ExecutionContext *context : ownedContexts()) {
        try {
            context->deactivate_component(self);
        } catch (const CORBA::Exception &) {
            // A context that is going away already.
        }
    }
    shutdownComponent();
    std::function<void(RtObject *)> handler;
    {
        std::lock_guard lock(m_mutex);
        handler.swap(m_exitHandler);
    }
    if (handler)
        handler(this);
    return RTC::RTC_OK;
}

void RtObject::shutdownComponent()
{
    releaseAll();
}

RTC::ExecutionContextHandle_t RtObject::attach_context(RTC::ExecutionContext_ptr exec_context)
{
    std::lock_guard lock(m_mutex);
    const RTC::ExecutionContextHandle_t handle = m_nextParticipatingHandle++;
    m_participating[handle] = RTC::ExecutionContext::_duplicate(exec_context);
    return handle;
}

RTC::ReturnCode_t RtObject::detach_context(RTC::ExecutionContextHandle_t exec_handle)
{
    std::lock_guard lock(m_mutex);
    return m_participating.erase(exec_handle) ? RTC::RTC_OK : RTC::BAD_PARAMETER;
}

RTC::ExecutionContext_ptr RtObject::get_context(RTC::ExecutionContextHandle_t exec_handle)
{
    std::lock_guard lock(m_mutex);
    if (exec_handle >= 0 && size_t(exec_handle) < m_ownedContexts.size())
        return m_ownedContexts[size_t(exec_handle)]->_this();
    auto it = m_participating.find(exec_handle);
    return it == m_participating.end() ? RTC::ExecutionContext::_nil()
                                       : RTC::ExecutionContext::_duplicate(it->second);
}

RTC::ExecutionContextList *RtObject::get_owned_contexts()
{
    std::lock_guard lock(m_mutex);
    auto *list = new RTC::ExecutionContextList;
    list->length(CORBA::ULong(m_ownedContexts.size()));
    for (CORBA::ULong i = 0; i < list->length(); ++i)
        (*list)[i] = m_ownedContexts[i]->_this();
    return list;
}

RTC::ExecutionContextList *RtObject::get_participating_contexts()
{
    std::lock_guard lock(m_mutex);
    auto *list = new RTC::ExecutionContextList;
    for (const auto &entry : m_participating) {
        const CORBA::ULong n = list->length();
        list->length(n + 1);
        (*list)[n] = RTC::ExecutionContext::_duplicate(entry.second);
    }
    return list;
}

RTC::ExecutionContextHandle_t RtObject::get_context_handle(RTC::ExecutionContext_ptr cxt)
{
    if (CORBA::is_nil(cxt))
        return -1;
    std::lock_guard lock(m_mutex);
    for (size_t i = 0; i < m_ownedContexts.size(); ++i) {
        RTC::ExecutionContextService_var own = m_ownedContexts[i]->_this();
        if (own->_is_equivalent(cxt))
            return RTC::ExecutionContextHandle_t(i);
    }
    for (const auto &entry : m_participating) {
        if (entry.second->_is_equivalent(cxt))
            return entry.first;
    }
    return -1;
}

} // namespace Runtime
