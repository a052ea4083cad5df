// -*- C++ -*-
// DocumentedCompComp.cpp: a program that starts a manager and creates one DocumentedComp in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "DocumentedComp.h"

void MyModuleInit(RTC::Manager* manager)
{
  DocumentedCompInit(manager);
  RTC::RtcBase* comp = manager->createComponent("DocumentedComp");
  if (comp == nullptr)
    {
      std::cerr << "DocumentedCompComp: the manager could not create DocumentedComp" << std::endl;
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
