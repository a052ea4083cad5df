// SPDX-License-Identifier: MIT
#include "organization.h"

#include "corbautil.h"

namespace Runtime {

namespace {

/// The member's SDO id, empty when it cannot be asked (process gone).
std::string sdoId(SDOPackage::SDO_ptr sdo)
{
    try {
        CORBA::String_var id = sdo->get_sdo_id();
        return id.in();
    } catch (const CORBA::Exception &) {
        return std::string();
    }
}

} // namespace

Organization::Organization(PortableServer::POA_ptr poa, SDOPackage::SDOSystemElement_ptr owner)
    : m_poa(PortableServer::POA::_duplicate(poa))
    , m_id(newUuid())
    , m_owner(SDOPackage::SDOSystemElement::_duplicate(owner))
{
}

Organization::~Organization() = default;

SDOPackage::Organization_ptr Organization::reference()
{
    std::lock_guard lock(m_mutex);
    if (CORBA::is_nil(m_self)) {
        PortableServer::ObjectId_var oid = m_poa->activate_object(this);
        CORBA::Object_var object = m_poa->id_to_reference(oid);
        m_self = SDOPackage::Organization::_narrow(object);
    }
    return SDOPackage::Organization::_duplicate(m_self);
}

void Organization::setProperty(const std::string &name, const std::string &value)
{
    std::lock_guard lock(m_mutex);
    nvSet(m_properties, name, value);
}

SDOPackage::SDOList Organization::members()
{
    std::lock_guard lock(m_mutex);
    return m_members;
}

char *Organization::get_organization_id()
{
    return CORBA::string_dup(m_id.c_str());
}

SDOPackage::OrganizationProperty *Organization::get_organization_property()
{
    auto *property = new SDOPackage::OrganizationProperty;
    std::lock_guard lock(m_mutex);
    property->properties = m_properties;
    return property;
}

CORBA::Any *Organization::get_organization_property_value(const char *name)
{
    if (name == nullptr || *name == '\0')
        throw SDOPackage::InvalidParameter("empty property name");
    std::lock_guard lock(m_mutex);
    for (CORBA::ULong i = 0; i < m_properties.length(); ++i) {
        if (std::string(m_properties[i].name.in()) == name)
            return new CORBA::Any(m_properties[i].value);
    }
    throw SDOPackage::InvalidParameter((std::string("no organization property '") + name + "'").c_str());
}

CORBA::Boolean Organization::add_organization_property(const SDOPackage::OrganizationProperty &organization_property)
{
    std::lock_guard lock(m_mutex);
    for (CORBA::ULong i = 0; i < organization_property.properties.length(); ++i) {
        const SDOPackage::NameValue &entry = organization_property.properties[i];
        CORBA::ULong at = 0;
        while (at < m_properties.length() && std::string(m_properties[at].name.in()) != entry.name.in())
            ++at;
        if (at == m_properties.length())
            m_properties.length(at + 1);
        m_properties[at] = entry;
    }
    return true;
}

CORBA::Boolean Organization::set_organization_property_value(const char *name, const CORBA::Any &value)
{
    if (name == nullptr || *name == '\0')
        throw SDOPackage::InvalidParameter("empty property name");
    SDOPackage::OrganizationProperty property;
    property.properties.length(1);
    property.properties[0].name = name;
    property.properties[0].value = value;
    return add_organization_property(property);
}

CORBA::Boolean Organization::remove_organization_property(const char *name)
{
    if (name == nullptr || *name == '\0')
        throw SDOPackage::InvalidParameter("empty property name");
    std::lock_guard lock(m_mutex);
    SDOPackage::NVList kept;
    bool found = false;
    for (CORBA::ULong i = 0; i < m_properties.length(); ++i) {
        if (std::string(m_properties[i].name.in()) == name) {
            found = true;
            continue;
        }
        const CORBA::ULong n = kept.length();
        kept.length(n + 1);
        kept[n] = m_properties[i];
    }
    if (!found)
        throw SDOPackage::InvalidParameter((std::string("no organization property '") + name + "'").c_str());
    m_properties = kept;
    return true;
}

SDOPackage::SDOSystemElement_ptr Organization::get_owner()
{
    std::lock_guard lock(m_mutex);
    return SDOPackage::SDOSystemElement::_duplicate(m_owner);
}

CORBA::Boolean Organization::set_owner(SDOPackage::SDOSystemElement_ptr sdo)
{
    if (CORBA::is_nil(sdo))
        throw SDOPackage::InvalidParameter("nil owner");
    std::lock_guard lock(m_mutex);
    m_owner = SDOPackage::SDOSystemElement::_duplicate(sdo);
    return true;
}

SDOPackage::SDOList *Organization::get_members()
{
    std::lock_guard lock(m_mutex);
    return new SDOPackage::SDOList(m_members);
}

CORBA::Boolean Organization::set_members(const SDOPackage::SDOList &sdos)
{
    std::lock_guard lock(m_mutex);
    m_members = sdos;
    return true;
}

CORBA::Boolean Organization::add_members(const SDOPackage::SDOList &sdo_list)
{
    std::lock_guard lock(m_mutex);
    appendSequence(m_members, sdo_list);
    return true;
}

CORBA::Boolean Organization::remove_member(const char *id)
{
    if (id == nullptr || *id == '\0')
        throw SDOPackage::InvalidParameter("empty member id");
    // Members are asked their ids without the lock: one may be slow or gone.
    const SDOPackage::SDOList current = members();
    for (CORBA::ULong i = 0; i < current.length(); ++i) {
        if (sdoId(current[i]) != id)
            continue;
        std::lock_guard lock(m_mutex);
        SDOPackage::SDOList kept;
        for (CORBA::ULong j = 0; j < m_members.length(); ++j) {
            if (m_members[j]->_is_equivalent(current[i]))
                continue;
            const CORBA::ULong n = kept.length();
            kept.length(n + 1);
            kept[n] = m_members[j];
        }
        m_members = kept;
        return true;
    }
    throw SDOPackage::InvalidParameter((std::string("no member '") + id + "'").c_str());
}

SDOPackage::DependencyType Organization::get_dependency()
{
    std::lock_guard lock(m_mutex);
    return m_dependency;
}

CORBA::Boolean Organization::set_dependency(SDOPackage::DependencyType dependency)
{
    std::lock_guard lock(m_mutex);
    m_dependency = dependency;
    return true;
}

} // namespace Runtime
