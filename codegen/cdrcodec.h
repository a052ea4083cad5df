// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

#include <optional>

#include <QByteArray>
#include <QJsonValue>
#include <QString>

namespace Codegen {

/// Where CdrCodec::read() takes bytes from: a sample in memory, or an ORB's request stream.
class CdrInput
{
public:
    virtual ~CdrInput() = default;
    /// Skips to the next multiple of @p alignment (counted as CDR counts it), then copies
    /// @p size bytes to @p to; false when fewer remain.
    virtual bool read(uchar *to, int size, int alignment) = 0;
    /// False when fewer than @p bytes remain (sizes read from the data are checked with it).
    virtual bool available(quint64 bytes) const = 0;
    /// The bytes left, or -1 when the input cannot tell (a stream still arriving).
    virtual qint64 remaining() const { return -1; }
};

/// Where CdrCodec::write() puts bytes: padding up to @p alignment first, then @p size bytes.
class CdrOutput
{
public:
    virtual ~CdrOutput() = default;
    virtual void write(const uchar *from, int size, int alignment) = 0;
};

/**
 * Data port samples as values: the CDR bytes an OutPort sends (OpenRTM's `corba_cdr` interface,
 * serializer `cdr`, alignment counted from the start of the sample) decoded by the IDL type of
 * the port, and values encoded back. Values are JSON: structs are objects, sequences and arrays
 * are arrays, enums are their enumerator names, `char` a one-letter string, `long long` exact
 * integers, and non-finite floats the strings "NaN", "Infinity" and "-Infinity".
 *
 * Types are the scoped names of an IdlModel (`RTC::TimedLong`); a union is
 * `{"_d": discriminator, "<member>": value}` with the member the discriminator selects; an object
 * reference is null when nil, else its IOR as `{"type_id": …, "profiles": [{"tag": n, "data": hex}]}`;
 * an `any` is `{"type": "long", "value": 5}` with its type named as IdlType::toString() writes it
 * (`"RTC::Time"`, `"sequence<long>"`, `"Object"` for CORBA::Object; null when empty) and its value
 * as a value of that type; a `TypeCode` value is such a type name (CdrTypeCode). An any whose
 * TypeCode names a type the model does not declare, `fixed` and `long double` are refused with an
 * error naming the member.
 */
class CdrCodec
{
public:
    explicit CdrCodec(const IdlModel &model);

    /// The scoped name of an OpenRTM data type id: `IDL:RTC/TimedLong:1.0` → `RTC::TimedLong`;
    /// a scoped name is returned as it is.
    static QString typeName(const QString &dataType);

    /// The case of @p type that @p discriminator (a value of the union's discriminator) selects:
    /// the one with its label, else the default case; null when none.
    static const IdlUnionCase *unionCase(const IdlUnion &type, const QJsonValue &discriminator);
    /// Case label @p label of @p type as a value of its discriminator (an enumerator's name, a
    /// number, a boolean or a character).
    static QJsonValue labelValue(const IdlModel &model, const IdlUnion &type, const QString &label);

    /// True when the model declares @p type (a struct, union, enum or typedef).
    bool knows(const QString &type) const;

    /// Decodes one sample; on failure an undefined value and the reason (with the member path).
    QJsonValue decode(const QString &type, const QByteArray &cdr, bool littleEndian,
                      QString *error) const;
    /// Encodes one sample. Struct members the value leaves out are zero / empty, except a
    /// timed type's `tm`, which is the current time.
    QByteArray encode(const QString &type, const QJsonValue &value, bool littleEndian,
                      QString *error) const;

    /// decode() and encode() of a value of any type (`sequence<long>`, a basic type, …), as
    /// omniORB's cdrMarshal writes it.
    QJsonValue decodeValue(const IdlType &type, const QByteArray &cdr, bool littleEndian, QString *error) const;
    QByteArray encodeValue(const IdlType &type, const QJsonValue &value, bool littleEndian, QString *error) const;

    /// Reads one value of @p type from @p input (an operation's parameter, say); on failure an
    /// undefined value and the reason.
    QJsonValue read(const IdlType &type, CdrInput &input, bool littleEndian, QString *error) const;
    /// Writes one value of @p type to @p output; false and the reason when it does not fit the type.
    bool write(const IdlType &type, const QJsonValue &value, CdrOutput &output, bool littleEndian,
               QString *error) const;

    /// A value read from a command line: a JSON value, or for a type with one member besides
    /// `tm` (TimedLong, TimedString, TimedDoubleSeq, …) that member's value alone (`42`,
    /// `[1,2]`, or plain text for a string member).
    QJsonValue parseArgument(const QString &type, const QString &text, QString *error) const;

    /// A string, number, boolean or null as JSON text (strings quoted and escaped).
    static QString jsonText(const QJsonValue &value);

    /// The value as one line of JSON with members in declaration order.
    QString toJson(const QString &type, const QJsonValue &value) const;
    /// The value as one line for people: `[sec.nsec] data=42` for timed types, members as
    /// `name=value`, sequences as `[1, 2]`, nested structs as `{x=1, y=2}`.
    QString toText(const QString &type, const QJsonValue &value) const;

private:
    const IdlModel &m_model;
};

} // namespace Codegen
