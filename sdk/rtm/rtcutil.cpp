// SPDX-License-Identifier: MIT
#include <rtm/RTCUtil.h>

namespace RTC_Utils {

namespace {

// _is_a asks the object (a remote call); a nil, unreachable or dead object is of no kind.
template<class Interface> bool implements(CORBA::Object_ptr obj)
{
    if (CORBA::is_nil(obj))
        return false;
    try {
        typename Interface::_var_type narrowed = Interface::_narrow(obj);
        return !CORBA::is_nil(narrowed);
    } catch (const CORBA::SystemException &) {
        return false;
    }
}

} // namespace

bool isDataFlowComponent(CORBA::Object_ptr obj)
{
    return implements<OpenRTM::DataFlowComponent>(obj);
}

bool isFsmParticipant(CORBA::Object_ptr obj)
{
    return implements<RTC::FsmParticipant>(obj);
}

bool isFsmObject(CORBA::Object_ptr obj)
{
    return implements<RTC::FsmObject>(obj);
}

bool isMultiModeObject(CORBA::Object_ptr obj)
{
    return implements<RTC::MultiModeObject>(obj);
}

} // namespace RTC_Utils
