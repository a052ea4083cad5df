// SPDX-License-Identifier: MIT
// A program on the project's own IDL, through the wrapper header rtm-skelwrapper wrote beside
// omniidl's output: serves Relay::Gauge from a servant, calls it through its object reference, and
// sends the reading through a CORBA::Any, whose RTC::Time member's type comes from the SDK's library.
// Prints the reading.
#include "RelaySkel.h"
#include <rtm/version.h>

#include <iostream>
#include <string>

class GaugeImpl
  : public virtual POA_Relay::Gauge
{
public:
  Relay::TimedReading* read(const char* unit)
  {
    Relay::TimedReading* reading = new Relay::TimedReading;
    reading->tm.sec = 7;
    reading->tm.nsec = 0;
    reading->value = std::string(unit) == "mm" ? 1250.0 : 1.25;
    reading->unit = CORBA::string_dup(unit);
    return reading;
  }
};

int main(int argc, char** argv)
{
  CORBA::ORB_var orb = CORBA::ORB_init(argc, argv);
  CORBA::Object_var poaObject = orb->resolve_initial_references("RootPOA");
  PortableServer::POA_var poa = PortableServer::POA::_narrow(poaObject);
  PortableServer::POAManager_var poaManager = poa->the_POAManager();
  poaManager->activate();

  GaugeImpl* servant = new GaugeImpl;
  PortableServer::ObjectId_var id = poa->activate_object(servant);
  CORBA::Object_var object = poa->id_to_reference(id);
  Relay::Gauge_var gauge = Relay::Gauge::_narrow(object);
  if (CORBA::is_nil(gauge))
    return 1;
  Relay::TimedReading_var reading = gauge->read("mm");

  CORBA::Any any;
  any <<= reading.in();
  const Relay::TimedReading* back = 0;
  if (!(any >>= back))
    return 2;

  std::cout << "openrtp20 " << RTC::openrtm_version << " " << back->value << back->unit << " "
            << back->tm.sec << " " << any.type()->id() << std::endl;

  poa->deactivate_object(id);
  servant->_remove_ref();
  orb->destroy();
  return 0;
}
