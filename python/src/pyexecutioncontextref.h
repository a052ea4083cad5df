// SPDX-License-Identifier: MIT
#pragma once

#include "pyrtobjectref.h"

#include <rtm/idl/RTCSkel.h>

#include <pybind11/pybind11.h>

namespace RtPython {

/**
 * An execution context's object reference as omniORBpy gives it (RTC.ExecutionContext, and
 * OpenRTM.ExtTrigExecutionContextService's tick()): what `get_owned_contexts()` returns, so that a
 * component activates itself as OpenRTM-aist-Python's examples do
 * (`ecs[0].activate_component(rtobj)`). Return codes and states are the RTC module's enum items.
 */
class PyExecutionContextRef
{
public:
    explicit PyExecutionContextRef(RTC::ExecutionContext_ptr context);

    RTC::ExecutionContext_ptr object() const { return m_context.in(); }

    pybind11::object activate_component(const PyRTObjectRef &component);
    pybind11::object deactivate_component(const PyRTObjectRef &component);
    pybind11::object reset_component(const PyRTObjectRef &component);
    pybind11::object get_component_state(const PyRTObjectRef &component);
    pybind11::object start();
    pybind11::object stop();
    bool is_running();
    double get_rate();
    pybind11::object set_rate(double rate);
    /// OpenRTM.ExtTrigExecutionContextService::tick(); a TypeError on another kind of context.
    void tick();

private:
    RTC::ExecutionContext_var m_context;
};

} // namespace RtPython
