// SPDX-License-Identifier: MIT
// InPort and OutPort with OpenRTM-aist-Python's methods.
#include "bindings.h"
#include "pyinport.h"
#include "pyoutport.h"

#include <memory>

namespace py = pybind11;

namespace RtPython {

namespace {

/**
 * OpenRTM-aist-Python's get_connector_profiles(): an RTC.ConnectorProfile for each connection of
 * @p port with its name, id and properties (each a CORBA.Any of the text it holds). The port
 * references are left out: Python components hold no references to ports.
 */
py::list connectorProfiles(Runtime::PortBase &port)
{
    std::unique_ptr<RTC::ConnectorProfileList> profiles;
    {
        py::gil_scoped_release released;
        profiles.reset(port.get_connector_profiles());
    }
    const py::object profileClass = py::module_::import("RTC").attr("ConnectorProfile");
    const py::object nameValue = py::module_::import("SDOPackage").attr("NameValue");
    const py::object corba = py::module_::import("omniORB.CORBA");
    const py::object stringType = corba.attr("TC_string");
    py::list result;
    for (CORBA::ULong i = 0; i < profiles->length(); ++i) {
        const RTC::ConnectorProfile &profile = (*profiles)[i];
        py::list properties;
        for (CORBA::ULong j = 0; j < profile.properties.length(); ++j) {
            const char *text = "";
            profile.properties[j].value >>= text;
            properties.append(nameValue(profile.properties[j].name.in(), corba.attr("Any")(stringType, text)));
        }
        result.append(profileClass(profile.name.in(), profile.connector_id.in(), py::list(), properties));
    }
    return result;
}

} // namespace

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
        .def("get_connector_profiles", [](PyInPort &port) { return connectorProfiles(port); })
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
        .def("get_connector_profiles", [](PyOutPort &port) { return connectorProfiles(port); })
        .def("addConnectorDataListener", &PyOutPort::addDataListener, py::arg("listener_type"), py::arg("listener"))
        .def("addConnectorListener", &PyOutPort::addConnectorListener, py::arg("listener_type"),
             py::arg("listener"));
}

} // namespace RtPython
