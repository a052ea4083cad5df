// -*- C++ -*-
// RoboticsSVC_impl.h: servant classes for the interfaces of Robotics.idl.

#ifndef ROBOTICSSVC_IMPL_H
#define ROBOTICSSVC_IMPL_H

#include "Robotics.hh"

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

// Implements Nav::Planner; its operations are defined in RoboticsSVC_impl.cpp.
class PlannerSVC_impl
  : public virtual POA_Nav::Planner,
    public virtual PortableServer::RefCountServantBase
{
 public:
  PlannerSVC_impl();
  ~PlannerSVC_impl() override;

  // One member per IDL operation and attribute accessor
  // <rtc-template block="Planner_operations">
  // Robot::Control::Status state()
  Robot::Control::Status state() override;
  // Robot::Geometry::Path plan(in Robot::Geometry::Pose start, in Robot::Geometry::Pose goal, out Robot::Geometry::Weights costs)
  Robot::Geometry::Path* plan(const Robot::Geometry::Pose& start, const Robot::Geometry::Pose& goal, Robot::Geometry::Weights_out costs) override;
  // string name()
  char* name() override;
  // void configure(in string key, inout string value, out string previous)
  void configure(const char* key, char*& value, CORBA::String_out previous) override;
  // Robot::Geometry::Path replan(in Robot::Geometry::Path previous, inout Robot::Geometry::Vector3 offset, out unsigned long count)
  Robot::Geometry::Path* replan(const Robot::Geometry::Path& previous, Robot::Geometry::Vector3& offset, CORBA::ULong_out count) override;
  // Robot::Control::Motor driver(in Robot::Control::Status wanted)
  Robot::Control::Motor_ptr driver(Robot::Control::Status wanted) override;
  // void cancel(in string reason)
  void cancel(const char* reason) override;
  // </rtc-template>
};

#endif // ROBOTICSSVC_IMPL_H
