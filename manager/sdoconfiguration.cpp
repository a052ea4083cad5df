// SPDX-License-Identifier: MIT
#include "sdoconfiguration.h"

#include "corbautil.h"

namespace Runtime {

SdoConfiguration::SdoConfiguration(ConfigAdmin &admin)
    : m_admin(admin)
{
}

CORBA::Boolean SdoConfiguration::set_device_profile(const SDOPackage::DeviceProfile &dProfile)
{
    std::lock_guard lock(m_mutex);
    m_deviceProfile = dProfile;
    return true;
}

CORBA::Boolean SdoConfiguration::add_service_profile(const SDOPackage::ServiceProfile &sProfile)
{
    std::lock_guard lock(m_mutex);
    for (CORBA::ULong i = 0; i < m_serviceProfiles.length(); ++i) {
        if (std::string(m_serviceProfiles[i].id) == std::string(sProfile.id)) {
            m_serviceProfiles[i] = sProfile;
            return true;
        }
    }
    const CORBA::ULong n = m_serviceProfiles.length();
    m_serviceProfiles.length(n + 1);
    m_serviceProfiles[n] = sProfile;
    return true;
}

CORBA::Boolean SdoConfiguration::add_organization(SDOPackage::Organization_ptr organization_object)
{
    if (CORBA::is_nil(organization_object))
        throw SDOPackage::InvalidParameter("nil organization");
    std::lock_guard lock(m_mutex);
    const CORBA::ULong n = m_organizations.length();
    m_organizations.length(n + 1);
    m_organizations[n] = SDOPackage::Organization::_duplicate(organization_object);
    return true;
}

CORBA::Boolean SdoConfiguration::remove_service_profile(const char *id)
{
    std::lock_guard lock(m_mutex);
    SDOPackage::ServiceProfileList kept;
    for (CORBA::ULong i = 0; i < m_serviceProfiles.length(); ++i) {
        if (std::string(m_serviceProfiles[i].id) == id)
            continue;
        const CORBA::ULong n = kept.length();
        kept.length(n + 1);
        kept[n] = m_serviceProfiles[i];
    }
    const bool removed = kept.length() != m_serviceProfiles.length();
    m_serviceProfiles = kept;
    if (!removed)
        throw SDOPackage::InvalidParameter("no such service profile");
    return true;
}

CORBA::Boolean SdoConfiguration::remove_organization(const char *organization_id)
{
    std::lock_guard lock(m_mutex);
    SDOPackage::OrganizationList kept;
    for (CORBA::ULong i = 0; i < m_organizations.length(); ++i) {
        try {
            CORBA::String_var id = m_organizations[i]->get_organization_id();
            if (std::string(id.in()) == organization_id)
                continue;
        } catch (const CORBA::Exception &) {
            continue; // an unreachable organization is dropped as well
        }
        const CORBA::ULong n = kept.length();
        kept.length(n + 1);
        kept[n] = m_organizations[i];
    }
    m_organizations = kept;
    return true;
}

SDOPackage::ParameterList *SdoConfiguration::get_configuration_parameters()
{
    return new SDOPackage::ParameterList;
}

SDOPackage::NVList *SdoConfiguration::get_configuration_parameter_values()
{
    return new SDOPackage::NVList(propertiesToNv(m_admin.set(m_admin.activeSetId())));
}

CORBA::Any *SdoConfiguration::get_configuration_parameter_value(const char *name)
{
    const Properties active = m_admin.set(m_admin.activeSetId());
    if (!name || !active.contains(name))
        throw SDOPackage::InvalidParameter("no such parameter");
    auto *any = new CORBA::Any;
    *any <<= active.value(name).c_str();
    return any;
}

CORBA::Boolean SdoConfiguration::set_configuration_parameter(const char *name, const CORBA::Any &value)
{
    const char *text = nullptr;
    if (!name || !(value >>= text))
        throw SDOPackage::InvalidParameter("parameter values are strings");
    return m_admin.setParameter(name, text);
}

void SdoConfiguration::toSet(const std::string &id, SDOPackage::ConfigurationSet &set) const
{
    set.id = id.c_str();
    set.description = "";
    set.configuration_data = propertiesToNv(m_admin.set(id));
}

SDOPackage::ConfigurationSetList *SdoConfiguration::get_configuration_sets()
{
    auto *list = new SDOPackage::ConfigurationSetList;
    const std::vector<std::string> ids = m_admin.setIds();
    list->length(CORBA::ULong(ids.size()));
    for (CORBA::ULong i = 0; i < ids.size(); ++i)
        toSet(ids[i], (*list)[i]);
    return list;
}

SDOPackage::ConfigurationSet *SdoConfiguration::get_configuration_set(const char *config_id)
{
    if (!config_id || !m_admin.hasSet(config_id))
        throw SDOPackage::InvalidParameter("no such configuration set");
    auto *set = new SDOPackage::ConfigurationSet;
    toSet(config_id, *set);
    return set;
}

CORBA::Boolean SdoConfiguration::set_configuration_set_values(const SDOPackage::ConfigurationSet &configuration_set)
{
    const std::string id(configuration_set.id);
    if (!m_admin.hasSet(id))
        throw SDOPackage::InvalidParameter("no such configuration set");
    Properties values = nvToProperties(configuration_set.configuration_data);
    // OpenRTM-aist stores a composite's exported ports in the `<instance>.<port>` form.
    if (values.contains("exported_ports"))
        values.set("exported_ports", exportedPortList(values.value("exported_ports")));
    return m_admin.setValues(id, values);
}

SDOPackage::ConfigurationSet *SdoConfiguration::get_active_configuration_set()
{
    // OpenRTM-aist: no active set between a change of the sets and the next activation.
    if (!m_admin.isActive())
        throw SDOPackage::NotAvailable("the configuration has changed and no set was activated since");
    auto *set = new SDOPackage::ConfigurationSet;
    toSet(m_admin.activeSetId(), *set);
    return set;
}

CORBA::Boolean SdoConfiguration::add_configuration_set(const SDOPackage::ConfigurationSet &configuration_set)
{
    if (!m_admin.addSet(std::string(configuration_set.id), nvToProperties(configuration_set.configuration_data)))
        throw SDOPackage::InvalidParameter("configuration set exists or has no id");
    return true;
}

CORBA::Boolean SdoConfiguration::remove_configuration_set(const char *config_id)
{
    if (!config_id || !m_admin.removeSet(config_id))
        throw SDOPackage::InvalidParameter("cannot remove this configuration set");
    return true;
}

CORBA::Boolean SdoConfiguration::activate_configuration_set(const char *config_id)
{
    if (!config_id || !m_admin.activate(config_id))
        throw SDOPackage::InvalidParameter("no such (visible) configuration set");
    return true;
}

SDOPackage::DeviceProfile SdoConfiguration::deviceProfile()
{
    std::lock_guard lock(m_mutex);
    return m_deviceProfile;
}

SDOPackage::ServiceProfileList SdoConfiguration::serviceProfiles()
{
    std::lock_guard lock(m_mutex);
    return m_serviceProfiles;
}

SDOPackage::OrganizationList SdoConfiguration::organizations()
{
    std::lock_guard lock(m_mutex);
    return m_organizations;
}

} // namespace Runtime
