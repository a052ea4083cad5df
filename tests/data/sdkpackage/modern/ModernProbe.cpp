// SPDX-License-Identifier: MIT
// Uses OpenRTM's interface data types through rtm/idl/...Skel.h and coil::Properties with the imported
// target's include paths. Prints the values after a round trip through a CORBA::Any.
#include <coil/Properties.h>
#include <rtm/config_rtc.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>

#include <iostream>

int main()
{
  RTC::TimedPose2D pose;
  pose.data.position.x = 3.0;
  pose.data.position.y = 4.0;
  pose.data.heading = 0.5;
  CORBA::Any poseAny;
  poseAny <<= pose;
  const RTC::TimedPose2D* poseBack = nullptr;
  if (!(poseAny >>= poseBack))
    return 1;

  coil::Properties properties;
  properties.setProperty("exec_cxt.periodic.rate", "1000");
  std::cout << "modern " << RTM_VERSION << " sdk=" << RTSTUDIO_SDK << " " << poseBack->data.position.x << " "
            << poseBack->data.position.y << " " << poseBack->data.heading << " rate="
            << properties.getProperty("exec_cxt.periodic.rate") << std::endl;
  return 0;
}
