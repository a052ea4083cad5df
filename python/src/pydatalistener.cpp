// SPDX-License-Identifier: MIT
#include "pydatalistener.h"
#include "pydatatypes.h"
#include "pyinterpreter.h"
#include "pyserializers.h"

#include <cstring>
#include <iostream>

namespace py = pybind11;

namespace RtPython {

PyDataListener::PyDataListener(py::object listener, std::string repositoryId, const char *side)
    : m_listener(std::move(listener))
    , m_repositoryId(std::move(repositoryId))
    , m_side(side)
{
}

PyDataListener::~PyDataListener()
{
    releasePython(m_listener);
}

PyDataListener::ReturnCode PyDataListener::operator()(RTC::ConnectorInfo &info, RTC::ByteData &data,
                                                      const std::string &marshalingtype)
{
    if (!interpreterAlive())
        return NO_CHANGE;
    const bool little = info.properties.getProperty("serializer.cdr.endian", "little").compare(0, 6, "little") == 0;
    // An OutPort hands its listeners the sample as the component wrote it, plain CDR of the port's
    // type, whatever serializer the connection sends it with; an InPort's get what arrived.
    const bool asWritten = std::strcmp(m_side, "outport") == 0;
    const std::string marshaling = asWritten ? std::string("cdr")
        : marshalingtype.empty() || marshalingtype == "cdr" ? PySerializers::marshalingType(info.properties, m_side)
                                                            : marshalingtype;
    Gil gil;
    try {
        // A user serializer is handed a value of the port's type, as the port's own read gives it.
        const py::object dataType = marshaling == "cdr" ? py::none() : PyDataTypes::instance().defaultValue(m_repositoryId);
        m_listener(info, PySerializers::read(marshaling, dataType, m_repositoryId, data.getBuffer(),
                                             data.getDataLength(), little));
    } catch (py::error_already_set &error) {
        printError("connector data listener of " + info.name + ":", error);
    } catch (const std::exception &error) {
        std::cerr << "connector data listener of " << info.name << ": " << error.what() << std::endl;
    }
    return NO_CHANGE;
}

} // namespace RtPython
