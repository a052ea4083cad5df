// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file ServicesCompTest.cpp
 * @brief Provided and required services from a multi-module IDL
 */
// </rtc-template>

#include "ServicesCompTest.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const servicescomptest_spec[] =
  {
    "implementation_id", "ServicesCompTest",
    "type_name", "ServicesCompTest",
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

ServicesCompTest::ServicesCompTest(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_MotorPortPort("MotorPort")
  , m_PlannerPortPort("PlannerPort")
  , m_DevicePortPort("DevicePort")
    // </rtc-template>
{
}

ServicesCompTest::~ServicesCompTest()
{
}

RTC::ReturnCode_t ServicesCompTest::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  m_MotorPortPort.registerConsumer("motor0", "Robot::Control::Motor", m_motor);
  addPort(m_MotorPortPort);
  m_PlannerPortPort.registerConsumer("planner", "Nav::Planner", m_plannerImpl);
  m_PlannerPortPort.registerProvider("mapper", "Robot::Geometry::Mapper", m_mapperRef);
  addPort(m_PlannerPortPort);
  m_DevicePortPort.registerProvider("device", "Robot::Control::Device", m_device);
  m_DevicePortPort.registerProvider("driver", "Robot::Control::Motor", m_driver);
  addPort(m_DevicePortPort);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  // </rtc-template>

  return RTC::RTC_OK;
}

// RTC::ReturnCode_t ServicesCompTest::onFinalize()
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onStartup(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onShutdown(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onActivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onDeactivated(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onAborting(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onError(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onReset(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

RTC::ReturnCode_t ServicesCompTest::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

// RTC::ReturnCode_t ServicesCompTest::onStateUpdate(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

// RTC::ReturnCode_t ServicesCompTest::onRateChanged(RTC::UniqueId /*ec_id*/)
// {
//   return RTC::RTC_OK;
// }

extern "C"
{
  void ServicesCompTestInit(RTC::Manager* manager)
  {
    coil::Properties profile(servicescomptest_spec);
    manager->registerFactory(profile,
                             RTC::Create<ServicesCompTest>,
                             RTC::Delete<ServicesCompTest>);
  }
}
