// SPDX-License-Identifier: MIT
#pragma once

#include "configadmin.h"

#include <SDOPackage.hh>

#include <mutex>

namespace Runtime {

/**
 * SDOPackage::Configuration servant over a component's ConfigAdmin: configuration sets as NVLists
 * of strings (as OpenRTM-aist sends them), plus device/service profiles and organizations kept as
 * given.
 */
class SdoConfiguration : public virtual POA_SDOPackage::Configuration
{
public:
    explicit SdoConfiguration(ConfigAdmin &admin);

    CORBA::Boolean set_device_profile(const SDOPackage::DeviceProfile &dProfile) override;
    CORBA::Boolean add_service_profile(const SDOPackage::ServiceProfile &sProfile) override;
    CORBA::Boolean add_organization(SDOPackage::Organization_ptr organization_object) override;
    CORBA::Boolean remove_service_profile(const char *id) override;
    CORBA::Boolean remove_organization(const char *organization_id) override;
    SDOPackage::ParameterList *get_configuration_parameters() override;
    SDOPackage::NVList *get_configuration_parameter_values() override;
    CORBA::Any *get_configuration_parameter_value(const char *name) override;
    CORBA::Boolean set_configuration_parameter(const char *name, const CORBA::Any &value) override;
    SDOPackage::ConfigurationSetList *get_configuration_sets() override;
    SDOPackage::ConfigurationSet *get_configuration_set(const char *config_id) override;
    CORBA::Boolean set_configuration_set_values(const SDOPackage::ConfigurationSet &configuration_set) override;
    SDOPackage::ConfigurationSet *get_active_configuration_set() override;
    CORBA::Boolean add_configuration_set(const SDOPackage::ConfigurationSet &configuration_set) override;
    CORBA::Boolean remove_configuration_set(const char *config_id) override;
    CORBA::Boolean activate_configuration_set(const char *config_id) override;

    /// The device profile last set (for the owner's get_device_profile).
    SDOPackage::DeviceProfile deviceProfile();
    SDOPackage::ServiceProfileList serviceProfiles();
    SDOPackage::OrganizationList organizations();

private:
    void toSet(const std::string &id, SDOPackage::ConfigurationSet &set) const;

    ConfigAdmin &m_admin;
    std::mutex m_mutex;
    SDOPackage::DeviceProfile m_deviceProfile;
    SDOPackage::ServiceProfileList m_serviceProfiles;
    SDOPackage::OrganizationList m_organizations;
};

} // namespace Runtime
