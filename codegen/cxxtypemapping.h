// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

namespace Codegen {

/**
 * The standard IDL → C++ mapping as omniidl writes it for servant skeletons
 * (POA_<Module>::<Interface>): parameter types by direction and category, return types, and a
 * statement that returns a valid empty value from a generated operation body.
 *
 * | category            | in          | out          | inout     | return      |
 * |---------------------|-------------|--------------|-----------|-------------|
 * | primitive, enum     | T           | T_out        | T&        | T           |
 * | string              | const char* | CORBA::String_out | char*& | char*     |
 * | fixed struct/union  | const T&    | T_out        | T&        | T           |
 * | variable struct, sequence | const T& | T_out    | T&        | T*          |
 * | array               | const T     | T_out        | T         | T_slice*    |
 * | interface           | I_ptr       | I_out        | I_ptr&    | I_ptr       |
 * | any                 | const CORBA::Any& | CORBA::Any_out | CORBA::Any& | CORBA::Any* |
 */

/// The C++ name of a type as used in declarations: `CORBA::Long`, `SimpleService::EchoList`.
QString cxxTypeName(const IdlModel &model, const IdlType &type);
/// The C++ type of an operation parameter.
QString cxxParameterType(const IdlModel &model, const IdlParameter &parameter);
/// The C++ return type of an operation.
QString cxxReturnType(const IdlModel &model, const IdlType &type);
/// `return …;` with a valid empty value of the return type; empty for void.
QString cxxReturnStatement(const IdlModel &model, const IdlType &type);

} // namespace Codegen
