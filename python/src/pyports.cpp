// SPDX-License-Identifier: MIT
#include "pyports.h"
#include "bindings.h"
#include "pydatatypes.h"
#include "pylisteners.h"

namespace py = pybind11;

namespace RtPython {

PyInPort::PyInPort(const std::string &name, py::object value)
    : InPortBase(name.c_str(), PyDataTypes::repositoryId(value).c_str())
    , m_value(std::move(value))
{
}

PyInPort::~PyInPort()
{
    releasePython(m_value);
}

bool PyInPort::read(std::string name)
{
    (void)name; // samples are not told apart by connection (as in the SDK's InPort with several)
    Runtime::SharedCdr bytes;
    bool little = true;
    {
        // A pull connection asks the other side here: other threads run Python meanwhile.
        py::gil_scoped_release released;
        if (!readBytes(&bytes, &little))
            return false;
    }
    m_value = PyDataTypes::instance().decode(dataType(), bytes->data(), bytes->size(), little);
    {
        py::gil_scoped_release released;
        m_listeners.notifyData(RTC::ConnectorDataListenerType::ON_BUFFER_READ, std::string(), bytes->data(),
                               static_cast<unsigned long>(bytes->size()), little);
    }
    return true;
}

py::object PyInPort::readValue()
{
    read();
    return m_value;
}

void PyInPort::addDataListener(RTC::ConnectorDataListenerType type, py::object listener)
{
    addConnectorDataListener(type, new PyDataListener(std::move(listener), dataType()));
}

void PyInPort::addConnectorListener(RTC::ConnectorListenerType type, py::object listener)
{
    RTC::InPortBase::addConnectorListener(type, new PyConnectorListener(std::move(listener)));
}

PyOutPort::PyOutPort(const std::string &name, py::object value)
    : OutPortBase(name.c_str(), PyDataTypes::repositoryId(value).c_str())
    , m_value(std::move(value))
{
}

PyOutPort::~PyOutPort()
{
    releasePython(m_value);
}

bool PyOutPort::write()
{
    py::gil_scoped_acquire gil;
    return writeValue(m_value);
}

bool PyOutPort::writeValue(py::object value)
{
    const PyDataTypes &types = PyDataTypes::instance();
    const py::object sample = value.is_none() ? m_value : value;
    const std::vector<unsigned char> little = types.encode(dataType(), sample, true);
    // Peers that asked for big-endian samples are rare; their bytes are made when first asked for.
    std::vector<unsigned char> big;
    auto marshal = [&](bool littleEndian) {
        if (!littleEndian && big.empty()) {
            py::gil_scoped_acquire gil;
            big = types.encode(dataType(), sample, false);
        }
        const std::vector<unsigned char> &bytes = littleEndian ? little : big;
        return Runtime::CdrView{bytes.data(), bytes.size()};
    };
    py::gil_scoped_release released;
    notifyWrite(nullptr, typeid(py::object), [&little] { return little; });
    writeBytes(marshal);
    return true;
}

void PyOutPort::addDataListener(RTC::ConnectorDataListenerType type, py::object listener)
{
    addConnectorDataListener(type, new PyDataListener(std::move(listener), dataType()));
}

void PyOutPort::addConnectorListener(RTC::ConnectorListenerType type, py::object listener)
{
    RTC::OutPortBase::addConnectorListener(type, new PyConnectorListener(std::move(listener)));
}

void bindPorts(py::module_ &module)
{
    py::class_<PyInPort>(module, "InPort")
        .def(py::init<const std::string &, py::object>(), py::arg("name"), py::arg("value"))
        .def("name", [](PyInPort &port) { return port.Runtime::PortBase::name(); })
        .def("isNew", [](PyInPort &port) { return port.isNew(); })
        .def("isEmpty", [](PyInPort &port) { return port.isEmpty(); })
        .def("read", &PyInPort::readValue)
        .def("addConnectorDataListener", &PyInPort::addDataListener, py::arg("listener_type"), py::arg("listener"))
        .def("addConnectorListener", &PyInPort::addConnectorListener, py::arg("listener_type"),
             py::arg("listener"));
    py::class_<PyOutPort>(module, "OutPort")
        .def(py::init<const std::string &, py::object>(), py::arg("name"), py::arg("value"))
        .def("name", [](PyOutPort &port) { return port.Runtime::PortBase::name(); })
        .def("write", &PyOutPort::writeValue, py::arg("value") = py::none())
        .def("addConnectorDataListener", &PyOutPort::addDataListener, py::arg("listener_type"), py::arg("listener"))
        .def("addConnectorListener", &PyOutPort::addConnectorListener, py::arg("listener_type"),
             py::arg("listener"));
}

} // namespace RtPython
