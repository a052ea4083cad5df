// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/idl/RTCSkel.h>

#include <pybind11/pybind11.h>

#include <vector>

namespace RtPython {

class PyExecutionContextRef;

/**
 * A component's object reference as omniORBpy gives it (RTC.RTObject): what
 * `servant_to_reference(comp)`, `getObjRef()` and `self._objref` return. It carries the calls
 * OpenRTM-aist-Python's examples make on it; `_narrow(RTC.RTObject)` returns it as it is.
 */
class PyRTObjectRef
{
public:
    explicit PyRTObjectRef(RTC::RTObject_ptr object);

    RTC::RTObject_ptr object() const { return m_object.in(); }
    std::vector<PyExecutionContextRef> get_owned_contexts();
    std::vector<PyExecutionContextRef> get_participating_contexts();
    bool is_alive(const PyExecutionContextRef *context);
    std::string instance_name();

private:
    RTC::RTObject_var m_object;
};

} // namespace RtPython
