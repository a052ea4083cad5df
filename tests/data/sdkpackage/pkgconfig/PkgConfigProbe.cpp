// SPDX-License-Identifier: MIT
// Built from the command line with pkg-config's flags for openrtm2: OpenRTM's data types through a
// quoted stub header found on the include path, and coil included the 2.1 way. Prints the values after a round trip through a CORBA::Any.
#include "BasicDataTypeStub.h"
#include <coil-2.1/coil/stringutil.h>
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

  const coil::vstring words = coil::split(textBack->data.in(), "-");
  std::cout << "pkgconfig " << RTC::openrtm_version << " " << textBack->data << " " << words.size() << std::endl;
  return 0;
}
