// SPDX-License-Identifier: MIT
// OpenRTM_aist.Properties: coil::Properties with OpenRTM-aist-Python's constructor and printing.
#include "bindings.h"

#include <coil/Properties.h>

#include <pybind11/stl.h>

#include <sstream>

namespace py = pybind11;

namespace RtPython {

namespace {

/// OpenRTM-aist-Python's keywords: key/value, defaults_map (dict), defaults_str (a flat list of
/// key, value, …, ended by ""), prop (a Properties to copy).
std::unique_ptr<coil::Properties> makeProperties(py::kwargs arguments)
{
    auto properties = std::make_unique<coil::Properties>();
    if (arguments.contains("prop"))
        *properties = arguments["prop"].cast<const coil::Properties &>();
    if (arguments.contains("key"))
        properties->setProperty(arguments["key"].cast<std::string>(),
                                arguments.contains("value") ? arguments["value"].cast<std::string>() : "");
    if (arguments.contains("defaults_map")) {
        for (const auto &[key, value] : arguments["defaults_map"].cast<py::dict>())
            properties->setDefault(py::str(key), py::str(value));
    }
    if (arguments.contains("defaults_str")) {
        const std::vector<std::string> pairs = arguments["defaults_str"].cast<std::vector<std::string>>();
        for (size_t i = 0; i + 1 < pairs.size() && !pairs[i].empty(); i += 2)
            properties->setDefault(pairs[i], pairs[i + 1]);
    }
    return properties;
}

std::string dump(const coil::Properties &properties)
{
    std::ostringstream text;
    text << properties;
    return text.str();
}

} // namespace

void bindProperties(py::module_ &module)
{
    py::class_<coil::Properties>(module, "Properties")
        .def(py::init(&makeProperties))
        .def("getProperty", [](const coil::Properties &p, const std::string &key, py::object fallback) {
            return fallback.is_none() ? p.getProperty(key) : p.getProperty(key, py::str(fallback));
        }, py::arg("key"), py::arg("default") = py::none())
        .def("setProperty", &coil::Properties::setProperty, py::arg("key"), py::arg("value"))
        .def("getDefault", &coil::Properties::getDefault, py::arg("key"))
        .def("setDefault", &coil::Properties::setDefault, py::arg("key"), py::arg("value"))
        .def("getName", &coil::Properties::getName)
        .def("getValue", &coil::Properties::getValue)
        .def("propertyNames", &coil::Properties::propertyNames)
        .def("size", &coil::Properties::size)
        .def("getNode", &coil::Properties::getNode, py::arg("key"), py::return_value_policy::reference_internal)
        .def("hasKey", [](const coil::Properties &p, const std::string &key) { return p.findNode(key) != nullptr; })
        .def("__str__", &dump);
}

} // namespace RtPython
