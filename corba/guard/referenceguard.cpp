// SPDX-License-Identifier: MIT
#include "referenceguard.h"

#include <omniORB4/CORBA.h>
#include <omniORB4/omniIOR.h>
#include <omniORB4/omniInterceptors.h>
#include <omniORB4/omniInternal.h>

#include <cstring>
#include <mutex>

namespace Corba {

namespace {

/// The object key of the references that stand in for undecodable ones: no POA or INS object has it.
constexpr const char *NoObjectKey = "RTStudio/undecodable-reference";

thread_local unsigned long t_standIns = 0;

/// Selects the profile omniORB would (the first IIOP one) and decodes the reference as omniORB is
/// about to; true when that succeeds.
bool decodes(omniIOR *ior)
{
    try {
        if (ior->addr_selected_profile_index() < 0) {
            const IOP::TaggedProfileList &profiles = ior->iopProfiles();
            for (CORBA::ULong i = 0; i < profiles.length(); ++i) {
                if (profiles[i].tag == IOP::TAG_INTERNET_IOP) {
                    ior->addr_selected_profile_index(CORBA::Long(i));
                    break;
                }
            }
        }
        ior->getIORInfo();
        return true;
    } catch (const CORBA::SystemException &) {
        return false;
    }
}

CORBA::Boolean guardIdentity(omni::omniInterceptors::createIdentity_T::info_T &info)
{
    if (decodes(info.ior))
        return true;
    {
        omni_optional_lock lock(*omni::internalLock, info.held_internalLock, info.held_internalLock);
        info.invoke_handle = omni::createInProcessIdentity(reinterpret_cast<const CORBA::Octet *>(NoObjectKey),
                                                           int(std::strlen(NoObjectKey)));
    }
    // createIdentity consumes the IOR it is given; the reference keeps its own.
    info.ior->release();
    ++t_standIns;
    return false;
}

} // namespace

void ReferenceGuard::install()
{
    static std::once_flag installed;
    std::call_once(installed, [] { omniORB::getInterceptors()->createIdentity.add(guardIdentity); });
}

unsigned long ReferenceGuard::standInsOnThisThread()
{
    return t_standIns;
}

} // namespace Corba
