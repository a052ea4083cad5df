// SPDX-License-Identifier: MIT
// Includes the project's stub wrapper, which reaches omniidl's header as "sensors/Ranger.hh", and
// sends a value of its type, which nests OpenRTM's RTC::RangerConfig, through a CORBA::Any.
#include "RangerStub.h"

#include <iostream>

int main()
{
  Sensors::TimedRange range;
  range.tm.sec = 3;
  range.tm.nsec = 0;
  range.config.minRange = 0.1;
  range.config.maxRange = 30.0;
  range.range = 4.5;
  CORBA::Any any;
  any <<= range;
  const Sensors::TimedRange* back = 0;
  if (!(any >>= back))
    return 1;
  std::cout << "includedir " << back->range << " " << back->config.maxRange << " " << any.type()->id()
            << std::endl;
  return 0;
}
