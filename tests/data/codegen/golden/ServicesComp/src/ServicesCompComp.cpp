// -*- C++ -*-
// ServicesCompComp.cpp: a program that starts a manager and creates one ServicesComp in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "ServicesComp.h"

void MyModuleInit(RTC::Manager* manager)
{
  ServicesCompInit(manager);
  RTC::RtcBase* comp = manager->createComponent("ServicesComp");
  if (comp == nullptr)
    {
      std::cerr << "ServicesCompComp: the manager could not create ServicesComp" << std::endl;
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
