// SPDX-License-Identifier: MIT
#include "sdkinternal.h"

namespace RTC::Sdk {

Runtime::Properties toRuntime(const coil::Properties &properties)
{
    Runtime::Properties result;
    for (const std::string &key : properties.propertyNames())
        result.set(key, properties.getProperty(key));
    return result;
}

coil::Properties toCoil(const Runtime::Properties &properties)
{
    coil::Properties result;
    for (const auto &[key, value] : properties.entries())
        result.setProperty(key, value);
    return result;
}

PortableServer::POA_ptr rootPoa()
{
    int argc = 0;
    CORBA::ORB_var orb = CORBA::ORB_init(argc, nullptr);
    CORBA::Object_var object = orb->resolve_initial_references("RootPOA");
    return PortableServer::POA::_narrow(object);
}

} // namespace RTC::Sdk
