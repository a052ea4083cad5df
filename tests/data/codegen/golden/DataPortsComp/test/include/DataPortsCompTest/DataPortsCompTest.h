// -*- C++ -*-
// <rtc-template block="description">
/*!
 * @file DataPortsCompTest.h
 * @brief Data ports of many types
 */
// </rtc-template>

#ifndef DATAPORTSCOMPTEST_H
#define DATAPORTSCOMPTEST_H

#include <rtm/idl/BasicDataTypeSkel.h>
#include <rtm/idl/ExtendedDataTypesSkel.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>

// Servant classes of the provided interfaces
// <rtc-template block="service_impl_h">
// </rtc-template>

// IDL stubs for the data types and the required interfaces
// <rtc-template block="consumer_stub_h">
#include <rtm/idl/BasicDataTypeSkel.h>
#include <rtm/idl/ExtendedDataTypesSkel.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>
// </rtc-template>

#include <rtm/Manager.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>

/*!
 * @class DataPortsCompTest
 * @brief Data ports of many types
 */
class DataPortsCompTest
  : public RTC::DataFlowComponentBase
{
 public:
  explicit DataPortsCompTest(RTC::Manager* manager);
  ~DataPortsCompTest() override;

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
  RTC::ReturnCode_t onDeactivated(RTC::UniqueId ec_id) override;
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
  RTC::TimedWString m_out_wide;
  /*!
   */
  RTC::InPort<RTC::TimedWString> m_out_wideIn;
  RTC::TimedOctetSeq m_out_octets;
  /*!
   */
  RTC::InPort<RTC::TimedOctetSeq> m_out_octetsIn;
  RTC::TimedBooleanSeq m_out_flags;
  /*!
   */
  RTC::InPort<RTC::TimedBooleanSeq> m_out_flagsIn;
  RTC::TimedVector3D m_out_vector;
  /*!
   */
  RTC::InPort<RTC::TimedVector3D> m_out_vectorIn;
  RTC::RangeData m_ranges;
  /*!
   */
  RTC::InPort<RTC::RangeData> m_rangesIn;
  RTC::PointCloud m_out_cloud;
  /*!
   */
  RTC::InPort<RTC::PointCloud> m_out_cloudIn;
  // </rtc-template>

  // OutPorts: the sample to write, and the port
  // <rtc-template block="outport_declare">
  RTC::TimedLong m_in_long;
  /*!
   */
  RTC::OutPort<RTC::TimedLong> m_in_longOut;
  RTC::TimedDoubleSeq m_doubles;
  /*!
   */
  RTC::OutPort<RTC::TimedDoubleSeq> m_doublesOut;
  RTC::TimedString m_in_text;
  /*!
   */
  RTC::OutPort<RTC::TimedString> m_in_textOut;
  RTC::TimedPose2D m_in_pose;
  /*!
   */
  RTC::OutPort<RTC::TimedPose2D> m_in_poseOut;
  RTC::CameraImage m_image;
  /*!
   */
  RTC::OutPort<RTC::CameraImage> m_imageOut;
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
  DLL_EXPORT void DataPortsCompTestInit(RTC::Manager* manager);
}

#endif // DATAPORTSCOMPTEST_H
