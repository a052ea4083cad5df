// SPDX-License-Identifier: MIT
#include "pyexecutioncontextref.h"
#include "pyremotecall.h"

#include <rtm/idl/OpenRTMSkel.h>

namespace py = pybind11;

namespace RtPython {

namespace {

/// The item of IDL enum @p enumName of module RTC with value @p value (RTC.RTC_OK, RTC.ACTIVE_STATE, …).
py::object rtcEnumItem(const char *enumName, int value)
{
    return py::module_::import("RTC").attr(enumName).attr("_item")(value);
}

} // namespace

py::object returnCode(RTC::ReturnCode_t code)
{
    return rtcEnumItem("ReturnCode_t", int(code));
}

PyExecutionContextRef::PyExecutionContextRef(RTC::ExecutionContext_ptr context)
    : m_context(RTC::ExecutionContext::_duplicate(context))
{
}

py::object PyExecutionContextRef::activate_component(const PyRTObjectRef &component)
{
    RTC::RTObject_ptr object = component.object();
    return returnCode(remoteCall("activate_component", [this, object] { return m_context->activate_component(object); }));
}

py::object PyExecutionContextRef::deactivate_component(const PyRTObjectRef &component)
{
    RTC::RTObject_ptr object = component.object();
    return returnCode(
        remoteCall("deactivate_component", [this, object] { return m_context->deactivate_component(object); }));
}

py::object PyExecutionContextRef::reset_component(const PyRTObjectRef &component)
{
    RTC::RTObject_ptr object = component.object();
    return returnCode(remoteCall("reset_component", [this, object] { return m_context->reset_component(object); }));
}

py::object PyExecutionContextRef::get_component_state(const PyRTObjectRef &component)
{
    RTC::RTObject_ptr object = component.object();
    const RTC::LifeCycleState state =
        remoteCall("get_component_state", [this, object] { return m_context->get_component_state(object); });
    return rtcEnumItem("LifeCycleState", int(state));
}

py::object PyExecutionContextRef::start()
{
    return returnCode(remoteCall("start", [this] { return m_context->start(); }));
}

py::object PyExecutionContextRef::stop()
{
    return returnCode(remoteCall("stop", [this] { return m_context->stop(); }));
}

bool PyExecutionContextRef::is_running()
{
    return remoteCall("is_running", [this] { return bool(m_context->is_running()); });
}

double PyExecutionContextRef::get_rate()
{
    return remoteCall("get_rate", [this] { return double(m_context->get_rate()); });
}

py::object PyExecutionContextRef::set_rate(double rate)
{
    return returnCode(remoteCall("set_rate", [this, rate] { return m_context->set_rate(rate); }));
}

void PyExecutionContextRef::tick()
{
    OpenRTM::ExtTrigExecutionContextService_var triggered =
        remoteCall("tick", [this] { return OpenRTM::ExtTrigExecutionContextService::_narrow(m_context.in()); });
    if (CORBA::is_nil(triggered))
        throw py::type_error("tick: the execution context is not triggered externally (ExtTrigExecutionContext)");
    remoteCall("tick", [&triggered] { triggered->tick(); });
}

} // namespace RtPython
