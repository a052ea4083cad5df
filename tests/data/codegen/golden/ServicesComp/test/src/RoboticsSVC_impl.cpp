// -*- C++ -*-
// RoboticsSVC_impl.cpp: the servants of Robotics.idl; write each operation's body
// where it says TODO.

#include "RoboticsSVC_impl.h"

// Robot::Geometry::Mapper
MapperSVC_impl::MapperSVC_impl()
{
}

MapperSVC_impl::~MapperSVC_impl()
{
}

// Robot::Geometry::Path plan(in Robot::Geometry::Pose start, in Robot::Geometry::Pose goal, out Robot::Geometry::Weights costs)
Robot::Geometry::Path* MapperSVC_impl::plan(const Robot::Geometry::Pose& start, const Robot::Geometry::Pose& goal, Robot::Geometry::Weights_out costs)
{
  // TODO: implement plan
  return new Robot::Geometry::Path();
}

// Robot::Control::Device
DeviceSVC_impl::DeviceSVC_impl()
{
}

DeviceSVC_impl::~DeviceSVC_impl()
{
}

// Robot::Control::Status state()
Robot::Control::Status DeviceSVC_impl::state()
{
  // TODO: implement state
  return Robot::Control::OK;
}

// string name()
char* DeviceSVC_impl::name()
{
  // TODO: implement name
  return CORBA::string_dup("");
}

// void configure(in string key, inout string value, out string previous)
void DeviceSVC_impl::configure(const char* key, char*& value, CORBA::String_out previous)
{
  // TODO: implement configure
}

// Robot::Control::Motor
MotorSVC_impl::MotorSVC_impl()
{
}

MotorSVC_impl::~MotorSVC_impl()
{
}

// Robot::Control::Status state()
Robot::Control::Status MotorSVC_impl::state()
{
  // TODO: implement state
  return Robot::Control::OK;
}

// double speed()
CORBA::Double MotorSVC_impl::speed()
{
  // TODO: implement speed
  return 0;
}

// void speed(in double value)
void MotorSVC_impl::speed(CORBA::Double value)
{
  // TODO: implement speed
}

// string name()
char* MotorSVC_impl::name()
{
  // TODO: implement name
  return CORBA::string_dup("");
}

// void configure(in string key, inout string value, out string previous)
void MotorSVC_impl::configure(const char* key, char*& value, CORBA::String_out previous)
{
  // TODO: implement configure
}

// boolean move(in Robot::Geometry::Pose target, out Robot::Geometry::Pose reached, inout Robot::Geometry::Weights gains)
CORBA::Boolean MotorSVC_impl::move(const Robot::Geometry::Pose& target, Robot::Geometry::Pose_out reached, Robot::Geometry::Weights& gains)
{
  // TODO: implement move
  return false;
}

// Robot::Geometry::PoseList trajectory(in Robot::Geometry::Path path, out Robot::Geometry::Path smoothed, inout Robot::Geometry::PoseList buffer)
Robot::Geometry::PoseList* MotorSVC_impl::trajectory(const Robot::Geometry::Path& path, Robot::Geometry::Path_out smoothed, Robot::Geometry::PoseList& buffer)
{
  // TODO: implement trajectory
  return new Robot::Geometry::PoseList();
}

// void report(out Robot::Control::Status code, out string text, inout Robot::Geometry::Vector3 drift)
void MotorSVC_impl::report(Robot::Control::Status_out code, CORBA::String_out text, Robot::Geometry::Vector3& drift)
{
  // TODO: implement report
}

// RTC::TimedDoubleSeq sample(in RTC::Time at, out RTC::TimedString label)
RTC::TimedDoubleSeq* MotorSVC_impl::sample(const RTC::Time& at, RTC::TimedString_out label)
{
  // TODO: implement sample
  return new RTC::TimedDoubleSeq();
}

