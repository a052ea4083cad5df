// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file DataPortsComp.cpp
 * @brief Data ports of many types
 */
// </rtc-template>

#include "DataPortsComp.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const dataportscomp_spec[] =
  {
    "implementation_id", "DataPortsComp",
    "type_name", "DataPortsComp",
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

DataPortsComp::DataPortsComp(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_in_longIn("in_long", m_in_long)
  , m_doublesIn("in_doubles", m_doubles)
  , m_in_textIn("in_text", m_in_text)
  , m_in_poseIn("in_pose", m_in_pose)
  , m_imageIn("in_image", m_image)
  , m_out_wideOut("out_wide", m_out_wide)
  , m_out_octetsOut("out_octets", m_out_octets)
  , m_out_flagsOut("out_flags", m_out_flags)
  , m_out_vectorOut("out_vector", m_out_vector)
  , m_rangesOut("out_range", m_ranges)
  , m_out_cloudOut("out_cloud", m_out_cloud)
    // </rtc-template>
{
}

DataPortsComp::~DataPortsComp()
{
}

RTC::ReturnCode_t DataPortsComp::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  addInPort("in_long", m_in_longIn);
  addInPort("in_doubles", m_doublesIn);
  addInPort("in_text", m_in_textIn);
  addInPort("in_pose", m_in_poseIn);
  addInPort("in_image", m_imageIn);
  addOutPort("out_wide", m_out_wideOut);
  addOutPort("out_octets", m_out_octetsOut);
  addOutPort("out_flags", m_out_flagsOut);
  addOutPort("out_vector", m_out_vectorOut);
  addOutPort("out_range", m_rangesOut);
  addOutPort("out_cloud", m_out_cloudOut);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  // </rtc-template>

  return RTC::RTC_OK;
}

// RTC::ReturnCode_t DataPortsComp::onFinalize()
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsComp::onStartup(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsComp::onShutdown(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t DataPortsComp::onActivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DataPortsComp::onDeactivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t DataPortsComp::onAborting(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsComp::onError(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsComp::onReset(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t DataPortsComp::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t DataPortsComp::onStateUpdate(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t DataPortsComp::onRateChanged(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

extern "C"
{
  void DataPortsCompInit(RTC::Manager* manager)
  {
    coil::Properties profile(dataportscomp_spec);
    manager->registerFactory(profile,
                             RTC::Create<DataPortsComp>,
                             RTC::Delete<DataPortsComp>);
  }
}
