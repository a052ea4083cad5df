// -*- C++ -*-
// DataPortsCompTestComp.cpp: a program that starts a manager and creates one DataPortsCompTest in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "DataPortsCompTest.h"

void MyModuleInit(RTC::Manager* manager)
{
  DataPortsCompTestInit(manager);
  RTC::RtcBase* comp = manager->createComponent("DataPortsCompTest");
  if (comp == nullptr)
    {
      std::cerr << "DataPortsCompTestComp: the manager could not create DataPortsCompTest" << std::endl;
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
