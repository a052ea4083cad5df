// SPDX-License-Identifier: MIT
// The base of SDO services a component provides (RTObject_impl::addSdoServiceProvider).
#ifndef RTC_SDOSERVICEPROVIDERBASE_H
#define RTC_SDOSERVICEPROVIDERBASE_H

#include <coil/Factory.h>
#include <rtm/RTC.h>
#include <rtm/RTObject.h>

namespace RTC {
/**
 * An SDO service servant a component offers: it is listed by the component's
 * get_service_profiles() and reached with get_sdo_service(id) once added with
 * RTObject_impl::addSdoServiceProvider().
 */
class SdoServiceProviderBase : public virtual POA_SDOPackage::SDOService,
                               public virtual PortableServer::RefCountServantBase
{
public:
    ~SdoServiceProviderBase() override;
    /// Prepares the service for component @p rtobj under @p profile; false when it cannot serve.
    virtual bool init(RTObject_impl &rtobj, const SDOPackage::ServiceProfile &profile) = 0;
    /// Takes a changed @p profile.
    virtual bool reinit(const SDOPackage::ServiceProfile &profile) = 0;
    virtual const SDOPackage::ServiceProfile &getProfile() const = 0;
    /// Called when the service is removed or the component finalizes.
    virtual void finalize() = 0;
};

/// SDO service providers by interface type.
using SdoServiceProviderFactory = ::coil::GlobalFactory<::RTC::SdoServiceProviderBase>;
} // namespace RTC

#endif // RTC_SDOSERVICEPROVIDERBASE_H
