// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

#include <pybind11/pybind11.h>

#include <QHash>
#include <QString>

#include <optional>
#include <vector>

namespace RtPython {

/**
 * Python values of IDL data types straight to CDR and back, without the JSON-shaped value that
 * PyValueConverter and Codegen::CdrCodec pass between them: for types made only of numbers,
 * booleans, chars, octets, strings, enums, structs, sequences and typedefs of those (OpenRTM's data
 * types but a few). PyDataTypes takes this way first; a type with anything else (wide characters,
 * unions, arrays, object references, any), and a value that does not fit or bytes that do not
 * decode, go the converter's way, which says what is wrong. Use with the GIL.
 */
class PyDirectCdr
{
public:
    /// @p classes maps each struct's and enum's scoped name to its Python class.
    PyDirectCdr(const Codegen::IdlModel &model, pybind11::dict classes);

    /// True when every member of the type @p typeName (a scoped name) is of a kind handled here.
    bool handles(const QString &typeName) const;
    /// Appends @p value as CDR of @p typeName to @p out; false (out as it was) when it does not fit.
    bool encode(const QString &typeName, pybind11::handle value, bool littleEndian, std::vector<unsigned char> *out) const;
    /// The Python value of the CDR @p data of @p typeName; none when the bytes do not decode.
    std::optional<pybind11::object> decode(const QString &typeName, const unsigned char *data, size_t size,
                                           bool littleEndian) const;

private:
    bool handlesType(const Codegen::IdlType &type, int depth) const;
    /// The member names of struct @p name as Python strings (made once).
    const std::vector<pybind11::str> &memberNames(const QString &name) const;

    const Codegen::IdlModel &m_model;
    pybind11::dict m_classes;
    mutable QHash<QString, bool> m_handles;
    mutable QHash<QString, std::vector<pybind11::str>> m_memberNames;

    friend class DirectWriter;
    friend class DirectReader;
};

} // namespace RtPython
