// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file ServicesCompTest.h
 * @brief Provided and required services from a multi-module IDL
 */
// </rtc-template>

#ifndef SERVICESCOMPTEST_H
#define SERVICESCOMPTEST_H

#include <rtm/idl/BasicDataTypeSkel.h>
#include <rtm/idl/ExtendedDataTypesSkel.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>

// Servant classes of the provided interfaces
// <rtc-template block="service_impl_h">
#include "RoboticsSVC_impl.h"
// </rtc-template>

// IDL stubs for the data types and the required interfaces
// <rtc-template block="consumer_stub_h">
#include "Robotics.hh"
// </rtc-template>

#include <rtm/Manager.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>

/*!
 * @class ServicesCompTest
 * @brief Provided and required services from a multi-module IDL
 */
class ServicesCompTest
  : public RTC::DataFlowComponentBase
{
 public:
  explicit ServicesCompTest(RTC::Manager* manager);
  ~ServicesCompTest() override;

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
  // </rtc-template>

  // InPorts: the sample last read, and the port
  // <rtc-template block="inport_declare">
  // </rtc-template>

  // OutPorts: the sample to write, and the port
  // <rtc-template block="outport_declare">
  // </rtc-template>

  // Service ports
  // <rtc-template block="corbaport_declare">
  RTC::CorbaPort m_MotorPortPort;
  RTC::CorbaPort m_PlannerPortPort;
  RTC::CorbaPort m_DevicePortPort;
  // </rtc-template>

  // Servants of the provided interfaces, one per interface
  // <rtc-template block="service_declare">
  MapperSVC_impl m_mapperRef;
  DeviceSVC_impl m_device;
  MotorSVC_impl m_driver;
  // </rtc-template>

  // The required interfaces: each holds the peer's reference once its port is connected
  // <rtc-template block="consumer_declare">
  RTC::CorbaConsumer<Robot::Control::Motor> m_motor;
  RTC::CorbaConsumer<Nav::Planner> m_plannerImpl;
  // </rtc-template>

 private:
  // <rtc-template block="private_attribute">
  // </rtc-template>

  // <rtc-template block="private_operation">
  // </rtc-template>
};

extern "C"
{
  DLL_EXPORT void ServicesCompTestInit(RTC::Manager* manager);
}

#endif // SERVICESCOMPTEST_H
