// SPDX-License-Identifier: MIT
// Built from the command line with pkg-config's flags for openrtm2: OpenRTM's data types through a
// quoted stub header found on the include path. Prints the values after a round trip through a CORBA::Any.
#include "BasicDataTypeStub.h"
#include <rtm/version.h>

#include <iostream>

int main()
{
  RTC::TimedString text;
  text.data = CORBA::string_dup("pkg-config");
  CORBA::Any textAny;
  textAny <<= text;
  const RTC::TimedString* textBack = nullptr;
  if (!(textAny >>= textBack))
    return 1;

  std::cout << "pkgconfig " << RTC::openrtm_version << " " << textBack->data << std::endl;
  return 0;
}
