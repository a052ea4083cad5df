// SPDX-License-Identifier: MIT
#include "pyoutport.h"
#include "pyconnectorlistener.h"
#include "pydatalistener.h"
#include "pydatatypes.h"
#include "pyinterpreter.h"

namespace py = pybind11;

namespace RtPython {

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
    addConnectorDataListener(type, new PyDataListener(std::move(listener), dataType(), "outport"));
}

void PyOutPort::addConnectorListener(RTC::ConnectorListenerType type, py::object listener)
{
    RTC::OutPortBase::addConnectorListener(type, new PyConnectorListener(std::move(listener)));
}

} // namespace RtPython
