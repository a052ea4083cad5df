// -*- C++ -*-
/*!
 * @file SampleCompComp.cpp
 * @brief Standalone program that runs one SampleComp component.
 */

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "SampleComp.h"

void MyModuleInit(RTC::Manager* manager)
{
  SampleCompInit(manager);
  RTC::RtcBase* comp = manager->createComponent("SampleComp");
  if (comp == nullptr)
    {
      std::cerr << "Component create failed." << std::endl;
      std::abort();
    }
}

int main(int argc, char** argv)
{
  RTC::Manager* manager = RTC::Manager::init(argc, argv);
  manager->setModuleInitProc(MyModuleInit);
  manager->activateManager();
  manager->runManager();
  return 0;
}
