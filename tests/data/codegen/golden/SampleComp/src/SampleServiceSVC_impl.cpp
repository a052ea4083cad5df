// -*- C++ -*-
// SampleServiceSVC_impl.cpp: the servants of SampleService.idl; write each operation's body
// where it says TODO.

#include "SampleServiceSVC_impl.h"

// Sample::Echo
EchoSVC_impl::EchoSVC_impl()
{
}

EchoSVC_impl::~EchoSVC_impl()
{
}

// string version()
char* EchoSVC_impl::version()
{
  // TODO: implement version
  return CORBA::string_dup("");
}

// long gain()
CORBA::Long EchoSVC_impl::gain()
{
  // TODO: implement gain
  return 0;
}

// void gain(in long value)
void EchoSVC_impl::gain(CORBA::Long value)
{
  // TODO: implement gain
}

// void reset()
void EchoSVC_impl::reset()
{
  // TODO: implement reset
}

// string say(in string message)
char* EchoSVC_impl::say(const char* message)
{
  // TODO: implement say
  return CORBA::string_dup("");
}

// boolean numbers(in short s, out long l, inout double d, in octet o, out char c)
CORBA::Boolean EchoSVC_impl::numbers(CORBA::Short s, CORBA::Long_out l, CORBA::Double& d, CORBA::Octet o, CORBA::Char_out c)
{
  // TODO: implement numbers
  return false;
}

// Sample::Point move(in Sample::Point from, out Sample::Point to, inout Sample::Point via)
Sample::Point EchoSVC_impl::move(const Sample::Point& from, Sample::Point_out to, Sample::Point& via)
{
  // TODO: implement move
  return Sample::Point();
}

// Sample::Label tag(in Sample::Label item, out Sample::Label copy, inout Sample::Label edited)
Sample::Label* EchoSVC_impl::tag(const Sample::Label& item, Sample::Label_out copy, Sample::Label& edited)
{
  // TODO: implement tag
  return new Sample::Label();
}

// Sample::NameList names(in Sample::NameList filter, out Sample::PointList points, inout Sample::NameList edited)
Sample::NameList* EchoSVC_impl::names(const Sample::NameList& filter, Sample::PointList_out points, Sample::NameList& edited)
{
  // TODO: implement names
  return new Sample::NameList();
}

// Sample::Matrix rotate(in Sample::Matrix m, out Sample::Matrix inverse, inout Sample::Matrix scratch)
Sample::Matrix_slice* EchoSVC_impl::rotate(const Sample::Matrix m, Sample::Matrix_out inverse, Sample::Matrix scratch)
{
  // TODO: implement rotate
  return Sample::Matrix_alloc();
}

// Sample::Mode switchMode(in Sample::Mode next, out Sample::Mode previous, inout Sample::Mode current)
Sample::Mode EchoSVC_impl::switchMode(Sample::Mode next, Sample::Mode_out previous, Sample::Mode& current)
{
  // TODO: implement switchMode
  return Sample::IDLE;
}

// any convert(in any value, out any result, inout any both)
CORBA::Any* EchoSVC_impl::convert(const CORBA::Any& value, CORBA::Any_out result, CORBA::Any& both)
{
  // TODO: implement convert
  return new CORBA::Any();
}

// Sample::Clock exchange(in Sample::Clock other, out Sample::Clock mine, inout Sample::Clock shared)
Sample::Clock_ptr EchoSVC_impl::exchange(Sample::Clock_ptr other, Sample::Clock_out mine, Sample::Clock_ptr& shared)
{
  // TODO: implement exchange
  return Sample::Clock::_nil();
}

// Sample::Count tally(in Sample::Count c, out Sample::Count total)
Sample::Count EchoSVC_impl::tally(Sample::Count c, Sample::Count_out total)
{
  // TODO: implement tally
  return 0;
}

// RTC::TimedLong sample(in RTC::Time when, out RTC::TimedLong value)
RTC::TimedLong EchoSVC_impl::sample(const RTC::Time& when, RTC::TimedLong_out value)
{
  // TODO: implement sample
  return RTC::TimedLong();
}

// void notify(in string event)
void EchoSVC_impl::notify(const char* event)
{
  // TODO: implement notify
}

