// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file SampleComp.cpp
 * @brief Sample component with "all" port kinds
 */
// </rtc-template>

#include "SampleComp.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const samplecomp_spec[] =
  {
    "implementation_id", "SampleComp",
    "type_name", "SampleComp",
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

SampleComp::SampleComp(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_inIn("in", m_in)
  , m_resultOut("out", m_result)
  , m_EchoPortPort("EchoPort")
  , m_ClockPortPort("ClockPort")
    // </rtc-template>
{
}

SampleComp::~SampleComp()
{
}

RTC::ReturnCode_t SampleComp::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  addInPort("in", m_inIn);
  addOutPort("out", m_resultOut);
  m_EchoPortPort.registerProvider("echo", "Sample::Echo", m_echo0);
  addPort(m_EchoPortPort);
  m_ClockPortPort.registerConsumer("clock", "Sample::Clock", m_clock);
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

// RTC::ReturnCode_t SampleComp::onFinalize()
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleComp::onStartup(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleComp::onShutdown(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t SampleComp::onActivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t SampleComp::onDeactivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleComp::onAborting(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleComp::onError(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleComp::onReset(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t SampleComp::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t SampleComp::onStateUpdate(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t SampleComp::onRateChanged(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

extern "C"
{
  void SampleCompInit(RTC::Manager* manager)
  {
    coil::Properties profile(samplecomp_spec);
    manager->registerFactory(profile,
                             RTC::Create<SampleComp>,
                             RTC::Delete<SampleComp>);
  }
}
