// -*- C++ -*-
// SampleServiceSVC_impl.cpp: the servants of SampleService.idl; write each operation's body
// where it says TODO.

#include "SampleServiceSVC_impl.h"

// Sample::Clock
ClockSVC_impl::ClockSVC_impl()
{
}

ClockSVC_impl::~ClockSVC_impl()
{
}

// unsigned long long now()
CORBA::ULongLong ClockSVC_impl::now()
{
  // TODO: implement now
  return 0;
}

