// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file ServicesComp.cpp
 * @brief Provided and required services from a multi-module IDL
 */
// </rtc-template>

#include "ServicesComp.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const servicescomp_spec[] =
  {
    "implementation_id", "ServicesComp",
    "type_name", "ServicesComp",
    "description", "Provided and required services from a multi-module IDL",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Controller",
    "activity_type", "SPORADIC",
    "kind", "DataFlowComponent",
    "max_instance", "0",
    "language", "C++",
    "lang_type", "compile",
    ""
  };
// </rtc-template>

ServicesComp::ServicesComp(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_MotorPortPort("MotorPort")
  , m_PlannerPortPort("PlannerPort")
  , m_DevicePortPort("DevicePort")
    // </rtc-template>
{
}

ServicesComp::~ServicesComp()
{
}

RTC::ReturnCode_t ServicesComp::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  m_MotorPortPort.registerProvider("motor0", "Robot::Control::Motor", m_motor);
  addPort(m_MotorPortPort);
  m_PlannerPortPort.registerProvider("planner", "Nav::Planner", m_plannerImpl);
  m_PlannerPortPort.registerConsumer("mapper", "Robot::Geometry::Mapper", m_mapperRef);
  addPort(m_PlannerPortPort);
  m_DevicePortPort.registerConsumer("device", "Robot::Control::Device", m_device);
  m_DevicePortPort.registerConsumer("driver", "Robot::Control::Motor", m_driver);
  addPort(m_DevicePortPort);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  // </rtc-template>

  return RTC::RTC_OK;
}

// RTC::ReturnCode_t ServicesComp::onFinalize()
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onStartup(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onShutdown(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onActivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onDeactivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onAborting(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onError(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onReset(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t ServicesComp::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t ServicesComp::onStateUpdate(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesComp::onRateChanged(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

extern "C"
{
  void ServicesCompInit(RTC::Manager* manager)
  {
    coil::Properties profile(servicescomp_spec);
    manager->registerFactory(profile,
                             RTC::Create<ServicesComp>,
                             RTC::Delete<ServicesComp>);
  }
}
