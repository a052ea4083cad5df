// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/idl/RTCSkel.h>

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

namespace RtPython {

/**
 * Runs @p call (a call on a CORBA object) without the GIL, so that the servant it reaches — often a
 * Python component of this very process — can take it; a CORBA exception becomes a Python
 * RuntimeError naming it, as omniORBpy raises CORBA exceptions.
 */
template <typename Call>
auto remoteCall(const char *operation, Call &&call) -> decltype(call())
{
    pybind11::gil_scoped_release released;
    try {
        return call();
    } catch (const CORBA::Exception &error) {
        throw std::runtime_error(std::string(operation) + ": " + error._name());
    }
}

/// The item of RTC.ReturnCode_t for @p code (RTC.RTC_OK, …), as omniORBpy returns it. Needs the GIL.
pybind11::object returnCode(RTC::ReturnCode_t code);

} // namespace RtPython
