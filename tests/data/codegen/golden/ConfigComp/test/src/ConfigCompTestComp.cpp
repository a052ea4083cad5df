// -*- C++ -*-
/*!
 * @file ConfigCompTestComp.cpp
 * @brief Standalone program that runs one ConfigCompTest component.
 */

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "ConfigCompTest.h"

void MyModuleInit(RTC::Manager* manager)
{
  ConfigCompTestInit(manager);
  RTC::RtcBase* comp = manager->createComponent("ConfigCompTest");
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
