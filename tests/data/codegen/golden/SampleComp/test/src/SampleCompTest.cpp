// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file SampleCompTest.cpp
 * @brief Sample component with "all" port kinds
 */
// </rtc-template>

#include "SampleCompTest.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const samplecomptest_spec[] =
  {
    "implementation_id", "SampleCompTest",
    "type_name", "SampleCompTest",
    "description", "Sample component with \"all\" port kinds",
    "version", "1.2.0",
    "vendor", "Example",
    "category", "Test",
    "activity_type", "PERIODIC",
    "kind", "DataFlowComponent",
    "max_instance", "1",
    "language", "C++",
    "lang_type", "compile",
    "conf.default.gain_value", "10",
    "conf.default.mode", "fast",
    "conf.default.rate", "0.5",
    "conf.__widget__.gain_value", "slider.1",
    "conf.__widget__.mode", "radio",
    "conf.__constraints__.gain_value", "0<=x<=100",
    "conf.__constraints__.mode", "(fast,slow)",
    "conf.__type__.gain_value", "int",
    "conf.__type__.mode", "string",
    "conf.__type__.rate", "double",
    ""
  };
// </rtc-template>

SampleCompTest::SampleCompTest(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_resultIn("out", m_result)
  , m_inOut("in", m_in)
  , m_EchoPortPort("EchoPort")
  , m_ClockPortPort("ClockPort")
    // </rtc-template>
{
}

SampleCompTest::~SampleCompTest()
{
}

RTC::ReturnCode_t SampleCompTest::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  addInPort("out", m_resultIn);
  addOutPort("in", m_inOut);
  m_EchoPortPort.registerConsumer("echo", "Sample::Echo", m_echo0);
  addPort(m_EchoPortPort);
  m_ClockPortPort.registerProvider("clock", "Sample::Clock", m_clock);
  addPort(m_ClockPortPort);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  bindParameter("gain_value", m_gain, "10");
  bindParameter("mode", m_mode, "fast");
  bindParameter("rate", m_rate, "0.5");
  // </rtc-template>

  return RTC::RTC_OK;
}

// RTC::ReturnCode_t SampleCompTest::onFinalize()
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleCompTest::onStartup(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleCompTest::onShutdown(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t SampleCompTest::onActivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t SampleCompTest::onDeactivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleCompTest::onAborting(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleCompTest::onError(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleCompTest::onReset(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t SampleCompTest::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t SampleCompTest::onStateUpdate(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleCompTest::onRateChanged(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

extern "C"
{
  void SampleCompTestInit(RTC::Manager* manager)
  {
    coil::Properties profile(samplecomptest_spec);
    manager->registerFactory(profile,
                             RTC::Create<SampleCompTest>,
                             RTC::Delete<SampleCompTest>);
  }
}
