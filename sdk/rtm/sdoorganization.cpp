// SPDX-License-Identifier: MIT
#include <rtm/SdoOrganization.h>

#include "sdkinternal.h"

namespace SDOPackage {

Organization_impl::Organization_impl(SDOSystemElement_ptr sdo)
    : ::Runtime::Organization(RTC::Sdk::rootPoa(), sdo)
    , rtclog("organization")
{
}

Organization_impl::~Organization_impl() = default;

Organization_ptr Organization_impl::getObjRef()
{
    return reference();
}

} // namespace SDOPackage
