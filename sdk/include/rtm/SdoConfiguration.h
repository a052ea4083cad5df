// SPDX-License-Identifier: MIT
// The SDO Configuration interface of a component: its configuration sets, device profile,
// service profiles and organizations.
#ifndef RTC_SDOCONFIGURATION_H
#define RTC_SDOCONFIGURATION_H

#include <rtm/RTC.h>

#include <mutex>

#include <rtm/ConfigAdmin.h>
#include <rtm/SdoServiceAdmin.h>
#include <rtm/SystemLogger.h>
#include <rtm/idl/SDOPackageSkel.h>

#include <rtmruntime/sdoconfiguration.h>

#include <string>

namespace SDOPackage
{
/**
 * An SDOPackage::Configuration servant over component configuration @p configsets, the one the
 * runtime gives every component (same NVList-of-strings sets as OpenRTM-aist). Service profiles
 * added through it attach SDO service consumers through @p sdoServiceAdmin, as in OpenRTM-aist.
 */
class Configuration_impl : public ::Runtime::SdoConfiguration, public virtual PortableServer::RefCountServantBase
{
public:
    Configuration_impl(RTC::ConfigAdmin &configsets, RTC::SdoServiceAdmin &sdoServiceAdmin);
    ~Configuration_impl() override;

    /// Attaches the consumer the profile names (false when its type is not enabled or unknown).
    CORBA::Boolean add_service_profile(const ServiceProfile &sProfile) override;
    /// Detaches consumer @p id; false when there is none.
    CORBA::Boolean remove_service_profile(const char *id) override;

    /// The servant's reference (activated in the ORB's root POA on first use).
    Configuration_ptr getObjRef();
    DeviceProfile getDeviceProfile();
    OrganizationList getOrganizations();

protected:
    static std::string getUUID();

    ::RTC::Logger rtclog;
    Configuration_var m_objref;
    RTC::ConfigAdmin &m_configsets;
    RTC::SdoServiceAdmin &m_sdoservice;
    std::mutex m_objref_mutex;
};
} // namespace SDOPackage

#endif // RTC_SDOCONFIGURATION_H
