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

/// OpenRTM-aist-Python's disconnect(connector_id): RTC.RTC_OK, or why not.
template <typename Port>
int disconnect(Port &port, const std::string &connectorId)
{
    return int(port.disconnect(connectorId.c_str()));
}

/// Makes @p port an end of CSP channels (OpenRTM_aist.CSPPort), of data type "any" when asked.
template <typename Port>
void setCspChannel(Port &port, bool anyDataType)
{
    port.setCspChannel();
    if (anyDataType)
        port.setProperty("dataport.data_type", "any");
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
             py::arg("listener"))
        .def("properties", [](PyInPort &port) -> coil::Properties & { return port.properties(); },
             py::return_value_policy::reference_internal)
        .def("disconnect", &disconnect<PyInPort>, py::arg("connector_id"), Release())
        .def("disconnect_all", [](PyInPort &port) { return int(port.disconnect_all()); }, Release())
        .def("_setCspChannel", &setCspChannel<PyInPort>, py::arg("any_data_type"));
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
             py::arg("listener"))
        .def("properties", [](PyOutPort &port) -> coil::Properties & { return port.properties(); },
             py::return_value_policy::reference_internal)
        .def("disconnect", &disconnect<PyOutPort>, py::arg("connector_id"), Release())
        .def("disconnect_all", [](PyOutPort &port) { return int(port.disconnect_all()); }, Release())
        .def("_setCspChannel", &setCspChannel<PyOutPort>, py::arg("any_data_type"));
}

} // namespace RtPython
