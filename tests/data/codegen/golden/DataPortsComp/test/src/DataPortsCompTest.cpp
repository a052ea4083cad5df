// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file DataPortsCompTest.cpp
 * @brief Data ports of many types
 */
// </rtc-template>

#include "DataPortsCompTest.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const dataportscomptest_spec[] =
  {
    "implementation_id", "DataPortsCompTest",
    "type_name", "DataPortsCompTest",
    "description", "Data ports of many types",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Converter",
    "activity_type", "PERIODIC",
    "kind", "DataFlowComponent",
    "max_instance", "1",
    "language", "C++",
    "lang_type", "compile",
    ""
  };
// </rtc-template>

DataPortsCompTest::DataPortsCompTest(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_out_wideIn("out_wide", m_out_wide)
  , m_out_octetsIn("out_octets", m_out_octets)
  , m_out_flagsIn("out_flags", m_out_flags)
  , m_out_vectorIn("out_vector", m_out_vector)
  , m_rangesIn("out_range", m_ranges)
  , m_out_cloudIn("out_cloud", m_out_cloud)
  , m_in_longOut("in_long", m_in_long)
  , m_doublesOut("in_doubles", m_doubles)
  , m_in_textOut("in_text", m_in_text)
  , m_in_poseOut("in_pose", m_in_pose)
  , m_imageOut("in_image", m_image)
    // </rtc-template>
{
}

DataPortsCompTest::~DataPortsCompTest()
{
}

RTC::ReturnCode_t DataPortsCompTest::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  addInPort("out_wide", m_out_wideIn);
  addInPort("out_octets", m_out_octetsIn);
  addInPort("out_flags", m_out_flagsIn);
  addInPort("out_vector", m_out_vectorIn);
  addInPort("out_range", m_rangesIn);
  addInPort("out_cloud", m_out_cloudIn);
  addOutPort("in_long", m_in_longOut);
  addOutPort("in_doubles", m_doublesOut);
  addOutPort("in_text", m_in_textOut);
  addOutPort("in_pose", m_in_poseOut);
  addOutPort("in_image", m_imageOut);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  // </rtc-template>

  return RTC::RTC_OK;
}

// RTC::ReturnCode_t DataPortsCompTest::onFinalize()
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsCompTest::onStartup(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsCompTest::onShutdown(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t DataPortsCompTest::onActivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DataPortsCompTest::onDeactivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t DataPortsCompTest::onAborting(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsCompTest::onError(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsCompTest::onReset(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t DataPortsCompTest::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t DataPortsCompTest::onStateUpdate(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsCompTest::onRateChanged(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

extern "C"
{
  void DataPortsCompTestInit(RTC::Manager* manager)
  {
    coil::Properties profile(dataportscomptest_spec);
    manager->registerFactory(profile,
                             RTC::Create<DataPortsCompTest>,
                             RTC::Delete<DataPortsCompTest>);
  }
}
