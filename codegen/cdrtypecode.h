// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

#include <QByteArray>
#include <QString>

namespace Codegen {

class CdrInput;
class CdrOutput;

/**
 * CORBA TypeCodes in CDR, as an `any` carries its value's type and a `TypeCode` value travels,
 * translated to and from the IDL types of an IdlModel.
 *
 * A TypeCode is written as omniORB writes the ones omniidl generates: a named type of the model
 * (struct, union, enum, exception, typedef, interface) with its repository id and simple name, a
 * typedef as an alias of its type, nested types inside encapsulations in the stream's byte order,
 * and a named type met again inside the same TypeCode as an indirection to its first occurrence.
 * Reading accepts any byte order and indirections, and maps repository ids back to the model's
 * scoped names; a named type the model does not declare is refused (its values could not be read).
 *
 * Types are named in text as IdlType::toString() writes them (`long`, `string`,
 * `sequence<RTC::Time>`, `RTC::TimedLong`, `long[3]`); `Object` is CORBA::Object, `TypeCode` the
 * TypeCode type, and the empty TypeCode of an empty any is `null`.
 */
class CdrTypeCode
{
public:
    /// Why a TypeCode could not be read or written.
    struct Error
    {
        QString message;
    };

    /// Reads one TypeCode from @p input; throws Error.
    static IdlType read(const IdlModel &model, CdrInput &input, bool littleEndian);
    /// Writes the TypeCode of @p type to @p output; throws Error.
    static void write(const IdlModel &model, const IdlType &type, CdrOutput &output, bool littleEndian);

    /// The type @p text names (IdlType::toString()'s form); throws Error when it is no type of @p model.
    static IdlType fromText(const IdlModel &model, const QString &text);
    /// True for the TypeCode type (`TypeCode`, or `CORBA::TypeCode` as IDL files write it).
    static bool isTypeCode(const IdlType &type);
    /// True for the types whose any holds no value (`null`, `void`).
    static bool isEmpty(const IdlType &type);
};

} // namespace Codegen
