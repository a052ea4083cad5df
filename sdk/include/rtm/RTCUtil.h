// SPDX-License-Identifier: MIT
// What kind of component an object reference denotes, asked from the object itself (_is_a).
#ifndef RTCUtil_h
#define RTCUtil_h

#include <rtm/idl/OpenRTMSkel.h>
#include <rtm/idl/RTCSkel.h>

namespace RTC_Utils
{
/// Whether `obj` is an OpenRTM::DataFlowComponent (a periodic data-flow component).
bool isDataFlowComponent(CORBA::Object_ptr obj);
/// Whether `obj` is an RTC::FsmParticipant.
bool isFsmParticipant(CORBA::Object_ptr obj);
/// Whether `obj` is an RTC::FsmObject.
bool isFsmObject(CORBA::Object_ptr obj);
/// Whether `obj` is an RTC::MultiModeObject.
bool isMultiModeObject(CORBA::Object_ptr obj);
} // namespace RTC_Utils

#endif // RTCUtil_h
