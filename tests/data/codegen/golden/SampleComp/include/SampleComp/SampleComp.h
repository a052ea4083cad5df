// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file SampleComp.h
 * @brief Sample component with "all" port kinds
 */
// </rtc-template>

#ifndef SAMPLECOMP_H
#define SAMPLECOMP_H

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
 * @class SampleComp
 * @brief Sample component with "all" port kinds
 */
class SampleComp
  : public RTC::DataFlowComponentBase
{
 public:
  explicit SampleComp(RTC::Manager* manager);
  ~SampleComp() override;

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
  RTC::TimedLong m_in;
  /*!
   * Values to copy
   */
  RTC::InPort<RTC::TimedLong> m_inIn;
  // </rtc-template>

  // OutPorts: the sample to write, and the port
  // <rtc-template block="outport_declare">
  RTC::TimedDouble m_result;
  /*!
   */
  RTC::OutPort<RTC::TimedDouble> m_resultOut;
  // </rtc-template>

  // Service ports
  // <rtc-template block="corbaport_declare">
  RTC::CorbaPort m_EchoPortPort;
  RTC::CorbaPort m_ClockPortPort;
  // </rtc-template>

  // Servants of the provided interfaces, one per interface
  // <rtc-template block="service_declare">
  EchoSVC_impl m_echo0;
  // </rtc-template>

  // The required interfaces: each holds the peer's reference once its port is connected
  // <rtc-template block="consumer_declare">
  RTC::CorbaConsumer<Sample::Clock> m_clock;
  // </rtc-template>

 private:
  // <rtc-template block="private_attribute">
  // </rtc-template>

  // <rtc-template block="private_operation">
  // </rtc-template>
};

extern "C"
{
  DLL_EXPORT void SampleCompInit(RTC::Manager* manager);
}

#endif // SAMPLECOMP_H
