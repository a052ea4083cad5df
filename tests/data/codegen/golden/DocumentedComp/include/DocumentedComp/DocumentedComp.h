// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file DocumentedComp.h
 * @brief A component with every documentation field
 */
// </rtc-template>

#ifndef DOCUMENTEDCOMP_H
#define DOCUMENTEDCOMP_H

#include <rtm/idl/BasicDataTypeSkel.h>
#include <rtm/idl/ExtendedDataTypesSkel.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>

// Servant classes of the provided interfaces
// <rtc-template block="service_impl_h">
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
 * @class DocumentedComp
 * @brief A component with every documentation field
 *
 * Long description: a fully documented sensor front end
 *
 * In/Out: One command in, one status out
 *
 * Algorithm: Reads the command, updates the state machine, writes the status
 *
 * Reference: OpenRTM-aist manual, chapter 3
 */
class DocumentedComp
  : public RTC::DataFlowComponentBase
{
 public:
  explicit DocumentedComp(RTC::Manager* manager);
  ~DocumentedComp() override;

  // <rtc-template block="public_attribute">
  // </rtc-template>

  // <rtc-template block="public_operation">
  // </rtc-template>

  // Callbacks: the ones switched off in the profile stay commented out.
  // <rtc-template block="activity_declare">
  // @pre: OnInitialize precondition
  // @post: OnInitialize postcondition
  RTC::ReturnCode_t onInitialize() override;
  // @pre: OnFinalize precondition
  // @post: OnFinalize postcondition
  RTC::ReturnCode_t onFinalize() override;
  // @pre: OnStartup precondition
  // @post: OnStartup postcondition
  RTC::ReturnCode_t onStartup(RTC::UniqueId ec_id) override;
  // @pre: OnShutdown precondition
  // @post: OnShutdown postcondition
  RTC::ReturnCode_t onShutdown(RTC::UniqueId ec_id) override;
  // @pre: OnActivated precondition
  // @post: OnActivated postcondition
  RTC::ReturnCode_t onActivated(RTC::UniqueId ec_id) override;
  // @pre: OnDeactivated precondition
  // @post: OnDeactivated postcondition
  RTC::ReturnCode_t onDeactivated(RTC::UniqueId ec_id) override;
  // @pre: OnAborting precondition
  // @post: OnAborting postcondition
  RTC::ReturnCode_t onAborting(RTC::UniqueId ec_id) override;
  // @pre: OnError precondition
  // @post: OnError postcondition
  RTC::ReturnCode_t onError(RTC::UniqueId ec_id) override;
  // @pre: OnReset precondition
  // @post: OnReset postcondition
  RTC::ReturnCode_t onReset(RTC::UniqueId ec_id) override;
  // @pre: OnExecute precondition
  // @post: OnExecute postcondition
  RTC::ReturnCode_t onExecute(RTC::UniqueId ec_id) override;
  // @pre: OnStateUpdate precondition
  // @post: OnStateUpdate postcondition
  RTC::ReturnCode_t onStateUpdate(RTC::UniqueId ec_id) override;
  // @pre: OnRateChanged precondition
  // @post: OnRateChanged postcondition
  RTC::ReturnCode_t onRateChanged(RTC::UniqueId ec_id) override;
  // </rtc-template>

 protected:
  // <rtc-template block="protected_attribute">
  // </rtc-template>

  // <rtc-template block="protected_operation">
  // </rtc-template>

  // Configuration parameters, bound in onInitialize()
  // <rtc-template block="config_declare">
  /*!
   * Sampling period of the sensor
   * - Name: period
   * - Default: 0.1
   * - Unit: s
   * - Range: 0.01-1.0
   * - Constraint: 0.01<=x<=1.0
   */
  double m_period;
  // </rtc-template>

  // InPorts: the sample last read, and the port
  // <rtc-template block="inport_declare">
  RTC::TimedLong m_command;
  /*!
   * Commands from the operator
   * - Type: long
   * - Number: 1
   * - Semantics: Command code to execute
   * - Unit: count
   * - Frequency: 10 Hz
   * - Operation Cycle: on demand
   */
  RTC::InPort<RTC::TimedLong> m_commandIn;
  // </rtc-template>

  // OutPorts: the sample to write, and the port
  // <rtc-template block="outport_declare">
  RTC::TimedString m_status;
  /*!
   * Current status text
   * - Type: string
   * - Number: 1
   * - Semantics: Human readable state
   * - Unit: none
   * - Frequency: 100 Hz
   * - Operation Cycle: every cycle
   */
  RTC::OutPort<RTC::TimedString> m_statusOut;
  // </rtc-template>

  // Service ports
  // <rtc-template block="corbaport_declare">
  // Port to read the time from
  // Interface: Clock interface
  RTC::CorbaPort m_ClockPortPort;
  // </rtc-template>

  // Servants of the provided interfaces, one per interface
  // <rtc-template block="service_declare">
  // </rtc-template>

  // The required interfaces: each holds the peer's reference once its port is connected
  // <rtc-template block="consumer_declare">
  // Time source of the component
  // - Argument: none
  // - Return: Nanoseconds since start
  // - Exception: none
  // - PreCondition: The clock runs
  // - PostCondition: Time is monotonic
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
  DLL_EXPORT void DocumentedCompInit(RTC::Manager* manager);
}

#endif // DOCUMENTEDCOMP_H
