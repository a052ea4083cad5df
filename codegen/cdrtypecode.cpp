// SPDX-License-Identifier: MIT
#include "cdrtypecode.h"
#include "cdrcodec.h"

#include <QHash>
#include <QRegularExpression>

namespace Codegen {

namespace {

/// CORBA's TCKind numbers of the kinds with parameters.
enum Kind : quint32 {
    TkObjref = 14, TkStruct = 15, TkUnion = 16, TkEnum = 17, TkString = 18, TkSequence = 19, TkArray = 20,
    TkAlias = 21, TkExcept = 22, TkWString = 27, TkFixed = 28,
};
constexpr quint32 Indirection = 0xffffffff;
constexpr int MaxDepth = 64;
const char ObjectId[] = "IDL:omg.org/CORBA/Object:1.0";

/// The kinds without parameters, by the IDL keyword naming them (IDL 4's integer names after the
/// classic ones, so that reading gives the classic name).
struct SimpleKind
{
    quint32 kind;
    const char *keyword;
};
constexpr SimpleKind SimpleKinds[] = {
    {0, "null"}, {1, "void"}, {2, "short"}, {3, "long"}, {4, "unsigned short"}, {5, "unsigned long"},
    {6, "float"}, {7, "double"}, {8, "boolean"}, {9, "char"}, {10, "octet"}, {11, "any"}, {12, "TypeCode"},
    {23, "long long"}, {24, "unsigned long long"}, {26, "wchar"},
    {2, "int16"}, {3, "int32"}, {4, "uint16"}, {5, "uint32"}, {23, "int64"}, {24, "uint64"}, {10, "int8"},
    {10, "uint8"},
};

const SimpleKind *simpleKind(quint32 kind)
{
    for (const SimpleKind &entry : SimpleKinds) {
        if (entry.kind == kind)
            return &entry;
    }
    return nullptr;
}

const SimpleKind *simpleKind(const QString &keyword)
{
    for (const SimpleKind &entry : SimpleKinds) {
        if (keyword == QLatin1String(entry.keyword))
            return &entry;
    }
    return nullptr;
}

[[noreturn]] void fail(const QString &message)
{
    throw CdrTypeCode::Error{message};
}

QString leafName(const QString &scopedName)
{
    return scopedName.section(QStringLiteral("::"), -1);
}

/// The size of a union's case label in a TypeCode, by the resolved discriminator type.
int labelSize(const IdlModel &model, const IdlType &discriminator)
{
    const IdlType type = model.resolve(discriminator);
    if (type.kind == IdlType::Kind::Named && model.enums.contains(type.name))
        return 4;
    static const QHash<QString, int> sizes = {
        {QStringLiteral("boolean"), 1}, {QStringLiteral("char"), 1}, {QStringLiteral("octet"), 1},
        {QStringLiteral("short"), 2}, {QStringLiteral("unsigned short"), 2}, {QStringLiteral("long"), 4},
        {QStringLiteral("unsigned long"), 4}, {QStringLiteral("long long"), 8},
        {QStringLiteral("unsigned long long"), 8},
    };
    const int size = type.kind == IdlType::Kind::Basic ? sizes.value(type.name) : 0;
    if (size == 0)
        fail(QStringLiteral("a union discriminated by %1 has no TypeCode here").arg(type.toString()));
    return size;
}

/// Writes one top-level TypeCode into memory; positions count from its first byte, which the
/// stream puts at a multiple of four, so that alignment and indirection offsets hold there too.
class Encoder
{
public:
    Encoder(const IdlModel &model, bool little)
        : m_model(model)
        , m_little(little)
    { }

    void typeCode(const IdlType &type)
    {
        if (++m_depth > MaxDepth)
            fail(QStringLiteral("types nested deeper than %1 levels").arg(MaxDepth));
        switch (type.kind) {
        case IdlType::Kind::Basic:
            basic(type.name);
            break;
        case IdlType::Kind::String:
        case IdlType::Kind::WString:
            ulong(type.kind == IdlType::Kind::String ? TkString : TkWString);
            ulong(type.bound.toUInt());
            break;
        case IdlType::Kind::Sequence:
            ulong(TkSequence);
            encapsulated([&] {
                typeCode(type.element.front());
                ulong(type.bound.toUInt());
            });
            break;
        case IdlType::Kind::Array:
            array(type);
            break;
        case IdlType::Kind::Named:
            named(type.name);
            break;
        case IdlType::Kind::Fixed:
            fail(QStringLiteral("fixed-point types have no TypeCode here"));
        }
        --m_depth;
    }

    QByteArray m_bytes;

private:
    void basic(const QString &keyword)
    {
        if (keyword == QLatin1String("Object")) {
            // CORBA::Object's TypeCode, as omniORB writes it: its id and an empty name.
            ulong(TkObjref);
            encapsulated([this] {
                string(QLatin1String(ObjectId));
                string(QString());
            });
            return;
        }
        const SimpleKind *kind = simpleKind(keyword);
        if (!kind)
            fail(QStringLiteral("the type %1 has no TypeCode here").arg(keyword));
        ulong(kind->kind);
    }

    /// An array of several dimensions is an array of arrays of one dimension less.
    void array(const IdlType &type)
    {
        IdlType inner = type;
        inner.dimensions.removeFirst();
        ulong(TkArray);
        encapsulated([&] {
            typeCode(inner.dimensions.isEmpty() ? type.element.front() : inner);
            ulong(type.dimensions.front().toUInt());
        });
    }

    void named(const QString &name)
    {
        if (name == QLatin1String("CORBA::TypeCode")) {
            basic(QStringLiteral("TypeCode"));
            return;
        }
        align(4);
        // omniidl's TypeCodes share a nested type's TypeCode object, which omniORB writes once.
        if (const auto seen = m_offsets.constFind(name); seen != m_offsets.constEnd()) {
            ulong(Indirection);
            ulong(quint32(qint32(*seen - m_bytes.size())));
            return;
        }
        m_offsets.insert(name, m_bytes.size());
        if (const auto it = m_model.typedefs.constFind(name); it != m_model.typedefs.constEnd())
            return header(TkAlias, name, [&] { typeCode(it->type); });
        // Exceptions first: a model may list them as structs too, to convert their members.
        if (const auto it = m_model.exceptions.constFind(name); it != m_model.exceptions.constEnd())
            return header(TkExcept, name, [&] { members(it->members); });
        if (const auto it = m_model.structs.constFind(name); it != m_model.structs.constEnd())
            return header(TkStruct, name, [&] { members(it->members); });
        if (const auto it = m_model.unions.constFind(name); it != m_model.unions.constEnd())
            return header(TkUnion, name, [&] { unionBody(*it); });
        if (const auto it = m_model.enums.constFind(name); it != m_model.enums.constEnd()) {
            return header(TkEnum, name, [&] {
                ulong(quint32(it->enumerators.size()));
                for (const QString &enumerator : it->enumerators)
                    string(enumerator);
            });
        }
        if (m_model.interfaces.contains(name))
            return header(TkObjref, name, [] { });
        fail(QStringLiteral("type '%1' is not declared in the IDL files").arg(name));
    }

    /// A named type's kind, then its repository id, simple name and @p body in an encapsulation.
    template <typename Body>
    void header(Kind kind, const QString &name, Body body)
    {
        ulong(kind);
        encapsulated([&] {
            string(m_model.repositoryId(name));
            string(leafName(name));
            body();
        });
    }

    void members(const QList<IdlMember> &members)
    {
        ulong(quint32(members.size()));
        for (const IdlMember &member : members) {
            string(member.name);
            typeCode(member.type);
        }
    }

    /// The discriminator's TypeCode, the default member's index, then one member per label; the
    /// default member's label is a zero octet.
    void unionBody(const IdlUnion &type)
    {
        typeCode(type.discriminator);
        struct Entry { const IdlUnionCase *unionCase; QString label; };
        QList<Entry> entries;
        qint32 defaultIndex = -1;
        for (const IdlUnionCase &c : type.cases) {
            for (const QString &label : c.labels)
                entries.append({&c, label});
            if (c.isDefault) {
                defaultIndex = qint32(entries.size());
                entries.append({&c, QString()});
            }
        }
        ulong(quint32(defaultIndex));
        ulong(quint32(entries.size()));
        const int size = labelSize(m_model, type.discriminator);
        for (const Entry &entry : entries) {
            if (entry.label.isNull())
                octet(0);
            else
                label(type, entry.label, size);
            string(entry.unionCase->member.name);
            typeCode(entry.unionCase->member.type);
        }
    }

    void label(const IdlUnion &type, const QString &text, int size)
    {
        const QJsonValue value = CdrCodec::labelValue(m_model, type, text);
        quint64 number = quint64(value.toInteger());
        const IdlType discriminator = m_model.resolve(type.discriminator);
        if (const auto it = m_model.enums.constFind(discriminator.name); it != m_model.enums.constEnd())
            number = quint64(it->enumerators.indexOf(value.toString()));
        else if (value.isBool())
            number = value.toBool() ? 1 : 0;
        else if (value.isString())
            number = quint64(uchar(value.toString().at(0).toLatin1()));
        integer(number, size);
    }

    template <typename Body>
    void encapsulated(Body body)
    {
        ulong(0);
        const qsizetype lengthAt = m_bytes.size() - 4;
        const qsizetype outerBase = m_base;
        m_base = m_bytes.size();
        octet(m_little ? 1 : 0);
        body();
        const quint32 length = quint32(m_bytes.size() - m_base);
        m_base = outerBase;
        for (int i = 0; i < 4; ++i)
            m_bytes[lengthAt + i] = char((length >> (8 * (m_little ? i : 3 - i))) & 0xff);
    }

    void align(int size)
    {
        while ((m_bytes.size() - m_base) % size != 0)
            m_bytes.append('\0');
    }

    void integer(quint64 value, int size)
    {
        align(size);
        for (int i = 0; i < size; ++i)
            m_bytes.append(char((value >> (8 * (m_little ? i : size - 1 - i))) & 0xff));
    }

    void ulong(quint32 value) { integer(value, 4); }
    void octet(quint8 value) { m_bytes.append(char(value)); }

    void string(const QString &text)
    {
        const QByteArray bytes = text.toUtf8();
        ulong(quint32(bytes.size() + 1));
        m_bytes.append(bytes).append('\0');
    }

    const IdlModel &m_model;
    const bool m_little;
    qsizetype m_base = 0;
    int m_depth = 0;
    QHash<QString, qsizetype> m_offsets;
};

/// Reads one top-level TypeCode held in memory (see Encoder for its positions).
class Decoder
{
public:
    Decoder(const IdlModel &model, const QByteArray &bytes, bool little)
        : m_model(model)
        , m_bytes(bytes)
        , m_little(little)
    { }

    IdlType typeCode()
    {
        if (++m_depth > MaxDepth)
            fail(QStringLiteral("TypeCodes nested deeper than %1 levels").arg(MaxDepth));
        align(4);
        const qsizetype start = m_position;
        const quint32 kind = ulong();
        IdlType type = kind == Indirection ? indirection() : ofKind(kind, start);
        --m_depth;
        return type;
    }

private:
    IdlType ofKind(quint32 kind, qsizetype start)
    {
        if (const SimpleKind *simple = simpleKind(kind))
            return IdlType::basic(QLatin1String(simple->keyword));
        switch (kind) {
        case TkString:
        case TkWString: {
            IdlType type;
            type.kind = kind == TkString ? IdlType::Kind::String : IdlType::Kind::WString;
            if (const quint32 bound = ulong())
                type.bound = QString::number(bound);
            return type;
        }
        case TkSequence:
            return encapsulated([this] {
                IdlType type;
                type.kind = IdlType::Kind::Sequence;
                type.element.push_back(typeCode());
                if (const quint32 bound = ulong())
                    type.bound = QString::number(bound);
                return type;
            });
        case TkArray:
            return encapsulated([this] { return array(); });
        case TkObjref:
        case TkStruct:
        case TkUnion:
        case TkEnum:
        case TkAlias:
        case TkExcept:
            return encapsulated([&] { return named(kind, start); });
        default:
            fail(QStringLiteral("TypeCodes of kind %1 are not read here").arg(kind));
        }
    }

    IdlType indirection()
    {
        const qsizetype at = m_position;
        const qsizetype target = at + qint32(ulong());
        const auto it = m_seen.constFind(target);
        if (it == m_seen.constEnd())
            fail(QStringLiteral("a TypeCode indirection to offset %1, where no named type starts").arg(target));
        return *it;
    }

    IdlType array()
    {
        const IdlType element = typeCode();
        const QString length = QString::number(ulong());
        IdlType type;
        type.kind = IdlType::Kind::Array;
        if (element.kind == IdlType::Kind::Array) {
            type = element;
            type.dimensions.prepend(length);
        } else {
            type.element.push_back(element);
            type.dimensions.append(length);
        }
        return type;
    }

    /// A named type: the model's type of the same repository id.
    IdlType named(quint32 kind, qsizetype start)
    {
        const QString id = string();
        string(); // the simple name
        const QString name = m_model.scopedNameOf(id);
        if (kind == TkObjref)
            return m_model.interfaces.contains(name) ? IdlType::named(name) : IdlType::basic(QStringLiteral("Object"));
        if (kind == TkAlias && name.isEmpty())
            return typeCode(); // an alias the model lacks stands for its type
        if (name.isEmpty() || (!CdrCodec(m_model).knows(name) && !m_model.exceptions.contains(name)))
            fail(QStringLiteral("an any of type %1, which the IDL files do not declare").arg(id));
        m_seen.insert(start, IdlType::named(name));
        skipParameters(kind);
        return IdlType::named(name);
    }

    /// The rest of a named type's parameters: the model already describes it, but nested
    /// TypeCodes are read so that later indirections find them.
    void skipParameters(quint32 kind)
    {
        if (kind == TkAlias) {
            typeCode();
            return;
        }
        if (kind == TkUnion) {
            const IdlType discriminator = typeCode();
            const qint32 defaultIndex = qint32(ulong());
            const quint32 count = ulong();
            const int size = labelSize(m_model, discriminator);
            for (quint32 i = 0; i < count; ++i) {
                skip(qint32(i) == defaultIndex ? 1 : size);
                string();
                typeCode();
            }
            return;
        }
        const quint32 count = ulong();
        for (quint32 i = 0; i < count; ++i) {
            string();
            if (kind != TkEnum)
                typeCode();
        }
    }

    template <typename Body>
    IdlType encapsulated(Body body)
    {
        const quint32 length = ulong();
        const qsizetype end = m_position + qsizetype(length);
        if (length == 0 || end > m_bytes.size())
            fail(QStringLiteral("a TypeCode encapsulation of %1 bytes where %2 remain").arg(length).arg(m_bytes.size() - m_position));
        const qsizetype outerBase = m_base;
        const bool outerLittle = m_little;
        m_base = m_position;
        m_little = m_bytes.at(m_position++) != 0;
        IdlType type = body();
        m_base = outerBase;
        m_little = outerLittle;
        m_position = end;
        return type;
    }

    void align(int size)
    {
        m_position += (size - (m_position - m_base) % size) % size;
    }

    void skip(int size)
    {
        align(size);
        need(size);
        m_position += size;
    }

    void need(qsizetype size) const
    {
        if (m_position + size > m_bytes.size())
            fail(QStringLiteral("the TypeCode ends early"));
    }

    quint32 ulong()
    {
        align(4);
        need(4);
        quint32 value = 0;
        for (int i = 0; i < 4; ++i)
            value |= quint32(uchar(m_bytes.at(m_position + i))) << (8 * (m_little ? i : 3 - i));
        m_position += 4;
        return value;
    }

    QString string()
    {
        const quint32 length = ulong();
        need(qsizetype(length));
        if (length == 0)
            fail(QStringLiteral("a TypeCode string without its terminating zero"));
        const QString text = QString::fromUtf8(m_bytes.constData() + m_position, qsizetype(length) - 1);
        m_position += length;
        return text;
    }

    const IdlModel &m_model;
    const QByteArray &m_bytes;
    bool m_little;
    qsizetype m_position = 0;
    qsizetype m_base = 0;
    int m_depth = 0;
    QHash<qsizetype, IdlType> m_seen;
};

quint32 readULong(CdrInput &input, bool little)
{
    uchar bytes[4];
    if (!input.read(bytes, 4, 4))
        fail(QStringLiteral("the TypeCode ends early"));
    quint32 value = 0;
    for (int i = 0; i < 4; ++i)
        value |= quint32(bytes[i]) << (8 * (little ? i : 3 - i));
    return value;
}

void appendULong(QByteArray &bytes, quint32 value, bool little)
{
    for (int i = 0; i < 4; ++i)
        bytes.append(char((value >> (8 * (little ? i : 3 - i))) & 0xff));
}

} // namespace

IdlType CdrTypeCode::read(const IdlModel &model, CdrInput &input, bool littleEndian)
{
    // The kind, and for the kinds with an encapsulation that whole, into memory: indirections
    // inside count their offsets from positions within it.
    QByteArray bytes;
    const quint32 kind = readULong(input, littleEndian);
    appendULong(bytes, kind, littleEndian);
    if (kind == Indirection)
        fail(QStringLiteral("an any's TypeCode is an indirection"));
    if (kind == TkFixed)
        fail(QStringLiteral("fixed-point TypeCodes are not read here"));
    const bool encapsulates = kind == TkObjref || (kind >= TkStruct && kind <= TkExcept && kind != TkString)
        || kind > TkWString;
    if (kind == TkString || kind == TkWString || encapsulates) {
        const quint32 length = readULong(input, littleEndian);
        appendULong(bytes, length, littleEndian);
        if (encapsulates) {
            if (!input.available(length))
                fail(QStringLiteral("a TypeCode of %1 bytes where fewer remain").arg(length));
            QByteArray content(qsizetype(length), Qt::Uninitialized);
            if (length > 0 && !input.read(reinterpret_cast<uchar *>(content.data()), int(length), 1))
                fail(QStringLiteral("the TypeCode ends early"));
            bytes.append(content);
        }
    }
    return Decoder(model, bytes, littleEndian).typeCode();
}

void CdrTypeCode::write(const IdlModel &model, const IdlType &type, CdrOutput &output, bool littleEndian)
{
    Encoder encoder(model, littleEndian);
    encoder.typeCode(type);
    output.write(reinterpret_cast<const uchar *>(encoder.m_bytes.constData()), int(encoder.m_bytes.size()), 4);
}

bool CdrTypeCode::isTypeCode(const IdlType &type)
{
    return (type.kind == IdlType::Kind::Basic && type.name == QLatin1String("TypeCode"))
        || (type.kind == IdlType::Kind::Named && type.name == QLatin1String("CORBA::TypeCode"));
}

bool CdrTypeCode::isEmpty(const IdlType &type)
{
    return type.kind == IdlType::Kind::Basic && (type.name == QLatin1String("null") || type.name == QLatin1String("void"));
}

namespace {

/// Reads IdlType::toString()'s form.
class TextParser
{
public:
    TextParser(const IdlModel &model, const QString &text)
        : m_model(model)
        , m_text(text)
    { }

    IdlType whole()
    {
        IdlType type = withDimensions();
        if (m_position != m_text.size())
            fail(QStringLiteral("'%1' is not a type").arg(m_text));
        return type;
    }

private:
    IdlType withDimensions()
    {
        const IdlType element = single();
        QStringList dimensions;
        while (take(QStringLiteral("[")))
            dimensions.append(number(QStringLiteral("]")));
        if (dimensions.isEmpty())
            return element;
        IdlType type;
        type.kind = IdlType::Kind::Array;
        type.element.push_back(element);
        type.dimensions = dimensions;
        return type;
    }

    IdlType single()
    {
        if (take(QStringLiteral("sequence<"))) {
            IdlType type;
            type.kind = IdlType::Kind::Sequence;
            type.element.push_back(withDimensions());
            if (take(QStringLiteral(",")))
                type.bound = number(QStringLiteral(">"));
            else if (!take(QStringLiteral(">")))
                fail(QStringLiteral("'%1' is not a type").arg(m_text));
            return type;
        }
        for (const auto &[word, kind] : {std::pair{"wstring", IdlType::Kind::WString}, std::pair{"string", IdlType::Kind::String}}) {
            if (take(QLatin1String(word))) {
                IdlType type;
                type.kind = kind;
                if (take(QStringLiteral("<")))
                    type.bound = number(QStringLiteral(">"));
                return type;
            }
        }
        static const QRegularExpression name(QStringLiteral("(unsigned )?(long )?[A-Za-z_][A-Za-z_0-9]*(::[A-Za-z_][A-Za-z_0-9]*)*"));
        const QRegularExpressionMatch match = name.match(m_text, m_position, QRegularExpression::NormalMatch,
                                                         QRegularExpression::AnchorAtOffsetMatchOption);
        if (!match.hasMatch())
            fail(QStringLiteral("'%1' is not a type").arg(m_text));
        m_position += match.capturedLength();
        return nameType(match.captured());
    }

    IdlType nameType(const QString &word) const
    {
        if (simpleKind(word) || word == QLatin1String("Object") || word == QLatin1String("long double"))
            return IdlType::basic(word);
        if (m_model.find(word) || word == QLatin1String("CORBA::TypeCode"))
            return IdlType::named(word);
        fail(QStringLiteral("type '%1' is not declared in the IDL files").arg(word));
    }

    QString number(const QString &end)
    {
        const qsizetype close = m_text.indexOf(end, m_position);
        bool ok = false;
        const QString digits = m_text.mid(m_position, close - m_position).trimmed();
        digits.toUInt(&ok);
        if (close < 0 || !ok)
            fail(QStringLiteral("'%1' is not a type").arg(m_text));
        m_position = close + end.size();
        return digits;
    }

    bool take(const QString &word)
    {
        while (m_position < m_text.size() && m_text.at(m_position) == QLatin1Char(' '))
            ++m_position;
        if (!m_text.mid(m_position).startsWith(word))
            return false;
        m_position += word.size();
        return true;
    }

    const IdlModel &m_model;
    const QString m_text;
    qsizetype m_position = 0;
};

} // namespace

IdlType CdrTypeCode::fromText(const IdlModel &model, const QString &text)
{
    return TextParser(model, text).whole();
}

} // namespace Codegen
