// -*- C++ -*-
// SampleServiceSVC_impl.h: servant classes for the interfaces of SampleService.idl.

#ifndef SAMPLESERVICESVC_IMPL_H
#define SAMPLESERVICESVC_IMPL_H

#include "SampleService.hh"

// Implements Sample::Echo; its operations are defined in SampleServiceSVC_impl.cpp.
class EchoSVC_impl
  : public virtual POA_Sample::Echo,
    public virtual PortableServer::RefCountServantBase
{
 public:
  EchoSVC_impl();
  ~EchoSVC_impl() override;

  // One member per IDL operation and attribute accessor
  // <rtc-template block="Echo_operations">
  // string version()
  char* version() override;
  // long gain()
  CORBA::Long gain() override;
  // void gain(in long value)
  void gain(CORBA::Long value) override;
  // void reset()
  void reset() override;
  // string say(in string message)
  char* say(const char* message) override;
  // boolean numbers(in short s, out long l, inout double d, in octet o, out char c)
  CORBA::Boolean numbers(CORBA::Short s, CORBA::Long_out l, CORBA::Double& d, CORBA::Octet o, CORBA::Char_out c) override;
  // Sample::Point move(in Sample::Point from, out Sample::Point to, inout Sample::Point via)
  Sample::Point move(const Sample::Point& from, Sample::Point_out to, Sample::Point& via) override;
  // Sample::Label tag(in Sample::Label item, out Sample::Label copy, inout Sample::Label edited)
  Sample::Label* tag(const Sample::Label& item, Sample::Label_out copy, Sample::Label& edited) override;
  // Sample::NameList names(in Sample::NameList filter, out Sample::PointList points, inout Sample::NameList edited)
  Sample::NameList* names(const Sample::NameList& filter, Sample::PointList_out points, Sample::NameList& edited) override;
  // Sample::Matrix rotate(in Sample::Matrix m, out Sample::Matrix inverse, inout Sample::Matrix scratch)
  Sample::Matrix_slice* rotate(const Sample::Matrix m, Sample::Matrix_out inverse, Sample::Matrix scratch) override;
  // Sample::Mode switchMode(in Sample::Mode next, out Sample::Mode previous, inout Sample::Mode current)
  Sample::Mode switchMode(Sample::Mode next, Sample::Mode_out previous, Sample::Mode& current) override;
  // any convert(in any value, out any result, inout any both)
  CORBA::Any* convert(const CORBA::Any& value, CORBA::Any_out result, CORBA::Any& both) override;
  // Sample::Clock exchange(in Sample::Clock other, out Sample::Clock mine, inout Sample::Clock shared)
  Sample::Clock_ptr exchange(Sample::Clock_ptr other, Sample::Clock_out mine, Sample::Clock_ptr& shared) override;
  // Sample::Count tally(in Sample::Count c, out Sample::Count total)
  Sample::Count tally(Sample::Count c, Sample::Count_out total) override;
  // RTC::TimedLong sample(in RTC::Time when, out RTC::TimedLong value)
  RTC::TimedLong sample(const RTC::Time& when, RTC::TimedLong_out value) override;
  // void notify(in string event)
  void notify(const char* event) override;
  // </rtc-template>
};

#endif // SAMPLESERVICESVC_IMPL_H
