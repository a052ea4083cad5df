// -*- C++ -*-
// SampleCompTestComp.cpp: a program that starts a manager and creates one SampleCompTest in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "SampleCompTest.h"

void MyModuleInit(RTC::Manager* manager)
{
  SampleCompTestInit(manager);
  RTC::RtcBase* comp = manager->createComponent("SampleCompTest");
  if (comp == nullptr)
    {
      std::cerr << "SampleCompTestComp: the manager could not create SampleCompTest" << std::endl;
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
