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

/**
 * What InPort and OutPort both have: name(), their connections' profiles and listeners, their
 * properties (rtc.conf's port settings), disconnect(connector_id) / disconnect_all() answering
 * RTC.RTC_OK or why not, and _setCspChannel(any_data_type), which makes the port an end of CSP
 * channels (OpenRTM_aist.CSPPort), of data type "any" when asked.
 */
template <typename Port>
void bindPortMethods(py::class_<Port> &port)
{
    using Release = py::call_guard<py::gil_scoped_release>;
    port.def("name", [](Port &p) { return p.Runtime::PortBase::name(); })
        .def("get_connector_profiles", [](Port &p) { return connectorProfiles(p); })
        .def("addConnectorDataListener", &Port::addDataListener, py::arg("listener_type"), py::arg("listener"))
        .def("addConnectorListener", &Port::addConnectorListener, py::arg("listener_type"), py::arg("listener"))
        .def("properties", [](Port &p) -> coil::Properties & { return p.properties(); },
             py::return_value_policy::reference_internal)
        .def("disconnect", [](Port &p, const std::string &id) { return int(p.disconnect(id.c_str())); },
             py::arg("connector_id"), Release())
        .def("disconnect_all", [](Port &p) { return int(p.disconnect_all()); }, Release())
        .def("_setCspChannel", [](Port &p, bool anyDataType) {
            p.setCspChannel();
            if (anyDataType)
                p.setProperty("dataport.data_type", "any");
        }, py::arg("any_data_type"));
}

} // namespace

void bindPorts(py::module_ &module)
{
    // The ports' locks are also taken by the ORB's threads, which may wait for the GIL to call
    // listeners: nothing waits for a lock while holding the GIL.
    using Release = py::call_guard<py::gil_scoped_release>;
    // The buffer OpenRTM-aist-Python's constructors take is not the connections' buffer there either:
    // each connection makes its own from the connector's properties (buffer.length, …).
    py::class_<PyInPort> inPort(module, "InPort");
    inPort.def(py::init([](const std::string &name, py::object value, const py::object &) {
                   return new PyInPort(name, std::move(value));
               }),
               py::arg("name"), py::arg("value"), py::arg("buffer") = py::none())
        .def("isNew", [](PyInPort &port) { return port.isNew(); }, Release())
        .def("isEmpty", [](PyInPort &port) { return port.isEmpty(); }, Release())
        .def("read", &PyInPort::readValue);
    bindPortMethods(inPort);
    py::class_<PyOutPort> outPort(module, "OutPort");
    outPort.def(py::init([](const std::string &name, py::object value, const py::object &) {
                    return new PyOutPort(name, std::move(value));
                }),
                py::arg("name"), py::arg("value"), py::arg("buffer") = py::none())
        .def("write", &PyOutPort::writeValue, py::arg("value") = py::none());
    bindPortMethods(outPort);
}

} // namespace RtPython
