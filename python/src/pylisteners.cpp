// SPDX-License-Identifier: MIT
#include "pylisteners.h"
#include "bindings.h"
#include "pydatatypes.h"
#include "pyerrors.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace RtPython {

void releasePython(py::object &object)
{
    if (!interpreterAlive()) {
        object.release();
        return;
    }
    py::gil_scoped_acquire gil;
    object = py::object();
}

PyDataListener::PyDataListener(py::object listener, std::string repositoryId)
    : m_listener(std::move(listener))
    , m_repositoryId(std::move(repositoryId))
{
}

PyDataListener::~PyDataListener()
{
    releasePython(m_listener);
}

PyDataListener::ReturnCode PyDataListener::operator()(RTC::ConnectorInfo &info, RTC::ByteData &data,
                                                      const std::string &marshalingtype)
{
    if ((!marshalingtype.empty() && marshalingtype != "cdr") || !interpreterAlive())
        return NO_CHANGE;
    const bool little = info.properties.getProperty("serializer.cdr.endian", "little").compare(0, 6, "little") == 0;
    py::gil_scoped_acquire gil;
    try {
        const py::object sample =
            PyDataTypes::instance().decode(m_repositoryId, data.getBuffer(), data.getDataLength(), little);
        m_listener(info, sample);
    } catch (py::error_already_set &error) {
        printError("connector data listener of " + info.name + ":", error);
    }
    return NO_CHANGE;
}

PyConnectorListener::PyConnectorListener(py::object listener)
    : m_listener(std::move(listener))
{
}

PyConnectorListener::~PyConnectorListener()
{
    releasePython(m_listener);
}

PyConnectorListener::ReturnCode PyConnectorListener::operator()(RTC::ConnectorInfo &info)
{
    if (!interpreterAlive())
        return NO_CHANGE;
    py::gil_scoped_acquire gil;
    try {
        m_listener(info);
    } catch (py::error_already_set &error) {
        printError("connector listener of " + info.name + ":", error);
    }
    return NO_CHANGE;
}

void bindListeners(py::module_ &module)
{
    py::class_<RTC::ConnectorInfo>(module, "ConnectorInfo")
        .def_readonly("name", &RTC::ConnectorInfo::name)
        .def_readonly("id", &RTC::ConnectorInfo::id)
        .def_readonly("ports", &RTC::ConnectorInfo::ports)
        .def_readonly("properties", &RTC::ConnectorInfo::properties);
    py::enum_<RTC::ConnectorDataListenerType>(module, "ConnectorDataListenerType")
        .value("ON_BUFFER_WRITE", RTC::ConnectorDataListenerType::ON_BUFFER_WRITE)
        .value("ON_BUFFER_FULL", RTC::ConnectorDataListenerType::ON_BUFFER_FULL)
        .value("ON_BUFFER_WRITE_TIMEOUT", RTC::ConnectorDataListenerType::ON_BUFFER_WRITE_TIMEOUT)
        .value("ON_BUFFER_OVERWRITE", RTC::ConnectorDataListenerType::ON_BUFFER_OVERWRITE)
        .value("ON_BUFFER_READ", RTC::ConnectorDataListenerType::ON_BUFFER_READ)
        .value("ON_SEND", RTC::ConnectorDataListenerType::ON_SEND)
        .value("ON_RECEIVED", RTC::ConnectorDataListenerType::ON_RECEIVED)
        .value("ON_RECEIVER_FULL", RTC::ConnectorDataListenerType::ON_RECEIVER_FULL)
        .value("ON_RECEIVER_TIMEOUT", RTC::ConnectorDataListenerType::ON_RECEIVER_TIMEOUT)
        .value("ON_RECEIVER_ERROR", RTC::ConnectorDataListenerType::ON_RECEIVER_ERROR);
    py::enum_<RTC::ConnectorListenerType>(module, "ConnectorListenerType")
        .value("ON_BUFFER_EMPTY", RTC::ConnectorListenerType::ON_BUFFER_EMPTY)
        .value("ON_BUFFER_READ_TIMEOUT", RTC::ConnectorListenerType::ON_BUFFER_READ_TIMEOUT)
        .value("ON_SENDER_EMPTY", RTC::ConnectorListenerType::ON_SENDER_EMPTY)
        .value("ON_SENDER_TIMEOUT", RTC::ConnectorListenerType::ON_SENDER_TIMEOUT)
        .value("ON_SENDER_ERROR", RTC::ConnectorListenerType::ON_SENDER_ERROR)
        .value("ON_CONNECT", RTC::ConnectorListenerType::ON_CONNECT)
        .value("ON_DISCONNECT", RTC::ConnectorListenerType::ON_DISCONNECT);
}

} // namespace RtPython
