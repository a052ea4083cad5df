// SPDX-License-Identifier: MIT
// The RTObject and SDO parts of RtObject: profile, ports, status and the SDO accessors.
#include "rtobject.h"

#include "corbautil.h"
#include "sdoconfiguration.h"

namespace Runtime {

RTC::ComponentProfile *RtObject::get_component_profile()
{
    const Properties p = properties();
    auto *profile = new RTC::ComponentProfile;
    profile->instance_name = p.value("instance_name").c_str();
    profile->type_name = p.value("type_name", p.value("implementation_id")).c_str();
    profile->description = p.value("description").c_str();
    profile->version = p.value("version").c_str();
    profile->vendor = p.value("vendor").c_str();
    profile->category = p.value("category").c_str();
    const std::vector<PortBase *> ports = portList();
    profile->port_profiles.length(CORBA::ULong(ports.size()));
    for (CORBA::ULong i = 0; i < ports.size(); ++i) {
        RTC::PortProfile_var port = ports[i]->get_port_profile();
        profile->port_profiles[i] = port.in();
    }
    // Ports of other components listed here (a composite's exported ports) describe themselves;
    // one whose owner is gone is left out.
    for (const RTC::PortService_var &reference : portReferences()) {
        try {
            RTC::PortProfile_var port = reference->get_port_profile();
            const CORBA::ULong n = profile->port_profiles.length();
            profile->port_profiles.length(n + 1);
            profile->port_profiles[n] = port.in();
        } catch (const CORBA::Exception &) {
        }
    }
    profile->parent = RTC::RTObject::_nil();
    profile->properties = propertiesToNv(p);
    return profile;
}

RTC::PortServiceList *RtObject::get_ports()
{
    const std::vector<PortBase *> ports = portList();
    auto *list = new RTC::PortServiceList;
    list->length(CORBA::ULong(ports.size()));
    for (CORBA::ULong i = 0; i < ports.size(); ++i)
        (*list)[i] = ports[i]->reference();
    for (const RTC::PortService_var &reference : portReferences()) {
        const CORBA::ULong n = list->length();
        list->length(n + 1);
        (*list)[n] = RTC::PortService::_duplicate(reference);
    }
    return list;
}

SDOPackage::OrganizationList *RtObject::get_owned_organizations()
{
    return new SDOPackage::OrganizationList;
}

char *RtObject::get_sdo_id()
{
    return CORBA::string_dup(instanceName().c_str());
}

char *RtObject::get_sdo_type()
{
    return CORBA::string_dup(properties().value("description").c_str());
}

SDOPackage::DeviceProfile *RtObject::get_device_profile()
{
    if (!m_sdoConfig)
        throw SDOPackage::NotAvailable("component not initialized");
    return new SDOPackage::DeviceProfile(m_sdoConfig->deviceProfile());
}

SDOPackage::ServiceProfileList *RtObject::get_service_profiles()
{
    if (!m_sdoConfig)
        throw SDOPackage::NotAvailable("component not initialized");
    return new SDOPackage::ServiceProfileList(m_sdoConfig->serviceProfiles());
}

SDOPackage::ServiceProfile *RtObject::get_service_profile(const char *id)
{
    SDOPackage::ServiceProfileList_var all = get_service_profiles();
    for (CORBA::ULong i = 0; i < all->length(); ++i) {
        if (id && std::string(all[i].id) == id)
            return new SDOPackage::ServiceProfile(all[i]);
    }
    throw SDOPackage::InvalidParameter("no such service profile");
}

SDOPackage::SDOService_ptr RtObject::get_sdo_service(const char *id)
{
    SDOPackage::ServiceProfile_var profile = get_service_profile(id);
    return SDOPackage::SDOService::_duplicate(profile->service);
}

SDOPackage::Configuration_ptr RtObject::get_configuration()
{
    if (!m_sdoConfig)
        throw SDOPackage::NotAvailable("component not initialized");
    return m_sdoConfig->_this();
}

SDOPackage::Monitoring_ptr RtObject::get_monitoring()
{
    throw SDOPackage::InterfaceNotImplemented("monitoring is not offered");
}

SDOPackage::OrganizationList *RtObject::get_organizations()
{
    if (!m_sdoConfig)
        return new SDOPackage::OrganizationList;
    return new SDOPackage::OrganizationList(m_sdoConfig->organizations());
}

SDOPackage::NVList *RtObject::get_status_list()
{
    std::lock_guard lock(m_mutex);
    auto *list = new SDOPackage::NVList;
    for (const auto &[name, value] : m_status)
        nvSet(*list, name, value);
    return list;
}

CORBA::Any *RtObject::get_status(const char *nme)
{
    std::lock_guard lock(m_mutex);
    auto it = nme ? m_status.find(nme) : m_status.end();
    if (it == m_status.end())
        throw SDOPackage::InvalidParameter("no such status");
    auto *any = new CORBA::Any;
    *any <<= it->second.c_str();
    return any;
}

} // namespace Runtime
