// SPDX-License-Identifier: MIT
#include "pycorbaport.h"
#include "bindings.h"
#include "pyinterpreter.h"
#include "pyobjectref.h"
#include "pyservant.h"

namespace py = pybind11;

namespace RtPython {

py::object PyConsumerSlot::reference()
{
    CORBA::Object_ptr object = getObject();
    if (CORBA::is_nil(object))
        return py::none();
    return py::cast(PyObjectRef(object));
}

PyCorbaPort::PyCorbaPort(const std::string &name)
    : RTC::CorbaPort(name.c_str())
{ }

PyCorbaPort::~PyCorbaPort()
{
    // The port's own references go with the base class; these are the ones made here.
    for (PyServant *servant : m_servants)
        servant->_remove_ref();
    for (py::object &slot : m_slots)
        releasePython(slot);
}

bool PyCorbaPort::registerPythonProvider(const std::string &instanceName,
                                         const std::string &typeName, py::object servant)
{
    if (!py::hasattr(servant, "_NP_RepositoryId"))
        throw py::type_error(
            "registerProvider: the provider must be a servant of a generated <Module>__POA class");
    auto *bridge = new PyServant(std::move(servant));
    if (!registerProvider(instanceName.c_str(), typeName.c_str(), *bridge)) {
        bridge->_remove_ref();
        return false;
    }
    m_servants.push_back(bridge);
    return true;
}

bool PyCorbaPort::registerPythonConsumer(const std::string &instanceName,
                                         const std::string &typeName, py::object slot)
{
    auto &consumer = slot.cast<PyConsumerSlot &>();
    m_slots.push_back(std::move(slot));
    return registerConsumer(instanceName.c_str(), typeName.c_str(), consumer);
}

void bindServicePorts(py::module_ &module)
{
    py::class_<PyConsumerSlot>(module, "ConsumerSlot")
        .def(py::init<>())
        .def("reference", &PyConsumerSlot::reference)
        .def("releaseObject", &PyConsumerSlot::releaseObject);
    py::class_<PyCorbaPort>(module, "CorbaPort")
        .def(py::init<const std::string &>(), py::arg("name"))
        .def("name", [](PyCorbaPort &port) { return port.Runtime::PortBase::name(); })
        .def("registerProvider", &PyCorbaPort::registerPythonProvider, py::arg("instance_name"),
             py::arg("type_name"), py::arg("provider"))
        .def("_registerConsumerSlot", &PyCorbaPort::registerPythonConsumer,
             py::arg("instance_name"), py::arg("type_name"), py::arg("slot"));
}

} // namespace RtPython
