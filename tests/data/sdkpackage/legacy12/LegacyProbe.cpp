// SPDX-License-Identifier: MIT
// Uses what a 1.2-era component's sources use: its own IDL's stub header, OpenRTM's types through
// rtm/idl/...Stub.h, the version constants, coil's 1.x time and lock types, and a component written
// in that era's style (virtual callbacks, RTC_INFO, coil::Guard) run by an RTC::Manager in this
// process. Prints the values after a round trip through a CORBA::Any and whether the component ran.
#include "GreetingStub.h"
#include <coil/Guard.h>
#include <coil/Mutex.h>
#include <coil/Time.h>
#include <coil/TimeValue.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/Manager.h>
#include <rtm/idl/ExtendedDataTypesStub.h>
#include <rtm/version.h>

#include <iostream>

static const char* ticker_spec[] =
  {
    "implementation_id", "Ticker",
    "type_name",         "Ticker",
    "description",       "Counts its executions",
    "version",           "1.0.0",
    "vendor",            "RTStudioTests",
    "category",          "Probe",
    "activity_type",     "PERIODIC",
    "kind",              "DataFlowComponent",
    "max_instance",      "1",
    "language",          "C++",
    "lang_type",         "compile",
    "exec_cxt.periodic.rate", "200",
    ""
  };

class Ticker
  : public RTC::DataFlowComponentBase
{
public:
  Ticker(RTC::Manager* manager)
    : RTC::DataFlowComponentBase(manager),
      m_tickOut("tick", m_tick),
      m_count(0)
  {
  }
  virtual ~Ticker() {}

  virtual RTC::ReturnCode_t onInitialize()
  {
    addOutPort("tick", m_tickOut);
    RTC_INFO(("%s initialized", getInstanceName()));
    return RTC::RTC_OK;
  }

  virtual RTC::ReturnCode_t onExecute(RTC::UniqueId ec_id)
  {
    coil::Guard<coil::Mutex> guard(m_mutex);
    ++m_count;
    m_tick.data = m_count;
    m_tickOut.write();
    return RTC::RTC_OK;
  }

  int count()
  {
    coil::Guard<coil::Mutex> guard(m_mutex);
    return m_count;
  }

private:
  RTC::TimedLong m_tick;
  RTC::OutPort<RTC::TimedLong> m_tickOut;
  coil::Mutex m_mutex;
  int m_count;
};

// The manager serves on a loopback port of its own choosing, without a name server or master.
static bool tickerRuns()
{
  static char program[] = "LegacyProbe";
  static char o[] = "-o";
  static char naming[] = "naming.enable:NO";
  static char master[] = "corba.master_manager:";
  static char endpoint[] = "corba.endpoints:127.0.0.1:";
  static char logging[] = "logger.enable:NO";
  char* argv[] = {program, o, naming, o, master, o, endpoint, o, logging, 0};
  RTC::Manager* manager = RTC::Manager::init(9, argv);
  manager->activateManager();
  manager->runManager(true);
  coil::Properties profile(ticker_spec);
  manager->registerFactory(profile, RTC::Create<Ticker>, RTC::Delete<Ticker>);
  Ticker* ticker = dynamic_cast<Ticker*>(manager->createComponent("Ticker"));
  if (ticker == 0)
    return false;
  RTC::ExecutionContextList_var contexts = ticker->get_owned_contexts();
  RTC::RTObject_var self = ticker->getObjRef();
  contexts[0]->activate_component(self);
  const coil::TimeValue start = coil::gettimeofday();
  while (ticker->count() < 5 && coil::gettimeofday() - start < coil::TimeValue(10, 0))
    coil::usleep(10000);
  const bool ran = ticker->count() >= 5;
  manager->terminate();
  manager->join();
  return ran;
}

int main()
{
  RTC::TimedPoint2D point;
  point.data.x = 1.5;
  point.data.y = -2.0;
  CORBA::Any pointAny;
  pointAny <<= point;
  const RTC::TimedPoint2D* pointBack = 0;
  if (!(pointAny >>= pointBack))
    return 1;

  Sample::TimedGreeting greeting;
  greeting.text = CORBA::string_dup("legacy");
  greeting.count = static_cast<CORBA::Long>(pointBack->data.x * 2);
  CORBA::Any greetingAny;
  greetingAny <<= greeting;
  const Sample::TimedGreeting* greetingBack = 0;
  if (!(greetingAny >>= greetingBack))
    return 2;

  const coil::TimeValue period(pointBack->data.x);
  std::cout << "legacy12 " << RTM_MAJOR_VERSION << "." << RTM_MINOR_VERSION << " " << greetingBack->text
            << " " << greetingBack->count << " " << pointBack->data.y << " " << period.sec() << "s"
            << period.usec() << "us " << (tickerRuns() ? "ticked" : "stalled") << std::endl;
  return 0;
}
