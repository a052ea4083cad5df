// SPDX-License-Identifier: MIT
#include "pydatalistener.h"
#include "pydatatypes.h"
#include "pyinterpreter.h"

namespace py = pybind11;

namespace RtPython {

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

} // namespace RtPython
