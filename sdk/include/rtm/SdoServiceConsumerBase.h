// SPDX-License-Identifier: MIT
// The base of SDO service consumers (services of others a component is given to use).
#ifndef RTC_SDOSERVICECONSUMERBASE_H
#define RTC_SDOSERVICECONSUMERBASE_H

#include <coil/Factory.h>
#include <rtm/RTC.h>
#include <rtm/RTObject.h>

namespace RTC {
/**
 * A consumer of an SDO service another party attaches to the component. OpenRTM-aist makes
 * these from a factory by the profile's interface type; RT Studio's SDK has no such factory,
 * so RTObject_impl::addSdoServiceConsumer() refuses every profile with a logged message.
 */
class SdoServiceConsumerBase
{
public:
    virtual ~SdoServiceConsumerBase() = default;
    virtual bool init(RTObject_impl &rtobj, const SDOPackage::ServiceProfile &profile) = 0;
    virtual bool reinit(const SDOPackage::ServiceProfile &profile) = 0;
    virtual const SDOPackage::ServiceProfile &getProfile() const = 0;
    virtual void finalize() = 0;
};

/// SDO service consumers by interface type (what addSdoServiceConsumer() makes them with).
using SdoServiceConsumerFactory = ::coil::GlobalFactory<::RTC::SdoServiceConsumerBase>;
} // namespace RTC

#endif // RTC_SDOSERVICECONSUMERBASE_H
