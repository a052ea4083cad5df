// -*- C++ -*-
/*!
 * @file  SampleServiceSVC_impl.h
 * @brief Service implementation header of SampleService.idl
 */

#ifndef SAMPLESERVICESVC_IMPL_H
#define SAMPLESERVICESVC_IMPL_H

#include "SampleService.hh"

/*!
 * @class ClockSVC_impl
 * Servant of IDL interface Sample::Clock
 */
class ClockSVC_impl
  : public virtual POA_Sample::Clock,
    public virtual PortableServer::RefCountServantBase
{
 public:
  ClockSVC_impl();
  ~ClockSVC_impl() override;

  // attributes and operations
  // <rtc-template block="Clock_operations">
  // unsigned long long now()
  CORBA::ULongLong now() override;
  // </rtc-template>
};

#endif // SAMPLESERVICESVC_IMPL_H
