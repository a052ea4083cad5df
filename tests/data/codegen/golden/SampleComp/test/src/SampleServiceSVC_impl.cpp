// -*- C++ -*-
/*!
 * @file  SampleServiceSVC_impl.cpp
 * @brief Service implementation code of SampleService.idl
 */

#include "SampleServiceSVC_impl.h"

/*
 * Servant of IDL interface Sample::Clock
 */
ClockSVC_impl::ClockSVC_impl()
{
  // Please add extra constructor code here.
}

ClockSVC_impl::~ClockSVC_impl()
{
  // Please add extra destructor code here.
}

/*
 * Methods corresponding to IDL attributes and operations
 */
// unsigned long long now()
CORBA::ULongLong ClockSVC_impl::now()
{
  // Please insert your code here.
  return 0;
}

// End of servant code
