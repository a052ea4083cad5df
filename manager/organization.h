// SPDX-License-Identifier: MIT
#pragma once

#include <SDOPackage.hh>

#include <mutex>
#include <string>
#include <vector>

namespace Runtime {

/**
 * An SDO organization (SDOPackage::Organization): an id, an owner, a member list, a dependency and
 * name/value properties. Composite components own one and list their members through it; tools
 * (rtshell, RT System Editor) read a composite's members from get_owned_organizations(). The
 * member operations are virtual so that an organization with behaviour (a composite that runs its
 * members) can act on each change and then let this class keep the list.
 */
class Organization : public virtual POA_SDOPackage::Organization
{
public:
    Organization(PortableServer::POA_ptr poa, SDOPackage::SDOSystemElement_ptr owner);
    ~Organization() override;

    /// The organization's reference (activates the servant in the POA on first use). Its owner
    /// ends it with releaseServant() (corbautil.h).
    SDOPackage::Organization_ptr reference();
    std::string id() const { return m_id; }
    /// Sets a string property (get_organization_property shows it).
    void setProperty(const std::string &name, const std::string &value);
    /// The members' references (a copy).
    SDOPackage::SDOList members();

    // SDOPackage::Organization
    char *get_organization_id() override;
    SDOPackage::OrganizationProperty *get_organization_property() override;
    CORBA::Any *get_organization_property_value(const char *name) override;
    CORBA::Boolean add_organization_property(const SDOPackage::OrganizationProperty &organization_property) override;
    CORBA::Boolean set_organization_property_value(const char *name, const CORBA::Any &value) override;
    CORBA::Boolean remove_organization_property(const char *name) override;
    SDOPackage::SDOSystemElement_ptr get_owner() override;
    CORBA::Boolean set_owner(SDOPackage::SDOSystemElement_ptr sdo) override;
    SDOPackage::SDOList *get_members() override;
    CORBA::Boolean set_members(const SDOPackage::SDOList &sdos) override;
    CORBA::Boolean add_members(const SDOPackage::SDOList &sdo_list) override;
    CORBA::Boolean remove_member(const char *id) override;
    SDOPackage::DependencyType get_dependency() override;
    CORBA::Boolean set_dependency(SDOPackage::DependencyType dependency) override;

protected:
    PortableServer::POA_ptr poa() const { return m_poa.in(); }

private:
    PortableServer::POA_var m_poa;
    const std::string m_id;
    mutable std::mutex m_mutex;
    SDOPackage::SDOSystemElement_var m_owner;
    SDOPackage::SDOList m_members;
    SDOPackage::NVList m_properties;
    SDOPackage::DependencyType m_dependency = SDOPackage::OWN;
    SDOPackage::Organization_var m_self;
};

} // namespace Runtime
