// SPDX-License-Identifier: MIT
#include "pyserializers.h"
#include "pydatatypes.h"

#include <coil/stringutil.h>

namespace py = pybind11;

namespace RtPython {

std::string PySerializers::marshalingType(const coil::Properties &connectorProperties, const char *side)
{
    const std::string common = connectorProperties.getProperty("marshaling_type", "cdr");
    return coil::eraseBothEndsBlank(connectorProperties.getProperty(std::string(side) + ".marshaling_type", common));
}

namespace {

/// A new serializer of @p marshaling for @p dataType (a class or a value of it); ValueError when none.
py::object serializerFor(const std::string &marshaling, py::handle dataType, const std::string &repositoryId,
                         bool littleEndian)
{
    const py::object serializer = py::module_::import("OpenRTM_aist")
                                      .attr("SerializerFactories").attr("instance")()
                                      .attr("createSerializer")(marshaling, dataType);
    if (serializer.is_none())
        throw py::value_error("no serializer '" + marshaling + "' for " + repositoryId + " (SerializerFactories)");
    serializer.attr("isLittleEndian")(littleEndian);
    return serializer;
}

} // namespace

py::object PySerializers::read(const std::string &marshaling, py::handle dataType, const std::string &repositoryId,
                               const unsigned char *data, size_t size, bool littleEndian)
{
    if (marshaling.empty() || marshaling == "cdr")
        return PyDataTypes::instance().decode(repositoryId, data, size, littleEndian);
    const py::object serializer = serializerFor(marshaling, dataType, repositoryId, littleEndian);
    const py::tuple result
        = serializer.attr("deserialize")(py::bytes(reinterpret_cast<const char *>(data), size), dataType);
    if (result[0].cast<int>() != 0)
        throw py::value_error("serializer '" + marshaling + "' could not read a sample of " + repositoryId);
    return result[1];
}

std::vector<unsigned char> PySerializers::write(const std::string &marshaling, py::handle sample,
                                                const std::string &repositoryId, bool littleEndian)
{
    if (marshaling.empty() || marshaling == "cdr")
        return PyDataTypes::instance().encode(repositoryId, sample, littleEndian);
    const py::object serializer = serializerFor(marshaling, sample, repositoryId, littleEndian);
    const py::tuple result = serializer.attr("serialize")(sample);
    if (result[0].cast<int>() != 0 || !py::isinstance<py::bytes>(result[1]))
        throw py::value_error("serializer '" + marshaling + "' could not write a sample of " + repositoryId);
    const std::string bytes = result[1].cast<std::string>();
    return std::vector<unsigned char>(bytes.begin(), bytes.end());
}

} // namespace RtPython
