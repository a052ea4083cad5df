// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file ConfigComp.h
 * @brief Configuration with every widget and constraint
 */
// </rtc-template>

#ifndef CONFIGCOMP_H
#define CONFIGCOMP_H

// Reads the std::vector configuration parameters; it comes before OpenRTM-aist's headers so
// that their conversion templates find it.
#include "VectorConvert.h"

#include <rtm/idl/BasicDataTypeSkel.h>
#include <rtm/idl/ExtendedDataTypesSkel.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>

// Servant classes of the provided interfaces
// <rtc-template block="service_impl_h">
// </rtc-template>

// IDL stubs for the data types and the required interfaces
// <rtc-template block="consumer_stub_h">
#include <rtm/idl/BasicDataTypeSkel.h>
// </rtc-template>

#include <rtm/Manager.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>

/*!
 * @class ConfigComp
 * @brief Configuration with every widget and constraint
 */
class ConfigComp
  : public RTC::DataFlowComponentBase
{
 public:
  explicit ConfigComp(RTC::Manager* manager);
  ~ConfigComp() override;

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
  // RTC::ReturnCode_t onActivated(RTC::UniqueId ec_id) override;
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
   * - Name: label
   * - Default: hello world
   */
  std::string m_label;
  /*!
   * - Name: gain
   * - Default: 1.5
   * - Unit: dB
   * - Constraint: 0<=x<=10
   */
  double m_gainValue;
  /*!
   * - Name: count
   * - Default: 3
   * - Constraint: 0<=x<=100
   */
  int m_count;
  /*!
   * - Name: threshold
   * - Default: 10
   * - Constraint: x>0
   */
  long m_threshold;
  /*!
   * - Name: limit
   * - Default: 5
   * - Constraint: x<8
   */
  short m_limit;
  /*!
   * - Name: mode
   * - Default: fast
   * - Constraint: (fast,slow,idle)
   */
  std::string m_mode;
  /*!
   * - Name: features
   * - Default: camera,lidar
   * - Constraint: (camera,lidar,sonar)
   */
  std::string m_features;
  /*!
   * - Name: order
   * - Default: first,second
   * - Constraint: (first,second,third)
   */
  std::vector<std::string> m_order;
  /*!
   * - Name: weights
   * - Default: 0.5,1.5
   * - Constraint: 0<=x<=1,0<=x<=2
   */
  std::vector<double> m_weights;
  /*!
   * - Name: scale
   * - Default: 0.25
   * - Constraint: x>=0
   */
  float m_scale;
  /*!
   * - Name: target
   * - Default: 42
   * - Constraint: 42
   */
  long m_target;
  // </rtc-template>

  // InPorts: the sample last read, and the port
  // <rtc-template block="inport_declare">
  RTC::TimedDouble m_in;
  /*!
   */
  RTC::InPort<RTC::TimedDouble> m_inIn;
  // </rtc-template>

  // OutPorts: the sample to write, and the port
  // <rtc-template block="outport_declare">
  RTC::TimedDouble m_out;
  /*!
   */
  RTC::OutPort<RTC::TimedDouble> m_outOut;
  // </rtc-template>

  // Service ports
  // <rtc-template block="corbaport_declare">
  // </rtc-template>

  // Servants of the provided interfaces, one per interface
  // <rtc-template block="service_declare">
  // </rtc-template>

  // The required interfaces: each holds the peer's reference once its port is connected
  // <rtc-template block="consumer_declare">
  // </rtc-template>

 private:
  // <rtc-template block="private_attribute">
  // </rtc-template>

  // <rtc-template block="private_operation">
  // </rtc-template>
};

extern "C"
{
  DLL_EXPORT void ConfigCompInit(RTC::Manager* manager);
}

#endif // CONFIGCOMP_H
