// -*- C++ -*-
// SampleCompComp.cpp: a program that starts a manager and creates one SampleComp in it.

#include <rtm/Manager.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "SampleComp.h"

void MyModuleInit(RTC::Manager* manager)
{
  SampleCompInit(manager);
  RTC::RtcBase* comp = manager->createComponent("SampleComp");
  if (comp == nullptr)
    {
      std::cerr << "SampleCompComp: the manager could not create SampleComp" << std::endl;
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
