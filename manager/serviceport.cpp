// SPDX-License-Identifier: MIT
#include "serviceport.h"

#include "corbautil.h"

#include <iostream>

namespace Runtime {

CORBA::Object_ptr ConsumerSlot::object()
{
    std::lock_guard lock(m_mutex);
    return CORBA::Object::_duplicate(m_object);
}

void ConsumerSlot::set(CORBA::Object_ptr object)
{
    std::lock_guard lock(m_mutex);
    m_object = CORBA::Object::_duplicate(object);
}

ServicePort::ServicePort(const std::string &name, PortableServer::POA_ptr poa)
    : PortBase(name)
    , m_poa(PortableServer::POA::_duplicate(poa))
{
    setProperty("port.port_type", "CorbaPort");
}

ServicePort::~ServicePort()
{
    releaseInterfaces();
}

void ServicePort::activateInterfaces()
{
    std::lock_guard lock(m_mutex);
    for (Provider &provider : m_providers) {
        if (provider.active)
            continue;
        try {
            m_poa->activate_object_with_id(provider.id, provider.servant);
        } catch (const PortableServer::POA::ObjectAlreadyActive &) {
            // Still finishing a call of its last activation: it answers as it is.
        } catch (const CORBA::Exception &error) {
            std::cerr << programName() << ": " << profileName() << ": cannot offer "
                      << provider.instanceName << ": " << describeException(error) << std::endl;
            continue;
        }
        provider.active = true;
    }
}

void ServicePort::deactivateInterfaces()
{
    std::lock_guard lock(m_mutex);
    for (Provider &provider : m_providers) {
        if (!provider.active)
            continue;
        provider.active = false;
        try {
            m_poa->deactivate_object(provider.id);
        } catch (const CORBA::Exception &) {
            // Already gone with its POA.
        }
    }
}

void ServicePort::releaseInterfaces()
{
    deactivateInterfaces();
    std::vector<Provider> providers;
    {
        std::lock_guard lock(m_mutex);
        providers.swap(m_providers);
    }
    for (Provider &provider : providers)
        provider.servant->_remove_ref();
}

void ServicePort::registerProvider(const std::string &instanceName, const std::string &typeName,
                                   PortableServer::ServantBase *servant)
{
    // The reference (and so the IOR published on connecting) is made once; the object itself
    // comes and goes with the component's activation.
    PortableServer::ObjectId_var id = m_poa->activate_object(servant);
    CORBA::Object_var ref = m_poa->id_to_reference(id);
    CORBA::String_var ior = theOrb()->object_to_string(ref);
    m_poa->deactivate_object(id);
    {
        std::lock_guard lock(m_mutex);
        m_providers.push_back({instanceName, typeName, servant, id.in(), std::string(ior.in()), false});
    }
    addInterfaceProfile(instanceName, typeName, true);
}

std::shared_ptr<ConsumerSlot> ServicePort::registerConsumer(const std::string &instanceName,
                                                            const std::string &typeName)
{
    auto slot = std::make_shared<ConsumerSlot>();
    {
        std::lock_guard lock(m_mutex);
        m_consumers.push_back({instanceName, typeName, slot, {}});
    }
    addInterfaceProfile(instanceName, typeName, false);
    return slot;
}

RTC::ReturnCode_t ServicePort::publishInterfaces(RTC::ConnectorProfile &profile)
{
    const std::string portName = profileName();
    std::lock_guard lock(m_mutex);
    for (const Provider &provider : m_providers) {
        nvSet(profile.properties, "port." + provider.typeName + '.' + provider.instanceName, provider.ior);
        // OpenRTM 1.1+ also publishes the fully qualified provider key.
        nvSet(profile.properties,
              portName + ".port." + provider.typeName + ".provided." + provider.instanceName, provider.ior);
    }
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ServicePort::subscribeInterfaces(const RTC::ConnectorProfile &profile)
{
    const Properties p = nvToProperties(profile.properties);
    CORBA::ORB_var orb = theOrb();
    std::lock_guard lock(m_mutex);
    for (Consumer &consumer : m_consumers) {
        std::string ior = p.value("port." + consumer.typeName + '.' + consumer.instanceName);
        if (ior.empty()) {
            const Properties ofType = p.subtree("port." + consumer.typeName);
            if (ofType.entries().size() == 1)
                ior = ofType.entries().begin()->second;
        }
        if (ior.empty())
            continue; // OpenRTM leaves an unmatched consumer unconnected without failing
        try {
            CORBA::Object_var object = orb->string_to_object(ior.c_str());
            consumer.slot->set(object);
            consumer.connectorId = std::string(profile.connector_id);
        } catch (const CORBA::Exception &) {
            return RTC::BAD_PARAMETER;
        }
    }
    return RTC::RTC_OK;
}

void ServicePort::unsubscribeInterfaces(const RTC::ConnectorProfile &profile)
{
    const std::string id(profile.connector_id);
    std::lock_guard lock(m_mutex);
    for (Consumer &consumer : m_consumers) {
        if (consumer.connectorId == id) {
            consumer.slot->set(CORBA::Object::_nil());
            consumer.connectorId.clear();
        }
    }
}

} // namespace Runtime
