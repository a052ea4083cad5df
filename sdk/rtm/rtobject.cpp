// SPDX-License-Identifier: MIT
#include <rtm/DataFlowComponentBase.h>
#include <rtm/Manager.h>
#include <rtm/RTObject.h>

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

ReturnCode_t RTObject_impl::on_execute(UniqueId exec_handle)
{
    if (m_readAll)
        readAll();
    const ReturnCode_t result = Runtime::RtObject::on_execute(exec_handle);
    if (m_writeAll)
        writeAll();
    return result;
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

bool RTObject_impl::addPort(PortBase &port)
{
    addBorrowedPort(&port);
    return true;
}

bool RTObject_impl::addPort(CorbaPort &port)
{
    return addPort(static_cast<PortBase &>(port));
}

bool RTObject_impl::addInPort(const char *name, InPortBase &inport)
{
    (void)name; // the port keeps the name it was constructed with, as in OpenRTM-aist
    addBorrowedPort(&inport);
    m_inports.push_back(&inport);
    return true;
}

bool RTObject_impl::addOutPort(const char *name, OutPortBase &outport)
{
    (void)name;
    addBorrowedPort(&outport);
    m_outports.push_back(&outport);
    return true;
}

bool RTObject_impl::removePort(PortBase &port)
{
    return Runtime::RtObject::removePort(&port);
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

DataFlowComponentBase::DataFlowComponentBase(Manager *manager)
    : RTObject_impl(manager)
{
}

DataFlowComponentBase::~DataFlowComponentBase() = default;

} // namespace RTC
