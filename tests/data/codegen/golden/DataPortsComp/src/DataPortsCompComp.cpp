// -*- C++ -*-
// DataPortsCompComp.cpp: a program that starts a manager and creates one DataPortsComp in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "DataPortsComp.h"

void MyModuleInit(RTC::Manager* manager)
{
  DataPortsCompInit(manager);
  RTC::RtcBase* comp = manager->createComponent("DataPortsComp");
  if (comp == nullptr)
    {
      std::cerr << "DataPortsCompComp: the manager could not create DataPortsComp" << std::endl;
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
