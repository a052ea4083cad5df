// -*- C++ -*-
// ConfigCompTestComp.cpp: a program that starts a manager and creates one ConfigCompTest in it.

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
      std::cerr << "ConfigCompTestComp: the manager could not create ConfigCompTest" << std::endl;
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
