// SPDX-License-Identifier: MIT
// InPort and OutPort with OpenRTM-aist-Python's methods.
#include "bindings.h"
#include "pyinport.h"
#include "pyoutport.h"

namespace py = pybind11;

namespace RtPython {

void bindPorts(py::module_ &module)
{
    // The ports' locks are also taken by the ORB's threads, which may wait for the GIL to call
    // listeners: nothing waits for a lock while holding the GIL.
    using Release = py::call_guard<py::gil_scoped_release>;
    // The buffer OpenRTM-aist-Python's constructors take is not the connections' buffer there either:
    // each connection makes its own from the connector's properties (buffer.length, …).
    py::class_<PyInPort>(module, "InPort")
        .def(py::init([](const std::string &name, py::object value, const py::object &) {
                 return new PyInPort(name, std::move(value));
             }),
             py::arg("name"), py::arg("value"), py::arg("buffer") = py::none())
        .def("name", [](PyInPort &port) { return port.Runtime::PortBase::name(); })
        .def("isNew", [](PyInPort &port) { return port.isNew(); }, Release())
        .def("isEmpty", [](PyInPort &port) { return port.isEmpty(); }, Release())
        .def("read", &PyInPort::readValue)
        .def("addConnectorDataListener", &PyInPort::addDataListener, py::arg("listener_type"), py::arg("listener"))
        .def("addConnectorListener", &PyInPort::addConnectorListener, py::arg("listener_type"),
             py::arg("listener"));
    py::class_<PyOutPort>(module, "OutPort")
        .def(py::init([](const std::string &name, py::object value, const py::object &) {
                 return new PyOutPort(name, std::move(value));
             }),
             py::arg("name"), py::arg("value"), py::arg("buffer") = py::none())
        .def("name", [](PyOutPort &port) { return port.Runtime::PortBase::name(); })
        .def("write", &PyOutPort::writeValue, py::arg("value") = py::none())
        .def("addConnectorDataListener", &PyOutPort::addDataListener, py::arg("listener_type"), py::arg("listener"))
        .def("addConnectorListener", &PyOutPort::addConnectorListener, py::arg("listener_type"),
             py::arg("listener"));
}

} // namespace RtPython
