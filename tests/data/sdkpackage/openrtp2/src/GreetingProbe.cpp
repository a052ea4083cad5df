// SPDX-License-Identifier: MIT
// Uses what an OpenRTP 2.0 component's sources use: its own IDL's skeleton header, OpenRTM's data types
// through a quoted wrapper header, rtm/version.h and coil included the 2.0 way. Prints the values after a round trip through a
// CORBA::Any, which exercises the stub code in the project and in the SDK's library.
#include "BasicDataTypeSkel.h"
#include "GreetingSkel.h"
#include <coil-2.0/coil/stringutil.h>
#include <rtm/version.h>

#include <iostream>

int main()
{
  RTC::TimedLong value;
  value.tm.sec = 1;
  value.tm.nsec = 2;
  value.data = 42;
  CORBA::Any valueAny;
  valueAny <<= value;
  const RTC::TimedLong* valueBack = 0;
  if (!(valueAny >>= valueBack))
    return 1;

  Sample::TimedGreeting greeting;
  greeting.tm = valueBack->tm;
  greeting.text = CORBA::string_dup("hello");
  greeting.count = valueBack->data;
  CORBA::Any greetingAny;
  greetingAny <<= greeting;
  const Sample::TimedGreeting* greetingBack = 0;
  if (!(greetingAny >>= greetingBack))
    return 2;

  std::cout << "openrtp2 " << RTC::openrtm_version << " " << coil::toUpper(greetingBack->text.in()) << " "
            << greetingBack->count << " " << greetingBack->tm.nsec << std::endl;
  return 0;
}
