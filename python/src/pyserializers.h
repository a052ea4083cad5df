// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/ConnectorBase.h>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace RtPython {

/**
 * Samples read as a connection's marshaling type says: plain `cdr` by the IDL type of the port, any
 * other name by the Python serializer a module registered under it for the port's data type
 * (OpenRTM-aist-Python's `SerializerFactories.instance().addSerializer(name, Class, RTC.TimedDouble)`),
 * whose `deserialize(bytes, data_type)` may read another type's CDR and return the port's.
 */
class PySerializers
{
public:
    /// The marshaling type of a connection for one side (`"inport"` or `"outport"`): the side's
    /// `<side>.marshaling_type`, else `marshaling_type`, else `cdr`.
    static std::string marshalingType(const coil::Properties &connectorProperties, const char *side);
    /**
     * The value of @p size bytes of CDR; @p dataType is the port's value (its type's
     * `_NP_RepositoryId` picks the serializer), @p repositoryId its type. Needs the GIL; throws
     * ValueError when no serializer of that name is registered or it cannot read the bytes.
     */
    static pybind11::object read(const std::string &marshaling, pybind11::handle dataType, const std::string &repositoryId,
                                 const unsigned char *data, size_t size, bool littleEndian);
    /**
     * The bytes of @p sample, a value of @p repositoryId, as the serializer registered under
     * @p marshaling for the sample's type writes them (its `serialize(data)`). Needs the GIL;
     * throws ValueError when none is registered or it cannot write the sample.
     */
    static std::vector<unsigned char> write(const std::string &marshaling, pybind11::handle sample,
                                            const std::string &repositoryId, bool littleEndian);
};

} // namespace RtPython
