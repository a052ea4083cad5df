// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file DocumentedComp.cpp
 * @brief A component with every documentation field
 */
// </rtc-template>

#include "DocumentedComp.h"

// The component type as the manager registers it (the profile's properties).
// <rtc-template block="module_spec">
static const char* const documentedcomp_spec[] =
  {
    "implementation_id", "DocumentedComp",
    "type_name", "DocumentedComp",
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

DocumentedComp::DocumentedComp(RTC::Manager* manager)
    // <rtc-template block="initializer">
  : RTC::DataFlowComponentBase(manager)
  , m_commandIn("command", m_command)
  , m_statusOut("status", m_status)
  , m_ClockPortPort("ClockPort")
    // </rtc-template>
{
}

DocumentedComp::~DocumentedComp()
{
}

RTC::ReturnCode_t DocumentedComp::onInitialize()
{
  // Adds the profile's ports to the component.
  // <rtc-template block="registration">
  addInPort("command", m_commandIn);
  addOutPort("status", m_statusOut);
  m_ClockPortPort.registerConsumer("clock", "Sample::Clock", m_clock);
  addPort(m_ClockPortPort);
  // </rtc-template>

  // Ties each configuration parameter to its member, with its default.
  // <rtc-template block="bind_config">
  bindParameter("period", m_period, "0.1");
  // </rtc-template>

  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onFinalize()
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onStartup(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onShutdown(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onActivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onDeactivated(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onAborting(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onError(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onReset(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onExecute(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onStateUpdate(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

RTC::ReturnCode_t DocumentedComp::onRateChanged(RTC::UniqueId /*ec_id*/)
{
  return RTC::RTC_OK;
}

extern "C"
{
  void DocumentedCompInit(RTC::Manager* manager)
  {
    coil::Properties profile(documentedcomp_spec);
    manager->registerFactory(profile,
                             RTC::Create<DocumentedComp>,
                             RTC::Delete<DocumentedComp>);
  }
}
