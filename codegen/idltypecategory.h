// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

namespace Codegen {

/// What a language mapping needs to know about an IDL type to pass it around.
enum class IdlTypeCategory {
    Void,
    Primitive, ///< integer, floating point, char, wchar, boolean, octet
    Enum,
    String,
    WString,
    FixedStruct, ///< struct or union whose size is fixed
    VariableStruct, ///< struct or union holding strings, sequences, references …
    Sequence,
    FixedArray,
    VariableArray,
    ObjectReference, ///< an IDL interface
    Object, ///< CORBA::Object
    Any,
    TypeCode,
    Unknown ///< a name the model does not declare
};

/// The category of `type`, following typedefs.
IdlTypeCategory idlTypeCategory(const IdlModel &model, const IdlType &type);

/// True when the type has variable length in the CORBA sense (strings, sequences, any, object
/// references, and structs/unions/arrays containing one).
bool isVariableLength(const IdlModel &model, const IdlType &type);

/// The type after following typedefs, for reading its structure (arrays, sequences, names).
IdlType resolvedIdlType(const IdlModel &model, const IdlType &type);

/// A basic keyword with whitespace normalised (`unsigned   long` → `unsigned long`).
QString normalizedKeyword(const QString &keyword);

} // namespace Codegen
