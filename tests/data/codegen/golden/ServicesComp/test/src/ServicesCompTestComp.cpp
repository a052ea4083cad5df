// -*- C++ -*-
// ServicesCompTestComp.cpp: a program that starts a manager and creates one ServicesCompTest in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "ServicesCompTest.h"

void MyModuleInit(RTC::Manager* manager)
{
  ServicesCompTestInit(manager);
  RTC::RtcBase* comp = manager->createComponent("ServicesCompTest");
  if (comp == nullptr)
    {
      std::cerr << "ServicesCompTestComp: the manager could not create ServicesCompTest" << std::endl;
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
