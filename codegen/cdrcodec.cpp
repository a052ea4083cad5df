// SPDX-License-Identifier: MIT
#include "cdrcodec.h"
#include "cdrtypecode.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QtEndian>

#include <cmath>
#include <cstring>
#include <limits>

namespace Codegen {

namespace {

constexpr int MaxDepth = 64;

/// The primitive kinds of CDR, with their size (= alignment).
enum class Primitive { Boolean, Char, Octet, Short, UShort, Long, ULong, LongLong, ULongLong, Float, Double };

std::optional<Primitive> primitive(const QString &keyword)
{
    static const QHash<QString, Primitive> kinds = {
        {QStringLiteral("boolean"), Primitive::Boolean},
        {QStringLiteral("char"), Primitive::Char},
        {QStringLiteral("octet"), Primitive::Octet},
        {QStringLiteral("int8"), Primitive::Octet},
        {QStringLiteral("uint8"), Primitive::Octet},
        {QStringLiteral("short"), Primitive::Short},
        {QStringLiteral("int16"), Primitive::Short},
        {QStringLiteral("unsigned short"), Primitive::UShort},
        {QStringLiteral("uint16"), Primitive::UShort},
        {QStringLiteral("long"), Primitive::Long},
        {QStringLiteral("int32"), Primitive::Long},
        {QStringLiteral("unsigned long"), Primitive::ULong},
        {QStringLiteral("uint32"), Primitive::ULong},
        {QStringLiteral("long long"), Primitive::LongLong},
        {QStringLiteral("int64"), Primitive::LongLong},
        {QStringLiteral("unsigned long long"), Primitive::ULongLong},
        {QStringLiteral("uint64"), Primitive::ULongLong},
        {QStringLiteral("float"), Primitive::Float},
        {QStringLiteral("double"), Primitive::Double},
    };
    const auto it = kinds.constFind(keyword);
    return it == kinds.constEnd() ? std::nullopt : std::optional<Primitive>(*it);
}

int sizeOf(Primitive kind)
{
    switch (kind) {
    case Primitive::Boolean:
    case Primitive::Char:
    case Primitive::Octet:
        return 1;
    case Primitive::Short:
    case Primitive::UShort:
        return 2;
    case Primitive::Long:
    case Primitive::ULong:
    case Primitive::Float:
        return 4;
    case Primitive::LongLong:
    case Primitive::ULongLong:
    case Primitive::Double:
        return 8;
    }
    return 1;
}

QJsonValue floatValue(double value)
{
    if (std::isnan(value))
        return QStringLiteral("NaN");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("Infinity") : QStringLiteral("-Infinity");
    return value;
}

/// `string`, as an IOR's type id is written.
IdlType plainString()
{
    IdlType type;
    type.kind = IdlType::Kind::String;
    return type;
}

/// The failure of one decode or encode, with the member path where it happened.
struct Failure
{
    QString message;
};

/// Walks a type with the model; the base of the reader and the writer.
class TypeWalker
{
public:
    explicit TypeWalker(const IdlModel &model)
        : m_model(model)
    { }

protected:
    [[noreturn]] void fail(const QString &message) const
    {
        throw Failure {m_path.isEmpty() ? message
                                        : QStringLiteral("%1: %2").arg(m_path.join(QString()), message)};
    }

    /// Typedefs followed; arrays whose element is a typedef of an array are kept as written.
    IdlType resolved(const IdlType &type) const { return m_model.resolve(type); }

    void enter(const QString &step)
    {
        if (m_path.size() > MaxDepth)
            fail(QStringLiteral("types nested deeper than %1 levels").arg(MaxDepth));
        m_path.append(step);
    }
    void leave() { m_path.removeLast(); }

    const IdlModel &m_model;
    QStringList m_path;
};

class Reader : public TypeWalker
{
public:
    Reader(const IdlModel &model, CdrInput &input, bool little)
        : TypeWalker(model)
        , m_input(input)
        , m_little(little)
    { }

    QJsonValue read(const IdlType &written)
    {
        const IdlType type = resolved(written);
        if (CdrTypeCode::isTypeCode(type))
            return readTypeCode().toString();
        switch (type.kind) {
        case IdlType::Kind::Basic: {
            if (type.name == QLatin1String("wchar"))
                return readWChar();
            if (type.name == QLatin1String("Object"))
                return readObjectReference();
            if (type.name == QLatin1String("any"))
                return readAny();
            const std::optional<Primitive> kind = primitive(type.name);
            if (!kind)
                fail(QStringLiteral("values of type '%1' cannot be shown").arg(type.name));
            return readPrimitive(*kind);
        }
        case IdlType::Kind::String: {
            const quint32 length = quint32(readUnsigned(4));
            if (length == 0 || !m_input.available(length))
                fail(QStringLiteral("string of %1 bytes where %2 remain").arg(length).arg(left()));
            QByteArray text(qsizetype(length), Qt::Uninitialized);
            m_input.read(reinterpret_cast<uchar *>(text.data()), int(length), 1);
            text.chop(1);
            return QString::fromUtf8(text);
        }
        case IdlType::Kind::WString: {
            // GIOP 1.2: the length in bytes, then UTF-16 (see readUtf16).
            const quint32 length = quint32(readUnsigned(4));
            if (length % 2 != 0 || !m_input.available(length))
                fail(QStringLiteral("wide string of %1 bytes where %2 remain").arg(length).arg(left()));
            return readUtf16(length);
        }
        case IdlType::Kind::Sequence: {
            const quint32 count = quint32(readUnsigned(4));
            // Every element takes at least one byte: a count beyond what remains is malformed.
            if (!m_input.available(count))
                fail(QStringLiteral("sequence of %1 elements where %2 remain").arg(count).arg(left()));
            if (!type.bound.isEmpty() && count > type.bound.toUInt())
                fail(QStringLiteral("sequence of %1 elements exceeds its bound %2").arg(count).arg(type.bound));
            QJsonArray items;
            for (quint32 i = 0; i < count; ++i) {
                enter(QStringLiteral("[%1]").arg(i));
                items.append(read(type.element.front()));
                leave();
            }
            return items;
        }
        case IdlType::Kind::Array:
            return readArray(type.element.front(), type.dimensions, 0);
        case IdlType::Kind::Fixed:
            fail(QStringLiteral("fixed-point values cannot be shown"));
        case IdlType::Kind::Named:
            return readNamed(type.name);
        }
        fail(QStringLiteral("unknown type"));
    }

private:
    /// An `any`: its TypeCode, then its value; `{"type": "long", "value": 5}`.
    QJsonValue readAny()
    {
        const IdlType type = readTypeCode();
        return QJsonObject{{QStringLiteral("type"), type.toString()},
                           {QStringLiteral("value"), CdrTypeCode::isEmpty(type) ? QJsonValue::Null : read(type)}};
    }

    IdlType readTypeCode()
    {
        try {
            return CdrTypeCode::read(m_model, m_input, m_little);
        } catch (const CdrTypeCode::Error &error) {
            fail(error.message);
        }
    }

    /// GIOP 1.2's wchar: its length in one octet, then UTF-16 (see readUtf16); one character.
    QJsonValue readWChar()
    {
        const quint32 length = quint32(readUnsigned(1));
        if (length % 2 != 0 || !m_input.available(length))
            fail(QStringLiteral("wide character of %1 bytes where %2 remain").arg(length).arg(left()));
        const QString text = readUtf16(length);
        if (text.size() != 1)
            fail(QStringLiteral("a wide character of %1 code units").arg(text.size()));
        return text;
    }

    /// @p length bytes of UTF-16: big-endian whatever the stream's byte order, unless a byte-order
    /// mark comes first (omniORB writes wide strings in the machine's order after one).
    QString readUtf16(quint32 length)
    {
        const QByteArray bytes = readOctets(length);
        bool big = true;
        QString text;
        for (quint32 i = 0; i + 1 < length; i += 2) {
            const uchar high = uchar(bytes[i]), low = uchar(bytes[i + 1]);
            const char16_t unit = big ? char16_t(high << 8 | low) : char16_t(low << 8 | high);
            if (i == 0 && (unit == 0xFEFF || unit == 0xFFFE)) {
                big = unit == 0xFEFF;
                continue;
            }
            text.append(QChar(unit));
        }
        return text;
    }

    /// @p length octets as they are (the caller has checked that they remain).
    QByteArray readOctets(quint32 length)
    {
        QByteArray bytes;
        bytes.reserve(qsizetype(length));
        for (quint32 i = 0; i < length; ++i)
            bytes.append(char(readUnsigned(1, /*aligned=*/false)));
        return bytes;
    }

    QJsonValue readArray(const IdlType &element, const QStringList &dimensions, int level)
    {
        const int count = dimensions.value(level).toInt();
        QJsonArray items;
        for (int i = 0; i < count; ++i) {
            enter(QStringLiteral("[%1]").arg(i));
            items.append(level + 1 < dimensions.size() ? readArray(element, dimensions, level + 1)
                                                       : read(element));
            leave();
        }
        return items;
    }

    QJsonValue readNamed(const QString &name)
    {
        if (const auto it = m_model.structs.constFind(name); it != m_model.structs.constEnd()) {
            QJsonObject object;
            for (const IdlMember &member : it->members) {
                enter(QLatin1Char('.') + member.name);
                object.insert(member.name, read(member.type));
                leave();
            }
            return object;
        }
        if (const auto it = m_model.enums.constFind(name); it != m_model.enums.constEnd()) {
            const quint32 index = quint32(readUnsigned(4));
            if (index >= quint32(it->enumerators.size()))
                fail(QStringLiteral("%1 has no enumerator %2").arg(name).arg(index));
            return it->enumerators.at(int(index));
        }
        if (const auto it = m_model.unions.constFind(name); it != m_model.unions.constEnd())
            return readUnion(*it);
        if (m_model.interfaces.contains(name))
            return readObjectReference();
        fail(QStringLiteral("type '%1' is not declared in the IDL files").arg(name));
    }

    /// An IOR: null when nil (no type id, no profiles), else its type id and tagged profiles.
    QJsonValue readObjectReference()
    {
        const QJsonValue typeId = read(plainString());
        const quint32 count = quint32(readUnsigned(4));
        if (!m_input.available(count))
            fail(QStringLiteral("object reference of %1 profiles where %2 remain").arg(count).arg(left()));
        QJsonArray profiles;
        for (quint32 i = 0; i < count; ++i) {
            const qint64 tag = qint64(readUnsigned(4));
            const quint32 length = quint32(readUnsigned(4));
            if (!m_input.available(length))
                fail(QStringLiteral("profile of %1 bytes where %2 remain").arg(length).arg(left()));
            profiles.append(QJsonObject{{QStringLiteral("tag"), tag},
                                        {QStringLiteral("data"), QString::fromLatin1(readOctets(length).toHex())}});
        }
        if (typeId.toString().isEmpty() && profiles.isEmpty())
            return QJsonValue::Null;
        return QJsonObject{{QStringLiteral("type_id"), typeId}, {QStringLiteral("profiles"), profiles}};
    }

    QJsonValue readUnion(const IdlUnion &type)
    {
        const QJsonValue discriminator = read(type.discriminator);
        const IdlUnionCase *chosen = CdrCodec::unionCase(type, discriminator);
        QJsonObject object {{QStringLiteral("_d"), discriminator}};
        if (chosen) {
            enter(QLatin1Char('.') + chosen->member.name);
            object.insert(chosen->member.name, read(chosen->member.type));
            leave();
        }
        return object;
    }

    /// What remains, for messages: "12 bytes", or "fewer" when the input cannot tell.
    QString left() const
    {
        const qint64 bytes = m_input.remaining();
        return bytes < 0 ? QStringLiteral("fewer") : QStringLiteral("%1 bytes").arg(bytes);
    }

    quint64 readUnsigned(int size, bool aligned = true)
    {
        uchar at[8];
        if (!m_input.read(at, size, aligned ? size : 1))
            fail(QStringLiteral("the sample ends early"));
        quint64 value = 0;
        for (int i = 0; i < size; ++i)
            value |= quint64(at[m_little ? i : size - 1 - i]) << (8 * i);
        return value;
    }

    QJsonValue readPrimitive(Primitive kind)
    {
        const quint64 raw = readUnsigned(sizeOf(kind));
        switch (kind) {
        case Primitive::Boolean:
            return raw != 0;
        case Primitive::Char:
            return QString(QChar::fromLatin1(char(raw)));
        case Primitive::Octet:
        case Primitive::UShort:
        case Primitive::ULong:
            return qint64(raw);
        case Primitive::Short:
            return qint64(qint16(raw));
        case Primitive::Long:
            return qint64(qint32(raw));
        case Primitive::LongLong:
            return qint64(raw);
        case Primitive::ULongLong:
            return raw <= quint64(std::numeric_limits<qint64>::max()) ? QJsonValue(qint64(raw))
                                                                      : QJsonValue(double(raw));
        case Primitive::Float: {
            const quint32 bits = quint32(raw);
            float value;
            std::memcpy(&value, &bits, sizeof value);
            return floatValue(value);
        }
        case Primitive::Double: {
            double value;
            std::memcpy(&value, &raw, sizeof value);
            return floatValue(value);
        }
        }
        return {};
    }

    CdrInput &m_input;
    const bool m_little;
};

class Writer : public TypeWalker
{
public:
    Writer(const IdlModel &model, CdrOutput &output, bool little)
        : TypeWalker(model)
        , m_output(output)
        , m_little(little)
    { }

    void write(const IdlType &written, const QJsonValue &value)
    {
        const IdlType type = resolved(written);
        if (CdrTypeCode::isTypeCode(type)) {
            writeTypeCode(value);
            return;
        }
        switch (type.kind) {
        case IdlType::Kind::Basic: {
            if (type.name == QLatin1String("wchar")) {
                writeWChar(value);
                return;
            }
            if (type.name == QLatin1String("Object")) {
                writeObjectReference(value);
                return;
            }
            if (type.name == QLatin1String("any")) {
                writeAny(value);
                return;
            }
            const std::optional<Primitive> kind = primitive(type.name);
            if (!kind)
                fail(QStringLiteral("values of type '%1' cannot be written").arg(type.name));
            writePrimitive(*kind, value);
            return;
        }
        case IdlType::Kind::String: {
            if (!value.isString() && !value.isUndefined() && !value.isNull())
                fail(QStringLiteral("a string is expected"));
            const QByteArray text = value.toString().toUtf8();
            if (!type.bound.isEmpty() && text.size() > type.bound.toInt())
                fail(QStringLiteral("the string is longer than its bound %1").arg(type.bound));
            writeUnsigned(4, quint64(text.size() + 1));
            m_output.write(reinterpret_cast<const uchar *>(text.constData()), int(text.size()) + 1, 1);
            return;
        }
        case IdlType::Kind::WString: {
            const QString text = value.toString();
            writeUnsigned(4, quint64(text.size() * 2));
            writeUtf16(text);
            return;
        }
        case IdlType::Kind::Sequence: {
            if (!value.isArray() && !value.isUndefined() && !value.isNull())
                fail(QStringLiteral("a list [ … ] is expected"));
            const QJsonArray items = value.toArray();
            if (!type.bound.isEmpty() && items.size() > type.bound.toInt())
                fail(QStringLiteral("%1 elements exceed the bound %2").arg(items.size()).arg(type.bound));
            writeUnsigned(4, quint64(items.size()));
            for (qsizetype i = 0; i < items.size(); ++i) {
                enter(QStringLiteral("[%1]").arg(i));
                write(type.element.front(), items.at(i));
                leave();
            }
            return;
        }
        case IdlType::Kind::Array:
            writeArray(type.element.front(), type.dimensions, 0, value);
            return;
        case IdlType::Kind::Fixed:
            fail(QStringLiteral("fixed-point values cannot be written"));
        case IdlType::Kind::Named:
            writeNamed(type.name, value);
            return;
        }
    }

private:
    /// An `any` from readAny()'s form; null (or nothing) is an empty one (TypeCode null).
    void writeAny(const QJsonValue &value)
    {
        if (!value.isObject() && !value.isUndefined() && !value.isNull())
            fail(QStringLiteral("an any {\"type\": \"long\", \"value\": …} or null is expected"));
        const IdlType type = writeTypeCode(value[QStringLiteral("type")]);
        if (!CdrTypeCode::isEmpty(type))
            write(type, value[QStringLiteral("value")]);
    }

    /// The TypeCode of the type named by @p name (IdlType::toString()'s form; none is `null`).
    IdlType writeTypeCode(const QJsonValue &name)
    {
        if (!name.isString() && !name.isUndefined() && !name.isNull())
            fail(QStringLiteral("a type name such as \"RTC::Time\" is expected"));
        try {
            const IdlType type = CdrTypeCode::fromText(m_model, name.toString(QStringLiteral("null")));
            CdrTypeCode::write(m_model, type, m_output, m_little);
            return type;
        } catch (const CdrTypeCode::Error &error) {
            fail(error.message);
        }
    }

    /// An IOR from readObjectReference()'s form; null (or nothing) is the nil reference.
    void writeObjectReference(const QJsonValue &value)
    {
        if (!value.isObject() && !value.isUndefined() && !value.isNull())
            fail(QStringLiteral("an object reference {\"type_id\": …, \"profiles\": […]} or null is expected"));
        const QJsonObject object = value.toObject();
        write(plainString(), object.value(QStringLiteral("type_id")));
        const QJsonArray profiles = object.value(QStringLiteral("profiles")).toArray();
        writeUnsigned(4, quint64(profiles.size()));
        for (const QJsonValue &profile : profiles) {
            writeUnsigned(4, quint64(profile[QStringLiteral("tag")].toInteger()));
            const QByteArray data = QByteArray::fromHex(profile[QStringLiteral("data")].toString().toLatin1());
            writeUnsigned(4, quint64(data.size()));
            m_output.write(reinterpret_cast<const uchar *>(data.constData()), int(data.size()), 1);
        }
    }

    /// A union as {"_d": discriminator, "<member>": value}: the discriminator, then the member it
    /// selects. Without "_d", the first case's first label.
    void writeUnion(const IdlUnion &type, const QJsonValue &value)
    {
        if (!value.isObject() && !value.isUndefined() && !value.isNull())
            fail(QStringLiteral("an object {\"_d\": …} is expected for %1").arg(type.scopedName));
        const QJsonObject object = value.toObject();
        QJsonValue discriminator = object.value(QStringLiteral("_d"));
        if (discriminator.isUndefined() && !type.cases.isEmpty() && !type.cases.front().labels.isEmpty())
            discriminator = CdrCodec::labelValue(m_model, type, type.cases.front().labels.front());
        enter(QStringLiteral("._d"));
        write(type.discriminator, discriminator);
        leave();
        if (const IdlUnionCase *chosen = CdrCodec::unionCase(type, discriminator)) {
            enter(QLatin1Char('.') + chosen->member.name);
            write(chosen->member.type, object.value(chosen->member.name));
            leave();
        }
    }

    /// GIOP 1.2's wchar: two octets of big-endian UTF-16 after their length, as omniORB writes it.
    void writeWChar(const QJsonValue &value)
    {
        const QString text = value.isUndefined() || value.isNull() ? QString(QChar(0)) : value.toString();
        if (text.size() != 1)
            fail(QStringLiteral("one wide character is expected"));
        writeUnsigned(1, 2);
        writeUtf16(text);
    }

    /// Big-endian UTF-16 without a byte-order mark: how GIOP 1.2 reads UTF-16 that has none.
    void writeUtf16(const QString &text)
    {
        for (const QChar c : text) {
            const uchar unit[2] = {uchar(c.unicode() >> 8), uchar(c.unicode() & 0xff)};
            m_output.write(unit, 2, 1);
        }
    }

    void writeArray(const IdlType &element, const QStringList &dimensions, int level,
                    const QJsonValue &value)
    {
        const int count = dimensions.value(level).toInt();
        const QJsonArray items = value.toArray();
        if (!value.isUndefined() && !value.isNull() && items.size() != count)
            fail(QStringLiteral("an array of %1 elements is expected").arg(count));
        for (int i = 0; i < count; ++i) {
            enter(QStringLiteral("[%1]").arg(i));
            if (level + 1 < dimensions.size())
                writeArray(element, dimensions, level + 1, items.at(i));
            else
                write(element, i < items.size() ? items.at(i) : QJsonValue());
            leave();
        }
    }

    void writeNamed(const QString &name, const QJsonValue &value)
    {
        if (const auto it = m_model.structs.constFind(name); it != m_model.structs.constEnd()) {
            if (!value.isObject() && !value.isUndefined() && !value.isNull())
                fail(QStringLiteral("an object { … } is expected for %1").arg(name));
            const QJsonObject object = value.toObject();
            for (auto key = object.constBegin(); key != object.constEnd(); ++key) {
                const bool known = std::any_of(it->members.cbegin(), it->members.cend(),
                                               [&](const IdlMember &m) { return m.name == key.key(); });
                if (!known)
                    fail(QStringLiteral("%1 has no member '%2'").arg(name, key.key()));
            }
            const bool timed = m_model.isTimed(*it);
            for (const IdlMember &member : it->members) {
                enter(QLatin1Char('.') + member.name);
                QJsonValue field = object.value(member.name);
                if (timed && member.name == QLatin1String("tm") && field.isUndefined()) {
                    const qint64 now = QDateTime::currentMSecsSinceEpoch();
                    field = QJsonObject {{QStringLiteral("sec"), now / 1000},
                                         {QStringLiteral("nsec"), (now % 1000) * 1000000}};
                }
                write(member.type, field);
                leave();
            }
            return;
        }
        if (const auto it = m_model.enums.constFind(name); it != m_model.enums.constEnd()) {
            const QString text = value.toString();
            qsizetype index = value.isDouble() ? qsizetype(value.toInteger(-1))
                                               : it->enumerators.indexOf(text.section(QStringLiteral("::"), -1));
            if (value.isUndefined() || value.isNull())
                index = 0;
            if (index < 0 || index >= it->enumerators.size())
                fail(QStringLiteral("'%1' is none of %2").arg(text, it->enumerators.join(QStringLiteral(", "))));
            writeUnsigned(4, quint64(index));
            return;
        }
        if (const auto it = m_model.unions.constFind(name); it != m_model.unions.constEnd()) {
            writeUnion(*it, value);
            return;
        }
        if (m_model.interfaces.contains(name)) {
            writeObjectReference(value);
            return;
        }
        fail(QStringLiteral("type '%1' is not declared in the IDL files").arg(name));
    }

    void writeUnsigned(int size, quint64 value, bool aligned = true)
    {
        uchar bytes[8];
        for (int i = 0; i < size; ++i) {
            const int shift = 8 * (m_little ? i : size - 1 - i);
            bytes[i] = uchar((value >> shift) & 0xff);
        }
        m_output.write(bytes, size, aligned ? size : 1);
    }

    double number(const QJsonValue &value)
    {
        if (value.isUndefined() || value.isNull())
            return 0;
        if (value.isBool())
            return value.toBool() ? 1 : 0;
        if (value.isString()) {
            const QString text = value.toString();
            if (text == QLatin1String("NaN"))
                return std::numeric_limits<double>::quiet_NaN();
            if (text == QLatin1String("Infinity"))
                return std::numeric_limits<double>::infinity();
            if (text == QLatin1String("-Infinity"))
                return -std::numeric_limits<double>::infinity();
            fail(QStringLiteral("'%1' is not a number").arg(text));
        }
        if (!value.isDouble())
            fail(QStringLiteral("a number is expected"));
        return value.toDouble();
    }

    qint64 integer(const QJsonValue &value, qint64 low, qint64 high)
    {
        const double d = number(value);
        if (d != std::floor(d) || d < double(low) || d > double(high))
            fail(QStringLiteral("%1 is not a whole number from %2 to %3").arg(d).arg(low).arg(high));
        return value.isDouble() ? value.toInteger() : qint64(d);
    }

    void writePrimitive(Primitive kind, const QJsonValue &value)
    {
        const int size = sizeOf(kind);
        switch (kind) {
        case Primitive::Boolean:
            writeUnsigned(size, value.isBool() ? quint64(value.toBool()) : quint64(integer(value, 0, 1)));
            return;
        case Primitive::Char: {
            const QString text = value.toString();
            if (value.isString() && text.size() != 1)
                fail(QStringLiteral("one character is expected"));
            writeUnsigned(size, value.isString() ? quint64(text.at(0).toLatin1())
                                                 : quint64(integer(value, 0, 255)));
            return;
        }
        case Primitive::Octet:
            writeUnsigned(size, quint64(integer(value, 0, 255)));
            return;
        case Primitive::Short:
            writeUnsigned(size, quint64(integer(value, -32768, 32767)));
            return;
        case Primitive::UShort:
            writeUnsigned(size, quint64(integer(value, 0, 65535)));
            return;
        case Primitive::Long:
            writeUnsigned(size, quint64(integer(value, std::numeric_limits<qint32>::min(),
                                                std::numeric_limits<qint32>::max())));
            return;
        case Primitive::ULong:
            writeUnsigned(size, quint64(integer(value, 0, std::numeric_limits<quint32>::max())));
            return;
        case Primitive::LongLong:
        case Primitive::ULongLong:
            writeUnsigned(size, quint64(integer(value, kind == Primitive::LongLong
                                                           ? std::numeric_limits<qint64>::min()
                                                           : 0,
                                                std::numeric_limits<qint64>::max())));
            return;
        case Primitive::Float: {
            const float f = float(number(value));
            quint32 bits;
            std::memcpy(&bits, &f, sizeof bits);
            writeUnsigned(size, bits);
            return;
        }
        case Primitive::Double: {
            const double d = number(value);
            quint64 bits;
            std::memcpy(&bits, &d, sizeof bits);
            writeUnsigned(size, bits);
            return;
        }
        }
    }

    CdrOutput &m_output;
    const bool m_little;
};

/// A sample in memory, alignment counted from its first byte.
class ByteInput : public CdrInput
{
public:
    explicit ByteInput(const QByteArray &bytes)
        : m_bytes(bytes)
    { }

    bool read(uchar *to, int size, int alignment) override
    {
        const qsizetype start = (m_position + alignment - 1) / alignment * alignment;
        if (start + size > m_bytes.size())
            return false;
        std::memcpy(to, m_bytes.constData() + start, size_t(size));
        m_position = start + size;
        return true;
    }
    bool available(quint64 bytes) const override { return bytes <= quint64(remaining()); }
    qint64 remaining() const override { return m_bytes.size() - m_position; }

private:
    const QByteArray &m_bytes;
    qsizetype m_position = 0;
};

class ByteOutput : public CdrOutput
{
public:
    void write(const uchar *from, int size, int alignment) override
    {
        while (m_bytes.size() % alignment != 0)
            m_bytes.append('\0');
        m_bytes.append(reinterpret_cast<const char *>(from), size);
    }
    QByteArray m_bytes;
};

/// Formats a value by its type; `json` picks JSON syntax, else the people's one-line form.
class Formatter
{
public:
    Formatter(const IdlModel &model, bool json)
        : m_model(model)
        , m_json(json)
    { }

    QString format(const IdlType &written, const QJsonValue &value, int depth = 0) const
    {
        if (depth > MaxDepth)
            return QStringLiteral("…");
        const IdlType type = m_model.resolve(written);
        if (type.kind == IdlType::Kind::Sequence || type.kind == IdlType::Kind::Array) {
            IdlType element = type.element.front();
            if (type.kind == IdlType::Kind::Array && type.dimensions.size() > 1) {
                IdlType inner = type;
                inner.dimensions.removeFirst();
                element = inner;
            }
            QStringList items;
            for (const QJsonValue &item : value.toArray())
                items.append(format(element, item, depth + 1));
            return QLatin1Char('[') + items.join(m_json ? QStringLiteral(",") : QStringLiteral(", "))
                + QLatin1Char(']');
        }
        if (type.kind == IdlType::Kind::Named && value.isObject()) {
            const QJsonObject object = value.toObject();
            QStringList names;
            if (const auto it = m_model.structs.constFind(type.name); it != m_model.structs.constEnd()) {
                for (const IdlMember &member : it->members)
                    names.append(member.name);
            } else {
                names = object.keys();
            }
            QStringList fields;
            for (const QString &name : names) {
                const IdlType memberType = memberTypeOf(type.name, name, object);
                const QString text = format(memberType, object.value(name), depth + 1);
                fields.append(m_json ? CdrCodec::jsonText(name) + QLatin1Char(':') + text
                                     : name + QLatin1Char('=') + text);
            }
            return m_json ? QLatin1Char('{') + fields.join(QLatin1Char(',')) + QLatin1Char('}')
                          : QLatin1Char('{') + fields.join(QStringLiteral(", ")) + QLatin1Char('}');
        }
        return CdrCodec::jsonText(value);
    }

    IdlType memberTypeOf(const QString &owner, const QString &member, const QJsonObject &object) const
    {
        if (const auto it = m_model.structs.constFind(owner); it != m_model.structs.constEnd()) {
            for (const IdlMember &m : it->members) {
                if (m.name == member)
                    return m.type;
            }
        }
        if (const auto it = m_model.unions.constFind(owner); it != m_model.unions.constEnd()) {
            if (member == QLatin1String("_d"))
                return it->discriminator;
            for (const IdlUnionCase &c : it->cases) {
                if (c.member.name == member)
                    return c.member.type;
            }
        }
        Q_UNUSED(object);
        return IdlType::basic(QStringLiteral("any"));
    }

private:
    const IdlModel &m_model;
    const bool m_json;
};

} // namespace

QString CdrCodec::jsonText(const QJsonValue &value)
{
    if (value.isString()) {
        const QByteArray doc = QJsonDocument(QJsonArray {value}).toJson(QJsonDocument::Compact);
        return QString::fromUtf8(doc.mid(1, doc.size() - 2));
    }
    if (value.isDouble()) {
        const double d = value.toDouble();
        if (d == std::floor(d) && std::abs(d) < 1e15)
            return QString::number(value.toInteger());
        return QString::number(d, 'g', QLocale::FloatingPointShortest);
    }
    if (value.isBool())
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    return QStringLiteral("null");
}

CdrCodec::CdrCodec(const IdlModel &model)
    : m_model(model)
{ }

const IdlUnionCase *CdrCodec::unionCase(const IdlUnion &type, const QJsonValue &discriminator)
{
    const QString label = discriminator.isString()
        ? discriminator.toString().section(QStringLiteral("::"), -1)
        : discriminator.isBool() ? (discriminator.toBool() ? QStringLiteral("TRUE") : QStringLiteral("FALSE"))
                                 : QString::number(discriminator.toInteger());
    const IdlUnionCase *fallback = nullptr;
    for (const IdlUnionCase &c : type.cases) {
        for (const QString &l : c.labels) {
            if (l.section(QStringLiteral("::"), -1) == label)
                return &c;
        }
        if (c.isDefault)
            fallback = &c;
    }
    return fallback;
}

QJsonValue CdrCodec::labelValue(const IdlModel &model, const IdlUnion &type, const QString &label)
{
    const IdlType discriminator = model.resolve(type.discriminator);
    if (discriminator.kind == IdlType::Kind::Named)
        return label.section(QStringLiteral("::"), -1);
    if (discriminator.name == QLatin1String("boolean"))
        return label == QLatin1String("TRUE");
    if (discriminator.name == QLatin1String("char") || discriminator.name == QLatin1String("wchar"))
        return label.mid(1, label.size() - 2);
    return label.toLongLong(nullptr, 0);
}

QString CdrCodec::typeName(const QString &dataType)
{
    if (!dataType.startsWith(QLatin1String("IDL:")))
        return dataType;
    QString name = dataType.mid(4);
    name = name.left(name.lastIndexOf(QLatin1Char(':')));
    return name.replace(QLatin1Char('/'), QStringLiteral("::"));
}

bool CdrCodec::knows(const QString &type) const
{
    return m_model.structs.contains(type) || m_model.unions.contains(type)
        || m_model.enums.contains(type) || m_model.typedefs.contains(type);
}

QJsonValue CdrCodec::decode(const QString &type, const QByteArray &cdr, bool littleEndian,
                            QString *error) const
{
    return decodeValue(IdlType::named(type), cdr, littleEndian, error);
}

QJsonValue CdrCodec::decodeValue(const IdlType &type, const QByteArray &cdr, bool littleEndian, QString *error) const
{
    try {
        ByteInput input(cdr);
        Reader reader(m_model, input, littleEndian);
        const QJsonValue value = reader.read(type);
        if (input.remaining() > 7) // at most the padding of a last member
            throw Failure {QStringLiteral("%1 bytes left over after a %2").arg(input.remaining()).arg(type.toString())};
        return value;
    } catch (const Failure &failure) {
        if (error)
            *error = failure.message;
        return QJsonValue(QJsonValue::Undefined);
    }
}

QByteArray CdrCodec::encode(const QString &type, const QJsonValue &value, bool littleEndian,
                            QString *error) const
{
    return encodeValue(IdlType::named(type), value, littleEndian, error);
}

QByteArray CdrCodec::encodeValue(const IdlType &type, const QJsonValue &value, bool littleEndian, QString *error) const
{
    ByteOutput output;
    if (!write(type, value, output, littleEndian, error))
        return {};
    return output.m_bytes;
}

QJsonValue CdrCodec::read(const IdlType &type, CdrInput &input, bool littleEndian, QString *error) const
{
    try {
        return Reader(m_model, input, littleEndian).read(type);
    } catch (const Failure &failure) {
        if (error)
            *error = failure.message;
        return QJsonValue(QJsonValue::Undefined);
    }
}

bool CdrCodec::write(const IdlType &type, const QJsonValue &value, CdrOutput &output, bool littleEndian,
                     QString *error) const
{
    try {
        Writer(m_model, output, littleEndian).write(type, value);
        return true;
    } catch (const Failure &failure) {
        if (error)
            *error = failure.message;
        return false;
    }
}

QJsonValue CdrCodec::parseArgument(const QString &type, const QString &text, QString *error) const
{
    QJsonParseError parseError;
    const QJsonDocument document
        = QJsonDocument::fromJson((QLatin1Char('[') + text + QLatin1Char(']')).toUtf8(), &parseError);
    const QJsonValue parsed = parseError.error == QJsonParseError::NoError && document.array().size() == 1
        ? document.array().at(0)
        : QJsonValue(QJsonValue::Undefined);
    const IdlType resolvedType = m_model.resolve(IdlType::named(type));
    const auto it = m_model.structs.constFind(resolvedType.name);
    if (parsed.isObject() || it == m_model.structs.constEnd()) {
        if (parsed.isUndefined() && error)
            *error = QStringLiteral("'%1' is not a JSON value").arg(text);
        return parsed;
    }
    // A type with one member besides the timestamp takes that member's value alone.
    QList<IdlMember> members = it->members;
    members.removeIf([](const IdlMember &m) { return m.name == QLatin1String("tm"); });
    if (members.size() != 1) {
        if (error)
            *error = QStringLiteral("%1 has %2 members: give them as a JSON object {\"name\": value, …}")
                         .arg(type)
                         .arg(it->members.size());
        return QJsonValue(QJsonValue::Undefined);
    }
    QJsonValue value = parsed;
    if (value.isUndefined()) {
        const IdlType member = m_model.resolve(members.front().type);
        if (member.kind != IdlType::Kind::String && member.kind != IdlType::Kind::WString) {
            if (error)
                *error = QStringLiteral("'%1' is not a value for %2.%3")
                             .arg(text, type, members.front().name);
            return QJsonValue(QJsonValue::Undefined);
        }
        value = text;
    }
    return QJsonObject {{members.front().name, value}};
}

QString CdrCodec::toJson(const QString &type, const QJsonValue &value) const
{
    return Formatter(m_model, true).format(IdlType::named(type), value);
}

QString CdrCodec::toText(const QString &type, const QJsonValue &value) const
{
    const IdlType resolvedType = m_model.resolve(IdlType::named(type));
    const auto it = m_model.structs.constFind(resolvedType.name);
    if (it == m_model.structs.constEnd() || !value.isObject() || !m_model.isTimed(*it))
        return Formatter(m_model, false).format(resolvedType, value);
    // Timed types: the source's timestamp first, then the other members.
    const QJsonObject object = value.toObject();
    const QJsonObject tm = object.value(QStringLiteral("tm")).toObject();
    QStringList fields;
    const Formatter formatter(m_model, false);
    for (const IdlMember &member : it->members) {
        if (member.name != QLatin1String("tm"))
            fields.append(member.name + QLatin1Char('=')
                          + formatter.format(member.type, object.value(member.name)));
    }
    return QStringLiteral("[%1.%2] %3")
        .arg(tm.value(QStringLiteral("sec")).toInteger())
        .arg(tm.value(QStringLiteral("nsec")).toInteger(), 9, 10, QLatin1Char('0'))
        .arg(fields.join(QLatin1Char(' ')));
}

} // namespace Codegen
