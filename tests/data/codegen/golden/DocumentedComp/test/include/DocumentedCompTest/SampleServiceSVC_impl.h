// -*- C++ -*-
// SampleServiceSVC_impl.h: servant classes for the interfaces of SampleService.idl.

#ifndef SAMPLESERVICESVC_IMPL_H
#define SAMPLESERVICESVC_IMPL_H

#include "SampleService.hh"

// Implements Sample::Clock; its operations are defined in SampleServiceSVC_impl.cpp.
class ClockSVC_impl
  : public virtual POA_Sample::Clock,
    public virtual PortableServer::RefCountServantBase
{
 public:
  ClockSVC_impl();
  ~ClockSVC_impl() override;

  // One member per IDL operation and attribute accessor
  // <rtc-template block="Clock_operations">
  // unsigned long long now()
  CORBA::ULongLong now() override;
  // </rtc-template>
};

#endif // SAMPLESERVICESVC_IMPL_H
