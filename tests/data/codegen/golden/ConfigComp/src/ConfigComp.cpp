// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file ConfigComp.cpp
 * @brief Configuration with every widget and constraint
 */
// </rtc-template>

#include "ConfigComp.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const configcomp_spec[] =
  {
    "implementation_id", "ConfigComp",
    "type_name", "ConfigComp",
    "description", "Configuration with every widget and constraint",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Controller",
    "activity_type", "EVENTDRIVEN",
    "kind", "DataFlowComponent",
    "max_instance", "4",
    "language", "C++",
    "lang_type", "compile",
    "conf.default.label", "hello world",
    "conf.default.gain", "1.5",
    "conf.default.count", "3",
    "conf.default.threshold", "10",
    "conf.default.limit", "5",
    "conf.default.mode", "fast",
    "conf.default.features", "camera,lidar",
    "conf.default.order", "first,second",
    "conf.default.weights", "0.5,1.5",
    "conf.default.scale", "0.25",
    "conf.default.target", "42",
    "conf.__widget__.label", "text",
    "conf.__widget__.gain", "slider.0.5",
    "conf.__widget__.count", "spin",
    "conf.__widget__.threshold", "text",
    "conf.__widget__.mode", "radio",
    "conf.__widget__.features", "checkbox",
    "conf.__widget__.order", "ordered_list",
    "conf.__widget__.weights", "text",
    "conf.__widget__.scale", "spin",
    "conf.__constraints__.gain", "0<=x<=10",
    "conf.__constraints__.count", "0<=x<=100",
    "conf.__constraints__.threshold", "x>0",
    "conf.__constraints__.limit", "x<8",
    "conf.__constraints__.mode", "(fast,slow,idle)",
    "conf.__constraints__.features", "(camera,lidar,sonar)",
    "conf.__constraints__.order", "(first,second,third)",
    "conf.__constraints__.weights", "0<=x<=1,0<=x<=2",
    "conf.__constraints__.scale", "x>=0",
    "conf.__constraints__.target", "42",
    "conf.__type__.label", "string",
    "conf.__type__.gain", "double",
    "conf.__type__.count", "int",
    "conf.__type__.threshold", "long",
    "conf.__type__.limit", "short",
    "conf.__type__.mode", "string",
    "conf.__type__.features", "string",
    "conf.__type__.order", "vector<string>",
    "conf.__type__.weights", "vector<double>",
    "conf.__type__.scale", "float",
    "conf.__type__.target", "long",
    ""
  };
// </rtc-template>

ConfigComp::ConfigComp(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_inIn("in", m_in)
  , m_outOut("out", m_out)
    // </rtc-template>
{
}

ConfigComp::~ConfigComp()
{
}

RTC::ReturnCode_t ConfigComp::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  addInPort("in", m_inIn);
  addOutPort("out", m_outOut);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  bindParameter("label", m_label, "hello world");
  bindParameter("gain", m_gainValue, "1.5");
  bindParameter("count", m_count, "3");
  bindParameter("threshold", m_threshold, "10");
  bindParameter("limit", m_limit, "5");
  bindParameter("mode", m_mode, "fast");
  bindParameter("features", m_features, "camera,lidar");
  bindParameter("order", m_order, "first,second");
  bindParameter("weights", m_weights, "0.5,1.5");
  bindParameter("scale", m_scale, "0.25");
  bindParameter("target", m_target, "42");
  // </rtc-template>

  return RTC::RTC_OK;
}

// RTC::ReturnCode_t ConfigComp::onFinalize()
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onStartup(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onShutdown(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onActivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onDeactivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onAborting(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onError(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onReset(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t ConfigComp::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t ConfigComp::onStateUpdate(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ConfigComp::onRateChanged(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

extern "C"
{
  void ConfigCompInit(RTC::Manager* manager)
  {
    coil::Properties profile(configcomp_spec);
    manager->registerFactory(profile,
                             RTC::Create<ConfigComp>,
                             RTC::Delete<ConfigComp>);
  }
}
