// SPDX-License-Identifier: MIT
#include "pyconnectorlistener.h"
#include "pyinterpreter.h"

namespace py = pybind11;

namespace RtPython {

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
    Gil gil;
    try {
        m_listener(info);
    } catch (py::error_already_set &error) {
        printError("connector listener of " + info.name + ":", error);
    }
    return NO_CHANGE;
}

} // namespace RtPython
