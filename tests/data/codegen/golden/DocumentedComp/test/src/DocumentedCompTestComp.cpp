// -*- C++ -*-
// DocumentedCompTestComp.cpp: a program that starts a manager and creates one DocumentedCompTest in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "DocumentedCompTest.h"

void MyModuleInit(RTC::Manager* manager)
{
  DocumentedCompTestInit(manager);
  RTC::RtcBase* comp = manager->createComponent("DocumentedCompTest");
  if (comp == nullptr)
    {
      std::cerr << "DocumentedCompTestComp: the manager could not create DocumentedCompTest" << std::endl;
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
