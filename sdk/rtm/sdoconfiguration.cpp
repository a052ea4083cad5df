// SPDX-License-Identifier: MIT
#include <rtm/SdoConfiguration.h>

#include <coil/UUID.h>

#include <memory>

namespace SDOPackage {

Configuration_impl::Configuration_impl(RTC::ConfigAdmin &configsets, RTC::SdoServiceAdmin &sdoServiceAdmin)
    : ::Runtime::SdoConfiguration(configsets.engine())
    , rtclog("sdo_configuration")
    , m_configsets(configsets)
    , m_sdoservice(sdoServiceAdmin)
{
}

Configuration_impl::~Configuration_impl() = default;

CORBA::Boolean Configuration_impl::add_service_profile(const ServiceProfile &sProfile)
{
    if (!m_sdoservice.addSdoServiceConsumer(sProfile))
        return false;
    // Also kept in the servant's list, which the owner's get_service_profiles() reads.
    return ::Runtime::SdoConfiguration::add_service_profile(sProfile);
}

CORBA::Boolean Configuration_impl::remove_service_profile(const char *id)
{
    if (id == nullptr || !m_sdoservice.removeSdoServiceConsumer(id))
        return false;
    try {
        ::Runtime::SdoConfiguration::remove_service_profile(id);
    } catch (const InvalidParameter &) {
        // added to the component directly, never listed here
    }
    return true;
}

Configuration_ptr Configuration_impl::getObjRef()
{
    std::lock_guard<std::mutex> lock(m_objref_mutex);
    if (CORBA::is_nil(m_objref))
        m_objref = _this();
    return ::SDOPackage::Configuration::_duplicate(m_objref);
}

DeviceProfile Configuration_impl::getDeviceProfile()
{
    return deviceProfile();
}

OrganizationList Configuration_impl::getOrganizations()
{
    return organizations();
}

std::string Configuration_impl::getUUID()
{
    std::unique_ptr<coil::UUID> uuid(coil::UUID_Generator::generateUUID(2, 0x01));
    return uuid->to_string();
}

} // namespace SDOPackage
