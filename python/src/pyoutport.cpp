// SPDX-License-Identifier: MIT
#include "pyoutport.h"
#include "pyconnectorlistener.h"
#include "pydatalistener.h"
#include "pydatatypes.h"
#include "pyinterpreter.h"
#include "pyserializers.h"

#include <map>
#include <utility>

namespace py = pybind11;

namespace RtPython {

PyOutPort::PyOutPort(const std::string &name, py::object value)
    : OutPortBase(name.c_str(), PyDataTypes::repositoryId(value).c_str())
    , m_value(std::move(value))
{
    setUserSerializers(true);
}

PyOutPort::~PyOutPort()
{
    releasePython(m_value);
}

bool PyOutPort::write()
{
    Gil gil;
    return writeValue(m_value);
}

bool PyOutPort::writeValue(py::object value)
{
    const PyDataTypes &types = PyDataTypes::instance();
    const py::object sample = value.is_none() ? m_value : value;
    const std::vector<unsigned char> little = types.encode(dataType(), sample, true);
    // Other byte orders and user serializers' bytes (`outport.marshaling_type`) are made when a
    // connection first asks for them; a serializer that fails is reported and fails its connections.
    std::map<std::pair<bool, std::string>, std::vector<unsigned char>> others;
    auto marshal = [&](bool littleEndian, const std::string &marshaling) {
        if (littleEndian && marshaling == "cdr")
            return Runtime::CdrView{little.data(), little.size()};
        auto &bytes = others[{littleEndian, marshaling}];
        if (bytes.empty()) {
            Gil gil;
            try {
                bytes = PySerializers::write(marshaling, sample, dataType(), littleEndian);
            } catch (const std::exception &error) {
                // A registered serializer's exception or none registered: logged with the port's name.
                RTC_ERROR(("%s: %s", getName(), error.what()));
                return Runtime::CdrView{};
            }
        }
        return Runtime::CdrView{bytes.data(), bytes.size()};
    };
    py::gil_scoped_release released;
    notifyWrite(nullptr, typeid(py::object), [&little] { return little; });
    writeBytesAs(marshal);
    return true;
}

void PyOutPort::addDataListener(RTC::ConnectorDataListenerType type, py::object listener)
{
    auto *made = new PyDataListener(std::move(listener), dataType(), "outport");
    // The port's lock is also taken by the ORB's threads while they call listeners, which wait for
    // the GIL: it is not held while waiting for that lock (as in portbindings.cpp).
    py::gil_scoped_release released;
    addConnectorDataListener(type, made);
}

void PyOutPort::addConnectorListener(RTC::ConnectorListenerType type, py::object listener)
{
    auto *made = new PyConnectorListener(std::move(listener));
    py::gil_scoped_release released; // see addDataListener()
    RTC::OutPortBase::addConnectorListener(type, made);
}

} // namespace RtPython
