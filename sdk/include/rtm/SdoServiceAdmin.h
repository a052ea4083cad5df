// SPDX-License-Identifier: MIT
// The SDO services of one component: the providers it offers and the consumers it attaches.
#ifndef RTC_SDOSERVICEADMIN_H
#define RTC_SDOSERVICEADMIN_H

#include <coil/Factory.h>
#include <coil/Properties.h>
#include <coil/stringutil.h>
#include <rtm/SystemLogger.h>
#include <rtm/idl/SDOPackageStub.h>

#include <string>
#include <vector>

namespace RTC
{
class RTObject_impl;
class SdoServiceProviderBase;
class SdoServiceConsumerBase;

/**
 * The SDO service administration of component @p rtobj, as OpenRTM-aist's SdoServiceAdmin: the
 * lists are the component's own (RTObject_impl::addSdoServiceProvider / addSdoServiceConsumer),
 * so a service added through either is seen by both. init() reads
 * `sdo.service.provider.enabled_services` (the providers SdoServiceProviderFactory makes that
 * the component offers at once, `ALL` for every registered one) and
 * `sdo.service.consumer.enabled_services` (the consumer types addSdoServiceConsumer() accepts;
 * `ALL`, the default, accepts every type).
 */
class SdoServiceAdmin
{
public:
    explicit SdoServiceAdmin(::RTC::RTObject_impl &rtobj);
    virtual ~SdoServiceAdmin();

    virtual void init(const coil::Properties &prop);

    /// The providers' profiles (the caller owns the list).
    SDOPackage::ServiceProfileList *getServiceProviderProfiles();
    /// Provider @p id's profile (the caller owns it); throws SDOPackage::InvalidParameter for an unknown id.
    SDOPackage::ServiceProfile *getServiceProviderProfile(const char *id);
    /// Provider @p id's reference; throws SDOPackage::InvalidParameter for an unknown id.
    SDOPackage::SDOService_ptr getServiceProvider(const char *id);
    bool addSdoServiceProvider(const SDOPackage::ServiceProfile &prof, SdoServiceProviderBase *provider);
    bool removeSdoServiceProvider(const char *id);
    /// Attaches a consumer for @p sProfile; false (logged) when its interface type is not enabled.
    bool addSdoServiceConsumer(const SDOPackage::ServiceProfile &sProfile);
    bool removeSdoServiceConsumer(const char *id);

protected:
    void initProvider(const coil::Properties &prop);
    void initConsumer(const coil::Properties &prop);
    bool isEnabledConsumerType(const SDOPackage::ServiceProfile &sProfile);
    bool isExistingConsumerType(const SDOPackage::ServiceProfile &sProfile);
    static std::string getUUID();
    /// The type name of a repository id: "IDL:org/openrtm/Foo:1.0" gives "Foo".
    static std::string ifrToKey(std::string &ifr);

private:
    RTC::RTObject_impl &m_rtobj;
    coil::vstring m_consumerTypes;
    bool m_allConsumerEnabled;
    ::RTC::Logger rtclog;
};
} // namespace RTC

#endif // RTC_SDOSERVICEADMIN_H
