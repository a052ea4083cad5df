// SPDX-License-Identifier: MIT
#include "livesystempeer.h"

#include <algorithm>
#include <atomic>
#include <thread>

namespace LivePeer {

using Lock = std::lock_guard<std::recursive_mutex>;

namespace {

void setNV(SDOPackage::NVList &list, const std::string &name, const std::string &value)
{
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (name == list[i].name.in()) {
            list[i].value <<= value.c_str();
            return;
        }
    }
    const CORBA::ULong n = list.length();
    list.length(n + 1);
    list[n].name = name.c_str();
    list[n].value <<= value.c_str();
}

std::string nvString(const CORBA::Any &any)
{
    const char *text = nullptr;
    return (any >>= text) && text ? std::string(text) : std::string();
}

CosNaming::Name hostName(const std::string &host)
{
    CosNaming::Name name;
    name.length(1);
    name[0].id = host.c_str();
    name[0].kind = "host_cxt";
    return name;
}

std::atomic<int> s_connectorCounter {0};

} // namespace

// Context ----------------------------------------------------------------------------------------

void Context::bind(const std::string &id, const std::string &kind, CORBA::Object_ptr object)
{
    CosNaming::Name host = hostName(this->host);
    try {
        CosNaming::NamingContext_var created = naming->bind_new_context(host);
    } catch (const CosNaming::NamingContext::AlreadyBound &) {
        // The host context is shared by every component of this host.
    }
    CosNaming::Name name = host;
    name.length(2);
    name[1].id = id.c_str();
    name[1].kind = kind.c_str();
    naming->rebind(name, object);
}

void Context::unbind(const std::string &id, const std::string &kind)
{
    CosNaming::Name name = hostName(host);
    name.length(2);
    name[1].id = id.c_str();
    name[1].kind = kind.c_str();
    try {
        naming->unbind(name);
    } catch (const CORBA::UserException &) {
        // Already gone: nothing to undo.
    }
}

// ExecutionContext -------------------------------------------------------------------------------

CORBA::Boolean ExecutionContext::is_running()
{
    Lock lock(m_context.mutex);
    return m_running;
}

RTC::ReturnCode_t ExecutionContext::start()
{
    Lock lock(m_context.mutex);
    if (m_running)
        return RTC::PRECONDITION_NOT_MET;
    m_running = true;
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContext::stop()
{
    Lock lock(m_context.mutex);
    if (!m_running)
        return RTC::PRECONDITION_NOT_MET;
    m_running = false;
    return RTC::RTC_OK;
}

CORBA::Double ExecutionContext::get_rate()
{
    Lock lock(m_context.mutex);
    return m_rate;
}

RTC::ReturnCode_t ExecutionContext::set_rate(CORBA::Double rate)
{
    Lock lock(m_context.mutex);
    if (rate <= 0)
        return RTC::BAD_PARAMETER;
    m_rate = rate;
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContext::add_component(RTC::LightweightRTObject_ptr)
{
    return RTC::UNSUPPORTED;
}

RTC::ReturnCode_t ExecutionContext::remove_component(RTC::LightweightRTObject_ptr)
{
    return RTC::UNSUPPORTED;
}

RTC::ReturnCode_t ExecutionContext::transition(RTC::LifeCycleState from, RTC::LifeCycleState to)
{
    Lock lock(m_context.mutex);
    if (m_state != from)
        return RTC::PRECONDITION_NOT_MET;
    m_state = to;
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContext::activate_component(RTC::LightweightRTObject_ptr)
{
    return transition(RTC::INACTIVE_STATE, RTC::ACTIVE_STATE);
}

RTC::ReturnCode_t ExecutionContext::deactivate_component(RTC::LightweightRTObject_ptr)
{
    return transition(RTC::ACTIVE_STATE, RTC::INACTIVE_STATE);
}

RTC::ReturnCode_t ExecutionContext::reset_component(RTC::LightweightRTObject_ptr)
{
    return transition(RTC::ERROR_STATE, RTC::INACTIVE_STATE);
}

RTC::LifeCycleState ExecutionContext::get_component_state(RTC::LightweightRTObject_ptr)
{
    Lock lock(m_context.mutex);
    return m_state;
}

RTC::ExecutionContextProfile *ExecutionContext::get_profile()
{
    Lock lock(m_context.mutex);
    auto *profile = new RTC::ExecutionContextProfile;
    profile->kind = RTC::PERIODIC;
    profile->rate = m_rate;
    profile->owner
        = m_owner ? RTC::RTObject::_duplicate(m_owner->reference()) : RTC::RTObject::_nil();
    return profile;
}

// Port -------------------------------------------------------------------------------------------

void Port::setReference(RTC::PortService_ptr self, RTC::RTObject_ptr owner)
{
    m_profile.port_ref = RTC::PortService::_duplicate(self);
    m_profile.owner = RTC::RTObject::_duplicate(owner);
}

RTC::PortProfile *Port::get_port_profile()
{
    Lock lock(m_context.mutex);
    return new RTC::PortProfile(m_profile);
}

RTC::ConnectorProfileList *Port::get_connector_profiles()
{
    Lock lock(m_context.mutex);
    return new RTC::ConnectorProfileList(m_profile.connector_profiles);
}

RTC::ConnectorProfile *Port::get_connector_profile(const char *connector_id)
{
    Lock lock(m_context.mutex);
    for (CORBA::ULong i = 0; i < m_profile.connector_profiles.length(); ++i) {
        if (std::string(connector_id) == m_profile.connector_profiles[i].connector_id.in())
            return new RTC::ConnectorProfile(m_profile.connector_profiles[i]);
    }
    return new RTC::ConnectorProfile;
}

// Like OpenRTM, the called port assigns the id and every port of the connector records it.
RTC::ReturnCode_t Port::connect(RTC::ConnectorProfile &connector_profile)
{
    if (std::string(connector_profile.connector_id.in()).empty()) {
        const std::string id
            = "connector" + std::to_string(++s_connectorCounter) + "-" + m_context.host;
        connector_profile.connector_id = id.c_str();
    }
    for (CORBA::ULong i = 0; i < connector_profile.ports.length(); ++i) {
        const RTC::ReturnCode_t code
            = connector_profile.ports[i]->notify_connect(connector_profile);
        if (code != RTC::RTC_OK)
            return code;
    }
    return RTC::RTC_OK;
}

RTC::ReturnCode_t Port::notify_connect(RTC::ConnectorProfile &connector_profile)
{
    Lock lock(m_context.mutex);
    auto &list = m_profile.connector_profiles;
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (std::string(connector_profile.connector_id.in()) == list[i].connector_id.in())
            return RTC::BAD_PARAMETER;
    }
    list.length(list.length() + 1);
    list[list.length() - 1] = connector_profile;
    return RTC::RTC_OK;
}

RTC::ReturnCode_t Port::disconnect(const char *connector_id)
{
    RTC::ConnectorProfile_var profile;
    {
        Lock lock(m_context.mutex);
        profile = get_connector_profile(connector_id);
    }
    if (std::string(profile->connector_id.in()).empty())
        return RTC::BAD_PARAMETER;
    for (CORBA::ULong i = 0; i < profile->ports.length(); ++i)
        profile->ports[i]->notify_disconnect(connector_id);
    return RTC::RTC_OK;
}

RTC::ReturnCode_t Port::notify_disconnect(const char *connector_id)
{
    Lock lock(m_context.mutex);
    auto &list = m_profile.connector_profiles;
    RTC::ConnectorProfileList kept;
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (std::string(connector_id) == list[i].connector_id.in())
            continue;
        kept.length(kept.length() + 1);
        kept[kept.length() - 1] = list[i];
    }
    const bool found = kept.length() != list.length();
    list = kept;
    return found ? RTC::RTC_OK : RTC::BAD_PARAMETER;
}

RTC::ReturnCode_t Port::disconnect_all()
{
    RTC::ConnectorProfileList_var list = get_connector_profiles();
    for (CORBA::ULong i = 0; i < list->length(); ++i)
        disconnect(list[i].connector_id.in());
    return RTC::RTC_OK;
}

// Configuration ----------------------------------------------------------------------------------

void Configuration::addSet(const std::string &id,
                           const std::vector<std::pair<std::string, std::string>> &values)
{
    SDOPackage::ConfigurationSet set;
    set.id = id.c_str();
    set.description = "";
    for (const auto &value : values)
        setNV(set.configuration_data, value.first, value.second);
    m_sets.push_back(set);
}

SDOPackage::ConfigurationSet *Configuration::find(const std::string &id)
{
    for (auto &set : m_sets) {
        if (id == set.id.in())
            return &set;
    }
    return nullptr;
}

SDOPackage::ParameterList *Configuration::get_configuration_parameters()
{
    return new SDOPackage::ParameterList;
}

SDOPackage::NVList *Configuration::get_configuration_parameter_values()
{
    Lock lock(m_context.mutex);
    SDOPackage::ConfigurationSet *active = find(m_active);
    return new SDOPackage::NVList(active ? active->configuration_data : SDOPackage::NVList());
}

CORBA::Any *Configuration::get_configuration_parameter_value(const char *name)
{
    Lock lock(m_context.mutex);
    SDOPackage::ConfigurationSet *active = find(m_active);
    for (CORBA::ULong i = 0; active && i < active->configuration_data.length(); ++i) {
        if (std::string(name) == active->configuration_data[i].name.in())
            return new CORBA::Any(active->configuration_data[i].value);
    }
    throw SDOPackage::InvalidParameter("no such parameter");
}

CORBA::Boolean Configuration::set_configuration_parameter(const char *name, const CORBA::Any &value)
{
    Lock lock(m_context.mutex);
    SDOPackage::ConfigurationSet *active = find(m_active);
    if (!active)
        return false;
    setNV(active->configuration_data, name, nvString(value));
    return true;
}

SDOPackage::ConfigurationSetList *Configuration::get_configuration_sets()
{
    Lock lock(m_context.mutex);
    auto *list = new SDOPackage::ConfigurationSetList;
    list->length(CORBA::ULong(m_sets.size()));
    for (size_t i = 0; i < m_sets.size(); ++i)
        (*list)[CORBA::ULong(i)] = m_sets[i];
    return list;
}

SDOPackage::ConfigurationSet *Configuration::get_configuration_set(const char *config_id)
{
    Lock lock(m_context.mutex);
    SDOPackage::ConfigurationSet *set = find(config_id);
    if (!set)
        throw SDOPackage::InvalidParameter("no such configuration set");
    return new SDOPackage::ConfigurationSet(*set);
}

CORBA::Boolean Configuration::set_configuration_set_values(const SDOPackage::ConfigurationSet &set)
{
    Lock lock(m_context.mutex);
    SDOPackage::ConfigurationSet *existing = find(set.id.in());
    if (!existing)
        return false;
    for (CORBA::ULong i = 0; i < set.configuration_data.length(); ++i)
        setNV(existing->configuration_data, set.configuration_data[i].name.in(),
              nvString(set.configuration_data[i].value));
    return true;
}

SDOPackage::ConfigurationSet *Configuration::get_active_configuration_set()
{
    Lock lock(m_context.mutex);
    SDOPackage::ConfigurationSet *set = find(m_active);
    if (!set)
        throw SDOPackage::NotAvailable("no active configuration set");
    return new SDOPackage::ConfigurationSet(*set);
}

CORBA::Boolean Configuration::add_configuration_set(const SDOPackage::ConfigurationSet &set)
{
    Lock lock(m_context.mutex);
    if (find(set.id.in()))
        return false;
    m_sets.push_back(set);
    return true;
}

CORBA::Boolean Configuration::remove_configuration_set(const char *config_id)
{
    Lock lock(m_context.mutex);
    if (m_active == config_id)
        return false;
    const auto it = std::find_if(m_sets.begin(), m_sets.end(), [&](const auto &set) {
        return std::string(config_id) == set.id.in();
    });
    if (it == m_sets.end())
        return false;
    m_sets.erase(it);
    return true;
}

CORBA::Boolean Configuration::activate_configuration_set(const char *config_id)
{
    Lock lock(m_context.mutex);
    if (!find(config_id))
        return false;
    m_active = config_id;
    return true;
}

} // namespace LivePeer
