// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file SampleCompTest.h
 * @brief Sample component with "all" port kinds
 */
// </rtc-template>

#ifndef SAMPLECOMPTEST_H
#define SAMPLECOMPTEST_H

#include <rtm/idl/BasicDataTypeSkel.h>
#include <rtm/idl/ExtendedDataTypesSkel.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>

// Servant classes of the provided interfaces
// <rtc-template block="service_impl_h">
#include "SampleServiceSVC_impl.h"
// </rtc-template>

// IDL stubs for the data types and the required interfaces
// <rtc-template block="consumer_stub_h">
#include <rtm/idl/BasicDataTypeSkel.h>
#include "SampleService.hh"
// </rtc-template>

#include <rtm/Manager.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>

/*!
 * @class SampleCompTest
 * @brief Sample component with "all" port kinds
 */
class SampleCompTest
  : public RTC::DataFlowComponentBase
{
 public:
  explicit SampleCompTest(RTC::Manager* manager);
  ~SampleCompTest() override;

  // <rtc-template block="public_attribute">
  // </rtc-template>

  // <rtc-template block="public_operation">
  // </rtc-template>

  // Callbacks: the ones switched off in the profile stay commented out.
  // <rtc-template block="activity_declare">
  RTC::ReturnCode_t onInitialize() override;
  // RTC::ReturnCode_t onFinalize() override;
  // RTC::ReturnCode_t onStartup(RTC::UniqueId ec_id) override;
  // RTC::ReturnCode_t onShutdown(RTC::UniqueId ec_id) override;
  RTC::ReturnCode_t onActivated(RTC::UniqueId ec_id) override;
  // RTC::ReturnCode_t onDeactivated(RTC::UniqueId ec_id) override;
  // RTC::ReturnCode_t onAborting(RTC::UniqueId ec_id) override;
  // RTC::ReturnCode_t onError(RTC::UniqueId ec_id) override;
  // RTC::ReturnCode_t onReset(RTC::UniqueId ec_id) override;
  RTC::ReturnCode_t onExecute(RTC::UniqueId ec_id) override;
  // RTC::ReturnCode_t onStateUpdate(RTC::UniqueId ec_id) override;
  // RTC::ReturnCode_t onRateChanged(RTC::UniqueId ec_id) override;
  // </rtc-template>

 protected:
  // <rtc-template block="protected_attribute">
  // </rtc-template>

  // <rtc-template block="protected_operation">
  // </rtc-template>

  // Configuration parameters, bound in onInitialize()
  // <rtc-template block="config_declare">
  /*!
   * Amplification
   * - Name: gain_value
   * - Default: 10
   * - Constraint: 0<=x<=100
   */
  int m_gain;
  /*!
   * - Name: mode
   * - Default: fast
   * - Constraint: (fast,slow)
   */
  std::string m_mode;
  /*!
   * - Name: rate
   * - Default: 0.5
   */
  double m_rate;
  // </rtc-template>

  // InPorts: the sample last read, and the port
  // <rtc-template block="inport_declare">
  RTC::TimedDouble m_result;
  /*!
   */
  RTC::InPort<RTC::TimedDouble> m_resultIn;
  // </rtc-template>

  // OutPorts: the sample to write, and the port
  // <rtc-template block="outport_declare">
  RTC::TimedLong m_in;
  /*!
   * Values to copy
   */
  RTC::OutPort<RTC::TimedLong> m_inOut;
  // </rtc-template>

  // Service ports
  // <rtc-template block="corbaport_declare">
  RTC::CorbaPort m_EchoPortPort;
  RTC::CorbaPort m_ClockPortPort;
  // </rtc-template>

  // Servants of the provided interfaces, one per interface
  // <rtc-template block="service_declare">
  ClockSVC_impl m_clock;
  // </rtc-template>

  // The required interfaces: each holds the peer's reference once its port is connected
  // <rtc-template block="consumer_declare">
  RTC::CorbaConsumer<Sample::Echo> m_echo0;
  // </rtc-template>

 private:
  // <rtc-template block="private_attribute">
  // </rtc-template>

  // <rtc-template block="private_operation">
  // </rtc-template>
};

extern "C"
{
  DLL_EXPORT void SampleCompTestInit(RTC::Manager* manager);
}

#endif // SAMPLECOMPTEST_H
