// SPDX-License-Identifier: MIT
// ConnectorInfo and the listener types, with OpenRTM-aist's names.
#include "bindings.h"

#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>

#include <pybind11/stl.h>

namespace py = pybind11;

namespace RtPython {

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
