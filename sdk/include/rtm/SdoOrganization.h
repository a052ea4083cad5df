// SPDX-License-Identifier: MIT
// An SDO organization: a group of SDOs (members) under an owner, with properties.
#ifndef RTC_SDOORGANIZATION_H
#define RTC_SDOORGANIZATION_H

#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>
#include <rtm/idl/SDOPackageSkel.h>

#include <rtmruntime/organization.h>

#include <mutex>
#include <string>

namespace SDOPackage
{
/**
 * An SDOPackage::Organization servant owned by @p sdo: the runtime's organization (the one
 * composite components list their members with), served by the process's root POA. Its id is
 * a new UUID; the dependency starts as OWN.
 */
class Organization_impl : public ::Runtime::Organization, public virtual PortableServer::RefCountServantBase
{
public:
    explicit Organization_impl(SDOSystemElement_ptr sdo);
    ~Organization_impl() override;

    /// The organization's reference (activated on first use).
    Organization_ptr getObjRef();

protected:
    ::RTC::Logger rtclog;
};
} // namespace SDOPackage

#endif // RTC_SDOORGANIZATION_H
