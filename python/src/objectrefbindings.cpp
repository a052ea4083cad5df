// SPDX-License-Identifier: MIT
// Object references of components and execution contexts as omniORBpy gives them, enough for a
// component to reach its execution context and activate itself, and for a program to tick an
// ExtTrigExecutionContext.
#include "bindings.h"
#include "pycomponent.h"
#include "pyexecutioncontextref.h"
#include "pyremotecall.h"
#include "pyrtobjectref.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace RtPython {

namespace {

using ComponentClass = py::class_<PyComponent, std::unique_ptr<PyComponent, py::nodelete>>;

PyRTObjectRef reference(PyComponent &component)
{
    RTC::RTObject_var object = component.getObjRef();
    return PyRTObjectRef(object.in());
}

/// The context known to @p component as @p ec_id; None when there is none.
py::object executionContext(PyComponent &component, RTC::UniqueId ec_id)
{
    RTC::ExecutionContext_var context;
    {
        py::gil_scoped_release released;
        context = component.getExecutionContext(ec_id);
    }
    return CORBA::is_nil(context) ? py::none() : py::cast(PyExecutionContextRef(context.in()));
}

/// A state change of the component itself (activate, deactivate, reset in context @p ec_id, exit):
/// made without the GIL, since the context runs the component's Python callbacks on the way.
template <RTC::ReturnCode_t (RTC::RTObject_impl::*change)(RTC::UniqueId)>
py::object changeState(PyComponent &component, RTC::UniqueId ec_id)
{
    RTC::ReturnCode_t code;
    {
        py::gil_scoped_release released;
        code = (component.*change)(ec_id);
    }
    return returnCode(code);
}

py::object exitComponent(PyComponent &component)
{
    RTC::ReturnCode_t code;
    {
        py::gil_scoped_release released;
        code = component.exit();
    }
    return returnCode(code);
}

void bindReferences(py::module_ &module)
{
    py::class_<PyRTObjectRef>(module, "RTObjectRef")
        .def("get_owned_contexts", &PyRTObjectRef::get_owned_contexts)
        .def("get_participating_contexts", &PyRTObjectRef::get_participating_contexts)
        .def("is_alive", &PyRTObjectRef::is_alive, py::arg("exec_context") = nullptr)
        .def("_narrow", [](py::object self, py::object) { return self; }, py::arg("interface"))
        .def("__repr__", [](PyRTObjectRef &self) { return "<RTC.RTObject " + self.instance_name() + ">"; });
    py::class_<PyExecutionContextRef>(module, "ExecutionContextRef")
        .def("activate_component", &PyExecutionContextRef::activate_component, py::arg("comp"))
        .def("deactivate_component", &PyExecutionContextRef::deactivate_component, py::arg("comp"))
        .def("reset_component", &PyExecutionContextRef::reset_component, py::arg("comp"))
        .def("get_component_state", &PyExecutionContextRef::get_component_state, py::arg("comp"))
        .def("start", &PyExecutionContextRef::start)
        .def("stop", &PyExecutionContextRef::stop)
        .def("is_running", &PyExecutionContextRef::is_running)
        .def("get_rate", &PyExecutionContextRef::get_rate)
        .def("set_rate", &PyExecutionContextRef::set_rate, py::arg("rate"))
        .def("tick", &PyExecutionContextRef::tick)
        .def("_narrow", [](py::object self, py::object) { return self; }, py::arg("interface"));
}

/// The component's own reference and contexts, on the bridge bound in pycomponent.cpp.
void bindComponentReferences(py::module_ &module)
{
    ComponentClass component = py::reinterpret_borrow<ComponentClass>(module.attr("Component"));
    component.def("getObjRef", &reference)
        .def_property_readonly("_objref", &reference)
        .def("get_owned_contexts", [](PyComponent &self) { return reference(self).get_owned_contexts(); })
        .def("get_participating_contexts",
             [](PyComponent &self) { return reference(self).get_participating_contexts(); })
        .def("getExecutionContext", &executionContext, py::arg("ec_id"))
        .def("get_context", &executionContext, py::arg("ec_id"))
        .def("activate", &changeState<&PyComponent::activate>, py::arg("ec_id"))
        .def("deactivate", &changeState<&PyComponent::deactivate>, py::arg("ec_id"))
        .def("reset", &changeState<&PyComponent::reset>, py::arg("ec_id"))
        .def("exit", &exitComponent);
}

} // namespace

void bindObjectReferences(py::module_ &module)
{
    bindReferences(module);
    bindComponentReferences(module);
}

} // namespace RtPython
