// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

namespace Codegen {

/**
 * The standard IDL → Java mapping (as idlj writes it): modules become packages, typedefs vanish
 * into the type they name, sequences and arrays become Java arrays, and out/inout parameters are
 * passed in Holder classes (`org.omg.CORBA.IntHolder`, `SimpleService.EchoListHolder`).
 */

/// The Java type of a value of `type`: `int`, `String`, `String[]`, `RTC.TimedLong`.
QString javaTypeName(const IdlModel &model, const IdlType &type);
/// The Java type of an operation parameter (a Holder for out and inout).
QString javaParameterType(const IdlModel &model, const IdlParameter &parameter);
/// An expression with an empty value of `type` (`0`, `false`, `""`, `new int[0]`, `null`).
QString javaDefaultValue(const IdlModel &model, const IdlType &type);

} // namespace Codegen
