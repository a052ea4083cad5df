// -*- C++ -*-
// RoboticsSVC_impl.h: servant classes for the interfaces of Robotics.idl.

#ifndef ROBOTICSSVC_IMPL_H
#define ROBOTICSSVC_IMPL_H

#include "Robotics.hh"

// Implements Robot::Geometry::Mapper; its operations are defined in RoboticsSVC_impl.cpp.
class MapperSVC_impl
  : public virtual POA_Robot::Geometry::Mapper,
    public virtual PortableServer::RefCountServantBase
{
 public:
  MapperSVC_impl();
  ~MapperSVC_impl() override;

  // One member per IDL operation and attribute accessor
  // <rtc-template block="Mapper_operations">
  // Robot::Geometry::Path plan(in Robot::Geometry::Pose start, in Robot::Geometry::Pose goal, out Robot::Geometry::Weights costs)
  Robot::Geometry::Path* plan(const Robot::Geometry::Pose& start, const Robot::Geometry::Pose& goal, Robot::Geometry::Weights_out costs) override;
  // </rtc-template>
};

// Implements Robot::Control::Device; its operations are defined in RoboticsSVC_impl.cpp.
class DeviceSVC_impl
  : public virtual POA_Robot::Control::Device,
    public virtual PortableServer::RefCountServantBase
{
 public:
  DeviceSVC_impl();
  ~DeviceSVC_impl() override;

  // One member per IDL operation and attribute accessor
  // <rtc-template block="Device_operations">
  // Robot::Control::Status state()
  Robot::Control::Status state() override;
  // string name()
  char* name() override;
  // void configure(in string key, inout string value, out string previous)
  void configure(const char* key, char*& value, CORBA::String_out previous) override;
  // </rtc-template>
};

// Implements Robot::Control::Motor; its operations are defined in RoboticsSVC_impl.cpp.
class MotorSVC_impl
  : public virtual POA_Robot::Control::Motor,
    public virtual PortableServer::RefCountServantBase
{
 public:
  MotorSVC_impl();
  ~MotorSVC_impl() override;

  // One member per IDL operation and attribute accessor
  // <rtc-template block="Motor_operations">
  // Robot::Control::Status state()
  Robot::Control::Status state() override;
  // double speed()
  CORBA::Double speed() override;
  // void speed(in double value)
  void speed(CORBA::Double value) override;
  // string name()
  char* name() override;
  // void configure(in string key, inout string value, out string previous)
  void configure(const char* key, char*& value, CORBA::String_out previous) override;
  // boolean move(in Robot::Geometry::Pose target, out Robot::Geometry::Pose reached, inout Robot::Geometry::Weights gains)
  CORBA::Boolean move(const Robot::Geometry::Pose& target, Robot::Geometry::Pose_out reached, Robot::Geometry::Weights& gains) override;
  // Robot::Geometry::PoseList trajectory(in Robot::Geometry::Path path, out Robot::Geometry::Path smoothed, inout Robot::Geometry::PoseList buffer)
  Robot::Geometry::PoseList* trajectory(const Robot::Geometry::Path& path, Robot::Geometry::Path_out smoothed, Robot::Geometry::PoseList& buffer) override;
  // void report(out Robot::Control::Status code, out string text, inout Robot::Geometry::Vector3 drift)
  void report(Robot::Control::Status_out code, CORBA::String_out text, Robot::Geometry::Vector3& drift) override;
  // RTC::TimedDoubleSeq sample(in RTC::Time at, out RTC::TimedString label)
  RTC::TimedDoubleSeq* sample(const RTC::Time& at, RTC::TimedString_out label) override;
  // </rtc-template>
};

#endif // ROBOTICSSVC_IMPL_H
