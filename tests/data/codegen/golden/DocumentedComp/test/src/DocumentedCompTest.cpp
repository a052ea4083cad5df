// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file DocumentedCompTest.cpp
 * @brief A component with every documentation field
 */
// </rtc-template>

#include "DocumentedCompTest.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const documentedcomptest_spec[] =
  {
    "implementation_id", "DocumentedCompTest",
    "type_name", "DocumentedCompTest",
    "description", "A component with every documentation field",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Sensor",
    "activity_type", "PERIODIC",
    "kind", "DataFlowComponent",
    "max_instance", "1",
    "language", "C++",
    "lang_type", "compile",
    "conf.default.period", "0.1",
    "conf.__widget__.period", "text",
    "conf.__constraints__.period", "0.01<=x<=1.0",
    "conf.__type__.period", "double",
    ""
  };
// </rtc-template>

DocumentedCompTest::DocumentedCompTest(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_statusIn("status", m_status)
  , m_commandOut("command", m_command)
  , m_ClockPortPort("ClockPort")
    // </rtc-template>
{
}

DocumentedCompTest::~DocumentedCompTest()
{
}

RTC::ReturnCode_t DocumentedCompTest::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  addInPort("status", m_statusIn);
  addOutPort("command", m_commandOut);
  m_ClockPortPort.registerProvider("clock", "Sample::Clock", m_clock);
  addPort(m_ClockPortPort);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  bindParameter("period", m_period, "0.1");
  // </rtc-template>

  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onFinalize()
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onStartup(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onShutdown(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onActivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onDeactivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onAborting(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onError(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onReset(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onStateUpdate(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedCompTest::onRateChanged(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

extern "C"
{
  void DocumentedCompTestInit(RTC::Manager* manager)
  {
    coil::Properties profile(documentedcomptest_spec);
    manager->registerFactory(profile,
                             RTC::Create<DocumentedCompTest>,
                             RTC::Delete<DocumentedCompTest>);
  }
}
