// SPDX-License-Identifier: MIT
#include <rtm/CORBA_SeqUtil.h>

namespace CORBA_SeqUtil::detail {

std::string objectToString(CORBA::Object_ptr object)
{
    // Stringifying needs no servant and no remote call: any ORB of the process will do, and
    // this one is the component program's.
    CORBA::ORB_ptr orb = RTC::Manager::instance().getORB();
    CORBA::String_var ior = orb->object_to_string(object);
    return std::string(ior.in());
}

} // namespace CORBA_SeqUtil::detail
