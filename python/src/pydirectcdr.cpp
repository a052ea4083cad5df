// SPDX-License-Identifier: MIT
#include "pydirectcdr.h"

#include <QSysInfo>

#include <algorithm>
#include <cstring>
#include <limits>

namespace py = pybind11;
using Codegen::IdlType;

namespace RtPython {

namespace {

/// Thrown where a value does not fit or bytes do not decode: the caller takes the converter's way.
struct NotDirect
{
};

constexpr bool HostLittle = QSysInfo::ByteOrder == QSysInfo::LittleEndian;
constexpr int MaxDepth = 64;

enum class Number { Boolean, Char, Octet, Short, UShort, Long, ULong, LongLong, ULongLong, Float, Double };

std::optional<Number> numberKind(const QString &keyword)
{
    static const QHash<QString, Number> kinds{
        {QStringLiteral("boolean"), Number::Boolean}, {QStringLiteral("char"), Number::Char},
        {QStringLiteral("octet"), Number::Octet}, {QStringLiteral("short"), Number::Short},
        {QStringLiteral("unsigned short"), Number::UShort}, {QStringLiteral("long"), Number::Long},
        {QStringLiteral("unsigned long"), Number::ULong}, {QStringLiteral("long long"), Number::LongLong},
        {QStringLiteral("unsigned long long"), Number::ULongLong}, {QStringLiteral("float"), Number::Float},
        {QStringLiteral("double"), Number::Double},
    };
    const auto it = kinds.constFind(keyword);
    return it == kinds.constEnd() ? std::nullopt : std::optional<Number>(*it);
}

} // namespace

/// Writes CDR (alignment counted from the start of the sample) in the byte order asked for.
class DirectWriter
{
public:
    DirectWriter(const PyDirectCdr &cdr, std::vector<unsigned char> &out, bool little)
        : m_cdr(cdr)
        , m_out(out)
        , m_swap(little != HostLittle)
    { }

    void write(const IdlType &written, py::handle value)
    {
        const IdlType type = m_cdr.m_model.resolve(written);
        switch (type.kind) {
        case IdlType::Kind::Basic:
            return writeNumber(*numberKind(type.name), value);
        case IdlType::Kind::String:
            return writeString(type, value);
        case IdlType::Kind::Sequence:
            return writeSequence(type, value);
        case IdlType::Kind::Named:
            return writeNamed(type.name, value);
        default:
            throw NotDirect{};
        }
    }

private:
    template <typename T>
    void put(T value)
    {
        while (m_out.size() % sizeof(T) != 0)
            m_out.push_back(0);
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        if (m_swap)
            std::reverse(bytes, bytes + sizeof(T));
        m_out.insert(m_out.end(), bytes, bytes + sizeof(T));
    }

    static long long integer(py::handle value, long long low, long long high)
    {
        if (!PyLong_Check(value.ptr()) || PyBool_Check(value.ptr()))
            throw NotDirect{};
        const long long number = PyLong_AsLongLong(value.ptr());
        if ((number == -1 && PyErr_Occurred()) || number < low || number > high) {
            PyErr_Clear();
            throw NotDirect{};
        }
        return number;
    }

    static double floating(py::handle value)
    {
        if (PyFloat_Check(value.ptr()))
            return PyFloat_AS_DOUBLE(value.ptr());
        if (!PyLong_Check(value.ptr()))
            throw NotDirect{};
        const double number = PyLong_AsDouble(value.ptr());
        if (number == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            throw NotDirect{};
        }
        return number;
    }

    void writeNumber(Number kind, py::handle value)
    {
        switch (kind) {
        case Number::Boolean:
            return put<quint8>(PyObject_IsTrue(value.ptr()) == 1 ? 1 : 0);
        case Number::Char: {
            Py_ssize_t length = 0;
            const char *text = PyUnicode_Check(value.ptr()) ? PyUnicode_AsUTF8AndSize(value.ptr(), &length) : nullptr;
            if (!text || length != 1)
                throw NotDirect{};
            return put<char>(text[0]);
        }
        case Number::Octet:
            return put<quint8>(quint8(integer(value, 0, 255)));
        case Number::Short:
            return put<qint16>(qint16(integer(value, -32768, 32767)));
        case Number::UShort:
            return put<quint16>(quint16(integer(value, 0, 65535)));
        case Number::Long:
            return put<qint32>(qint32(integer(value, std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max())));
        case Number::ULong:
            return put<quint32>(quint32(integer(value, 0, std::numeric_limits<quint32>::max())));
        case Number::LongLong:
            return put<qint64>(integer(value, std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max()));
        case Number::ULongLong: {
            if (!PyLong_Check(value.ptr()) || PyBool_Check(value.ptr()))
                throw NotDirect{};
            const unsigned long long number = PyLong_AsUnsignedLongLong(value.ptr());
            if (PyErr_Occurred()) {
                PyErr_Clear();
                throw NotDirect{};
            }
            return put<quint64>(number);
        }
        case Number::Float:
            return put<float>(float(floating(value)));
        case Number::Double:
            return put<double>(floating(value));
        }
    }

    void writeString(const IdlType &type, py::handle value)
    {
        Py_ssize_t length = 0;
        const char *text = PyUnicode_Check(value.ptr()) ? PyUnicode_AsUTF8AndSize(value.ptr(), &length) : nullptr;
        if (!text || (!type.bound.isEmpty() && length > type.bound.toLongLong()))
            throw NotDirect{};
        put<quint32>(quint32(length + 1));
        m_out.insert(m_out.end(), text, text + length + 1);
    }

    void writeSequence(const IdlType &type, py::handle value)
    {
        const IdlType element = m_cdr.m_model.resolve(type.element.front());
        const bool octets = element.kind == IdlType::Kind::Basic && element.name == QLatin1String("octet");
        if (octets && (PyBytes_Check(value.ptr()) || PyByteArray_Check(value.ptr()))) {
            const std::string bytes = value.cast<std::string>();
            checkBound(type, bytes.size());
            put<quint32>(quint32(bytes.size()));
            m_out.insert(m_out.end(), bytes.begin(), bytes.end());
            return;
        }
        const bool chars = element.kind == IdlType::Kind::Basic && element.name == QLatin1String("char");
        if (chars && PyUnicode_Check(value.ptr())) {
            Py_ssize_t length = 0;
            const char *text = PyUnicode_AsUTF8AndSize(value.ptr(), &length);
            if (!text || PyUnicode_GetLength(value.ptr()) != length)
                throw NotDirect{}; // one byte per character only
            checkBound(type, size_t(length));
            put<quint32>(quint32(length));
            m_out.insert(m_out.end(), text, text + length);
            return;
        }
        if (PyUnicode_Check(value.ptr()) || !PySequence_Check(value.ptr()))
            throw NotDirect{};
        const py::sequence items = py::reinterpret_borrow<py::sequence>(value);
        checkBound(type, size_t(py::len(items)));
        put<quint32>(quint32(py::len(items)));
        // Numbers: the element type is looked up once, not once per element.
        if (const std::optional<Number> number = element.kind == IdlType::Kind::Basic ? numberKind(element.name)
                                                                                     : std::nullopt) {
            for (const py::handle item : items)
                writeNumber(*number, item);
            return;
        }
        for (const py::handle item : items)
            write(element, item);
    }

    static void checkBound(const IdlType &type, size_t count)
    {
        if (!type.bound.isEmpty() && count > type.bound.toULongLong())
            throw NotDirect{};
    }

    void writeNamed(const QString &name, py::handle value)
    {
        if (const auto it = m_cdr.m_model.structs.constFind(name); it != m_cdr.m_model.structs.constEnd()) {
            const std::vector<py::str> &names = m_cdr.memberNames(name);
            for (size_t i = 0; i < names.size(); ++i) {
                PyObject *member = PyObject_GetAttr(value.ptr(), names[i].ptr());
                if (!member) {
                    PyErr_Clear();
                    throw NotDirect{};
                }
                const py::object owned = py::reinterpret_steal<py::object>(member);
                write(it->members.at(qsizetype(i)).type, owned);
            }
            return;
        }
        if (const auto it = m_cdr.m_model.enums.constFind(name); it != m_cdr.m_model.enums.constEnd()) {
            const py::object number = py::hasattr(value, "_v") ? py::object(value.attr("_v"))
                                                                : py::reinterpret_borrow<py::object>(value);
            return put<quint32>(quint32(integer(number, 0, it->enumerators.size() - 1)));
        }
        throw NotDirect{};
    }

    const PyDirectCdr &m_cdr;
    std::vector<unsigned char> &m_out;
    bool m_swap;
};

/// Reads CDR written as DirectWriter writes it, into new Python values.
class DirectReader
{
public:
    DirectReader(const PyDirectCdr &cdr, const unsigned char *data, size_t size, bool little)
        : m_cdr(cdr)
        , m_data(data)
        , m_size(size)
        , m_swap(little != HostLittle)
    { }

    py::object read(const IdlType &written)
    {
        const IdlType type = m_cdr.m_model.resolve(written);
        switch (type.kind) {
        case IdlType::Kind::Basic:
            return readNumber(*numberKind(type.name));
        case IdlType::Kind::String: {
            const quint32 length = get<quint32>();
            if (length == 0)
                throw NotDirect{};
            const char *text = take(length);
            if (text[length - 1] != '\0')
                throw NotDirect{};
            return py::reinterpret_steal<py::object>(checked(PyUnicode_DecodeUTF8(text, length - 1, "replace")));
        }
        case IdlType::Kind::Sequence:
            return readSequence(type);
        case IdlType::Kind::Named:
            return readNamed(type.name);
        default:
            throw NotDirect{};
        }
    }

    bool atEnd() const { return m_offset == m_size; }

private:
    const char *take(size_t count)
    {
        if (count > m_size - m_offset)
            throw NotDirect{};
        const char *at = reinterpret_cast<const char *>(m_data + m_offset);
        m_offset += count;
        return at;
    }

    template <typename T>
    T get()
    {
        m_offset = (m_offset + sizeof(T) - 1) / sizeof(T) * sizeof(T);
        if (m_offset > m_size)
            throw NotDirect{};
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, take(sizeof(T)), sizeof(T));
        if (m_swap)
            std::reverse(bytes, bytes + sizeof(T));
        T value;
        std::memcpy(&value, bytes, sizeof(T));
        return value;
    }

    static PyObject *checked(PyObject *object)
    {
        if (!object) {
            PyErr_Clear();
            throw NotDirect{};
        }
        return object;
    }

    py::object readNumber(Number kind)
    {
        switch (kind) {
        case Number::Boolean:
            return py::bool_(get<quint8>() != 0);
        case Number::Char: {
            const char c = get<char>();
            return py::reinterpret_steal<py::object>(checked(PyUnicode_DecodeLatin1(&c, 1, nullptr)));
        }
        case Number::Octet:
            return py::int_(get<quint8>());
        case Number::Short:
            return py::int_(get<qint16>());
        case Number::UShort:
            return py::int_(get<quint16>());
        case Number::Long:
            return py::int_(get<qint32>());
        case Number::ULong:
            return py::int_(get<quint32>());
        case Number::LongLong:
            return py::int_(get<qint64>());
        case Number::ULongLong:
            return py::int_(get<quint64>());
        case Number::Float:
            return py::float_(get<float>());
        case Number::Double:
            return py::float_(get<double>());
        }
        throw NotDirect{};
    }

    py::object readSequence(const IdlType &type)
    {
        const quint32 count = get<quint32>();
        if (count > m_size - m_offset || (!type.bound.isEmpty() && count > type.bound.toULongLong()))
            throw NotDirect{};
        const IdlType element = m_cdr.m_model.resolve(type.element.front());
        if (element.kind == IdlType::Kind::Basic && element.name == QLatin1String("octet"))
            return py::bytes(take(count), count);
        if (element.kind == IdlType::Kind::Basic && element.name == QLatin1String("char"))
            return py::reinterpret_steal<py::object>(checked(PyUnicode_DecodeLatin1(take(count), count, nullptr)));
        py::list items(count);
        // Numbers: the element type is looked up once, not once per element.
        if (const std::optional<Number> number = element.kind == IdlType::Kind::Basic ? numberKind(element.name)
                                                                                     : std::nullopt) {
            for (quint32 i = 0; i < count; ++i)
                PyList_SET_ITEM(items.ptr(), Py_ssize_t(i), readNumber(*number).release().ptr());
            return std::move(items);
        }
        for (quint32 i = 0; i < count; ++i)
            items[i] = read(element);
        return std::move(items);
    }

    py::object readNamed(const QString &name)
    {
        const py::object cls = m_cdr.m_classes[py::str(name.toStdString())];
        if (const auto it = m_cdr.m_model.structs.constFind(name); it != m_cdr.m_model.structs.constEnd()) {
            // Made without __init__, as omniORBpy's unmarshalling does: members are set one by one.
            py::object object = cls.attr("__new__")(cls);
            const std::vector<py::str> &names = m_cdr.memberNames(name);
            for (size_t i = 0; i < names.size(); ++i) {
                const py::object member = read(it->members.at(qsizetype(i)).type);
                if (PyObject_SetAttr(object.ptr(), names[i].ptr(), member.ptr()) != 0)
                    throw py::error_already_set();
            }
            return object;
        }
        if (const auto it = m_cdr.m_model.enums.constFind(name); it != m_cdr.m_model.enums.constEnd()) {
            const quint32 index = get<quint32>();
            if (index >= quint32(it->enumerators.size()))
                throw NotDirect{};
            return cls.attr("_items")[py::int_(index)];
        }
        throw NotDirect{};
    }

    const PyDirectCdr &m_cdr;
    const unsigned char *m_data;
    size_t m_size;
    size_t m_offset = 0;
    bool m_swap;
};

PyDirectCdr::PyDirectCdr(const Codegen::IdlModel &model, py::dict classes)
    : m_model(model)
    , m_classes(std::move(classes))
{ }

bool PyDirectCdr::handles(const QString &typeName) const
{
    const auto it = m_handles.constFind(typeName);
    if (it != m_handles.constEnd())
        return *it;
    const bool handled = handlesType(IdlType::named(typeName), 0);
    m_handles.insert(typeName, handled);
    return handled;
}

bool PyDirectCdr::handlesType(const IdlType &written, int depth) const
{
    if (depth > MaxDepth)
        return false;
    const IdlType type = m_model.resolve(written);
    switch (type.kind) {
    case IdlType::Kind::Basic:
        return numberKind(type.name).has_value();
    case IdlType::Kind::String:
        return true;
    case IdlType::Kind::Sequence:
        return handlesType(type.element.front(), depth + 1);
    case IdlType::Kind::Named: {
        const py::str key(type.name.toStdString());
        if (const auto it = m_model.structs.constFind(type.name); it != m_model.structs.constEnd()) {
            if (!m_classes.contains(key))
                return false;
            for (const Codegen::IdlMember &member : it->members) {
                if (!handlesType(member.type, depth + 1))
                    return false;
            }
            return true;
        }
        return m_model.enums.contains(type.name) && m_classes.contains(key);
    }
    default:
        return false;
    }
}

const std::vector<py::str> &PyDirectCdr::memberNames(const QString &name) const
{
    auto it = m_memberNames.find(name);
    if (it == m_memberNames.end()) {
        std::vector<py::str> names;
        for (const Codegen::IdlMember &member : m_model.structs.value(name).members)
            names.emplace_back(member.name.toStdString());
        it = m_memberNames.insert(name, std::move(names));
    }
    return *it;
}

bool PyDirectCdr::encode(const QString &typeName, py::handle value, bool littleEndian,
                         std::vector<unsigned char> *out) const
{
    const size_t before = out->size();
    try {
        DirectWriter(*this, *out, littleEndian).write(IdlType::named(typeName), value);
        return true;
    } catch (const NotDirect &) {
        out->resize(before);
        return false;
    }
}

std::optional<py::object> PyDirectCdr::decode(const QString &typeName, const unsigned char *data, size_t size,
                                              bool littleEndian) const
{
    try {
        DirectReader reader(*this, data, size, littleEndian);
        py::object value = reader.read(IdlType::named(typeName));
        if (!reader.atEnd())
            return std::nullopt;
        return value;
    } catch (const NotDirect &) {
        return std::nullopt;
    }
}

} // namespace RtPython
