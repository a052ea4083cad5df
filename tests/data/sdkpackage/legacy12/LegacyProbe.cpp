// SPDX-License-Identifier: MIT
// Uses what a 1.2-era component's sources use: its own IDL's stub header, OpenRTM's types through
// rtm/idl/...Stub.h, the version constants and coil's 1.x time type. Prints the values after a round trip through a CORBA::Any.
#include "GreetingStub.h"
#include <coil/TimeValue.h>
#include <rtm/idl/ExtendedDataTypesStub.h>
#include <rtm/version.h>

#include <iostream>

int main()
{
  RTC::TimedPoint2D point;
  point.data.x = 1.5;
  point.data.y = -2.0;
  CORBA::Any pointAny;
  pointAny <<= point;
  const RTC::TimedPoint2D* pointBack = 0;
  if (!(pointAny >>= pointBack))
    return 1;

  Sample::TimedGreeting greeting;
  greeting.text = CORBA::string_dup("legacy");
  greeting.count = static_cast<CORBA::Long>(pointBack->data.x * 2);
  CORBA::Any greetingAny;
  greetingAny <<= greeting;
  const Sample::TimedGreeting* greetingBack = 0;
  if (!(greetingAny >>= greetingBack))
    return 2;

  const coil::TimeValue period(pointBack->data.x);
  std::cout << "legacy12 " << RTM_MAJOR_VERSION << "." << RTM_MINOR_VERSION << " " << greetingBack->text
            << " " << greetingBack->count << " " << pointBack->data.y << " " << period.sec() << "s"
            << period.usec() << "us" << std::endl;
  return 0;
}
