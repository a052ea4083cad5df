// -*- C++ -*-
// ConfigCompComp.cpp: a program that starts a manager and creates one ConfigComp in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "ConfigComp.h"

void MyModuleInit(RTC::Manager* manager)
{
  ConfigCompInit(manager);
  RTC::RtcBase* comp = manager->createComponent("ConfigComp");
  if (comp == nullptr)
    {
      std::cerr << "ConfigCompComp: the manager could not create ConfigComp" << std::endl;
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
