// SPDX-License-Identifier: MIT
#include "pyvalueconverter.h"
#include "pyiorform.h"
#include "pyobjectref.h"

#include <rtmruntime/corbautil.h>

#include "cdrcodec.h"
#include "cdrtypecode.h"

#include <QJsonArray>
#include <utility>
#include <QJsonObject>

#include <cmath>

namespace py = pybind11;
using Codegen::IdlType;

namespace RtPython {

namespace {

bool isFloating(const QString &keyword)
{
    return keyword == QLatin1String("float") || keyword == QLatin1String("double");
}

bool isCharacter(const QString &keyword)
{
    return keyword == QLatin1String("char") || keyword == QLatin1String("wchar");
}

bool isBasic(const IdlType &type, const char *keyword)
{
    return type.kind == IdlType::Kind::Basic && type.name == QLatin1String(keyword);
}

// The codec writes non-finite floating values as these strings.
QJsonValue floatingToJson(double number)
{
    if (std::isnan(number))
        return QStringLiteral("NaN");
    if (std::isinf(number))
        return number > 0 ? QStringLiteral("Infinity") : QStringLiteral("-Infinity");
    return number;
}

double floatingFromJson(const QJsonValue &value)
{
    if (!value.isString())
        return value.toDouble();
    const QString text = value.toString();
    if (text == QLatin1String("NaN"))
        return std::nan("");
    return text.startsWith(QLatin1Char('-')) ? -INFINITY : INFINITY;
}

} // namespace

PyValueConverter::PyValueConverter(const Codegen::IdlModel &model, py::dict classes)
    : m_model(model)
    , m_classes(std::move(classes))
{
}

void PyValueConverter::refuse(const QString &path, const QString &reason)
{
    throw py::type_error((path + QStringLiteral(": ") + reason).toStdString());
}

QJsonValue PyValueConverter::toJson(const IdlType &written, py::handle value, const QString &path) const
{
    const IdlType type = m_model.resolve(written);
    if (Codegen::CdrTypeCode::isTypeCode(type))
        return typeCodeToJson(value, path);
    switch (type.kind) {
    case IdlType::Kind::Basic:
        return basicToJson(type.name, value, path);
    case IdlType::Kind::String:
    case IdlType::Kind::WString:
        if (!py::isinstance<py::str>(value))
            refuse(path, QStringLiteral("a str is needed"));
        return QString::fromStdString(value.cast<std::string>());
    case IdlType::Kind::Sequence:
        return listToJson(type.element.front(), value, path);
    case IdlType::Kind::Array: {
        // An array of several dimensions is a list of arrays of one dimension less.
        IdlType inner = type;
        inner.dimensions.removeFirst();
        return listToJson(inner.dimensions.isEmpty() ? type.element.front() : inner, value, path);
    }
    case IdlType::Kind::Named:
        return namedToJson(type.name, value, path);
    case IdlType::Kind::Fixed:
        break;
    }
    refuse(path, QStringLiteral("the type %1 is not supported yet").arg(type.toString()));
}

QJsonValue PyValueConverter::basicToJson(const QString &keyword, py::handle value, const QString &path) const
{
    if (keyword == QLatin1String("boolean"))
        return bool(py::bool_(py::reinterpret_borrow<py::object>(value)));
    if (isCharacter(keyword)) {
        if (!py::isinstance<py::str>(value) || py::len(value) != 1)
            refuse(path, QStringLiteral("a str of one character is needed"));
        return QString::fromStdString(value.cast<std::string>());
    }
    if (isFloating(keyword)) {
        if (!py::isinstance<py::float_>(value) && !py::isinstance<py::int_>(value))
            refuse(path, QStringLiteral("a number is needed"));
        return floatingToJson(value.cast<double>());
    }
    if (keyword == QLatin1String("Object"))
        return referenceToJson(value, path);
    if (keyword == QLatin1String("any"))
        return anyToJson(value, path);
    if (keyword == QLatin1String("long double"))
        refuse(path, QStringLiteral("the type %1 is not supported yet").arg(keyword));
    if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
        refuse(path, QStringLiteral("an int is needed"));
    return QJsonValue(qint64(value.cast<long long>()));
}

QJsonValue PyValueConverter::listToJson(const IdlType &element, py::handle value, const QString &path) const
{
    QJsonArray items;
    const IdlType resolved = m_model.resolve(element);
    if (isBasic(resolved, "octet") && (py::isinstance<py::bytes>(value) || py::isinstance<py::bytearray>(value))) {
        for (const char byte : value.cast<std::string>())
            items.append(int(static_cast<unsigned char>(byte)));
        return items;
    }
    if (resolved.kind == IdlType::Kind::Basic && isCharacter(resolved.name) && py::isinstance<py::str>(value)) {
        for (const QChar c : QString::fromStdString(value.cast<std::string>()))
            items.append(QString(c));
        return items;
    }
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
        refuse(path, QStringLiteral("a list is needed"));
    int index = 0;
    for (const py::handle item : value)
        items.append(toJson(element, item, path + QStringLiteral("[%1]").arg(index++)));
    return items;
}

QJsonValue PyValueConverter::namedToJson(const QString &name, py::handle value, const QString &path) const
{
    if (const auto it = m_model.structs.constFind(name); it != m_model.structs.constEnd()) {
        QJsonObject object;
        for (const Codegen::IdlMember &member : it->members) {
            const std::string attribute = member.name.toStdString();
            if (!py::hasattr(value, attribute.c_str()))
                refuse(path, QStringLiteral("%1 has no member '%2'").arg(name, member.name));
            object.insert(member.name, toJson(member.type, value.attr(attribute.c_str()),
                                              path + QLatin1Char('.') + member.name));
        }
        return object;
    }
    if (const auto it = m_model.enums.constFind(name); it != m_model.enums.constEnd())
        return enumToJson(*it, value, path);
    if (const auto it = m_model.unions.constFind(name); it != m_model.unions.constEnd())
        return unionToJson(*it, value, path);
    if (m_model.interfaces.contains(name))
        return referenceToJson(value, path);
    refuse(path, QStringLiteral("the type %1 is not supported yet").arg(name));
}

QJsonValue PyValueConverter::unionToJson(const Codegen::IdlUnion &type, py::handle value, const QString &path) const
{
    if (!py::hasattr(value, "_d") || !py::hasattr(value, "_v"))
        refuse(path, QStringLiteral("a %1 (with _d and _v) is needed").arg(type.scopedName));
    const QJsonValue discriminator = toJson(type.discriminator, value.attr("_d"), path + QStringLiteral("._d"));
    QJsonObject object{{QStringLiteral("_d"), discriminator}};
    if (const Codegen::IdlUnionCase *chosen = Codegen::CdrCodec::unionCase(type, discriminator))
        object.insert(chosen->member.name,
                      toJson(chosen->member.type, value.attr("_v"), path + QLatin1Char('.') + chosen->member.name));
    return object;
}

QJsonValue PyValueConverter::referenceToJson(py::handle value, const QString &path) const
{
    if (value.is_none())
        return QJsonValue::Null;
    // A reference to call (a generated _objref_ class, as a call or string_to_object gives it).
    if (py::isinstance(value, py::module_::import("omniORB.CORBA").attr("Object"))
        && py::isinstance<PyObjectRef>(value.attr("_obj")))
        return IorForm::fromIor(value.attr("_obj").cast<const PyObjectRef &>().ior());
    if (!py::isinstance(value, referenceClass()))
        refuse(path, QStringLiteral("None or an object reference is needed"));
    QJsonArray profiles;
    for (const py::handle profile : value.attr("_profiles")) {
        const py::tuple pair = py::reinterpret_borrow<py::tuple>(profile);
        profiles.append(QJsonObject{{QStringLiteral("tag"), qint64(pair[0].cast<long long>())},
                                    {QStringLiteral("data"), QString::fromStdString(pair[1].attr("hex")().cast<std::string>())}});
    }
    return QJsonObject{{QStringLiteral("type_id"), QString::fromStdString(value.attr("_NP_RepositoryId").cast<std::string>())},
                       {QStringLiteral("profiles"), profiles}};
}

namespace {

/// Set while a CallableReferences lives in this thread.
thread_local bool t_callableReferences = false;

} // namespace

PyValueConverter::CallableReferences::CallableReferences()
    : m_before(std::exchange(t_callableReferences, true))
{ }

PyValueConverter::CallableReferences::~CallableReferences()
{
    t_callableReferences = m_before;
}

py::object PyValueConverter::referenceToPython(const QJsonValue &value, const QString &interfaceName) const
{
    if (!value.isObject())
        return py::none();
    // A reference of an interface whose stub module is imported is one to call, as omniORBpy gives it;
    // so is any reference a call returns (a CORBA::Object of the type its IOR names, to _narrow).
    if (!interfaceName.isEmpty() || t_callableReferences) {
        const py::object omniORB = py::module_::import("omniORB");
        const QString typeId = interfaceName.isEmpty() ? value[QStringLiteral("type_id")].toString()
                                                       : m_model.repositoryId(interfaceName);
        const py::object cls = omniORB.attr("objrefClass")(typeId.toStdString(), t_callableReferences);
        if (!cls.is(omniORB.attr("CORBA").attr("Object")) || t_callableReferences) {
            CORBA::Object_var object = Runtime::theOrb()->string_to_object(IorForm::toIor(value).c_str());
            return cls(py::cast(PyObjectRef(object.in())));
        }
    }
    py::list profiles;
    for (const QJsonValue &profile : value[QStringLiteral("profiles")].toArray()) {
        const QByteArray data = QByteArray::fromHex(profile[QStringLiteral("data")].toString().toLatin1());
        profiles.append(py::make_tuple(profile[QStringLiteral("tag")].toInteger(), py::bytes(data.constData(), size_t(data.size()))));
    }
    return referenceClass()(value[QStringLiteral("type_id")].toString().toStdString(), profiles);
}

Codegen::IdlType PyValueConverter::typeNamed(const QString &name, const QString &path) const
{
    try {
        return Codegen::CdrTypeCode::fromText(m_model, name);
    } catch (const Codegen::CdrTypeCode::Error &error) {
        refuse(path, error.message);
    }
}

QJsonValue PyValueConverter::anyToJson(py::handle value, const QString &path) const
{
    // omniORBpy's CORBA.Any: its TypeCode (here naming the IDL type) and its value.
    if (value.is_none())
        return QJsonValue::Null;
    if (!py::hasattr(value, "_t") || !py::hasattr(value, "_v"))
        refuse(path, QStringLiteral("a CORBA.Any is needed (CORBA.Any(CORBA.TC_long, 5), omniORB.any.to_any(5))"));
    const QString name = typeCodeToJson(value.attr("_t"), path).toString();
    const IdlType type = typeNamed(name, path);
    return QJsonObject{{QStringLiteral("type"), name},
                       {QStringLiteral("value"), Codegen::CdrTypeCode::isEmpty(type)
                                                     ? QJsonValue::Null : toJson(type, value.attr("_v"), path)}};
}

py::object PyValueConverter::anyToPython(const QJsonValue &value) const
{
    const QString name = value[QStringLiteral("type")].toString(QStringLiteral("null"));
    const IdlType type = typeNamed(name, QString());
    const py::object content
        = Codegen::CdrTypeCode::isEmpty(type) ? py::none() : toPython(type, value[QStringLiteral("value")]);
    return py::module_::import("omniORB.CORBA").attr("Any")(typeCodeToPython(name), content);
}

QJsonValue PyValueConverter::typeCodeToJson(py::handle value, const QString &path) const
{
    if (!py::hasattr(value, "_name"))
        refuse(path, QStringLiteral("a CORBA.TypeCode is needed (CORBA.TC_long, RTC._tc_Time)"));
    const QString name = QString::fromStdString(value.attr("_name").cast<std::string>());
    typeNamed(name, path);
    return name;
}

py::object PyValueConverter::typeCodeToPython(const QString &name)
{
    return py::module_::import("omniORB.CORBA").attr("TypeCode")(name.toStdString());
}

py::object PyValueConverter::referenceClass()
{
    return py::module_::import("_rtstudio_interfaces").attr("ObjectReference");
}

QJsonValue PyValueConverter::enumToJson(const Codegen::IdlEnum &type, py::handle value, const QString &path) const
{
    // omniORBpy's enum items carry their value in _v; a plain int is taken as that value.
    const py::object number = py::hasattr(value, "_v") ? value.attr("_v") : py::reinterpret_borrow<py::object>(value);
    if (!py::isinstance<py::int_>(number))
        refuse(path, QStringLiteral("an item of %1 is needed").arg(type.scopedName));
    const long long index = number.cast<long long>();
    if (index < 0 || index >= type.enumerators.size())
        refuse(path, QStringLiteral("%1 has no item %2").arg(type.scopedName).arg(index));
    return type.enumerators.at(int(index));
}

py::object PyValueConverter::toPython(const IdlType &written, const QJsonValue &value) const
{
    const IdlType type = m_model.resolve(written);
    if (Codegen::CdrTypeCode::isTypeCode(type))
        return typeCodeToPython(value.toString(QStringLiteral("null")));
    switch (type.kind) {
    case IdlType::Kind::Basic:
        return basicToPython(type.name, value);
    case IdlType::Kind::String:
    case IdlType::Kind::WString:
        return py::str(value.toString().toStdString());
    case IdlType::Kind::Sequence:
        return listToPython(type.element.front(), value);
    case IdlType::Kind::Array: {
        IdlType inner = type;
        inner.dimensions.removeFirst();
        return listToPython(inner.dimensions.isEmpty() ? type.element.front() : inner, value);
    }
    case IdlType::Kind::Named:
        return namedToPython(type.name, value);
    case IdlType::Kind::Fixed:
        break;
    }
    return py::none();
}

py::object PyValueConverter::basicToPython(const QString &keyword, const QJsonValue &value) const
{
    if (keyword == QLatin1String("boolean"))
        return py::bool_(value.toBool());
    if (isCharacter(keyword))
        return py::str(value.toString().toStdString());
    if (keyword == QLatin1String("Object"))
        return referenceToPython(value);
    if (keyword == QLatin1String("any"))
        return anyToPython(value);
    if (isFloating(keyword))
        return py::float_(floatingFromJson(value));
    return py::int_(static_cast<long long>(value.toInteger()));
}

py::object PyValueConverter::listToPython(const IdlType &element, const QJsonValue &value) const
{
    const QJsonArray items = value.toArray();
    const IdlType resolved = m_model.resolve(element);
    if (isBasic(resolved, "octet")) {
        std::string bytes;
        for (const QJsonValue &item : items)
            bytes.push_back(char(item.toInt()));
        return py::bytes(bytes);
    }
    if (resolved.kind == IdlType::Kind::Basic && isCharacter(resolved.name)) {
        QString text;
        for (const QJsonValue &item : items)
            text += item.toString();
        return py::str(text.toStdString());
    }
    py::list list;
    for (const QJsonValue &item : items)
        list.append(toPython(element, item));
    return std::move(list);
}

py::object PyValueConverter::namedToPython(const QString &name, const QJsonValue &value) const
{
    if (const auto it = m_model.structs.constFind(name); it != m_model.structs.constEnd()) {
        const py::object cls = classOf(name);
        // Made without __init__, as omniORBpy's unmarshalling does: members are set one by one.
        py::object object = cls.attr("__new__")(cls);
        const QJsonObject members = value.toObject();
        for (const Codegen::IdlMember &member : it->members)
            py::setattr(object, member.name.toStdString().c_str(), toPython(member.type, members.value(member.name)));
        return object;
    }
    if (const auto it = m_model.enums.constFind(name); it != m_model.enums.constEnd())
        return classOf(name).attr("_items")[py::int_(it->enumerators.indexOf(value.toString()))];
    if (const auto it = m_model.unions.constFind(name); it != m_model.unions.constEnd()) {
        const py::object cls = classOf(name);
        py::object object = cls.attr("__new__")(cls);
        const QJsonValue discriminator = value[QStringLiteral("_d")];
        const Codegen::IdlUnionCase *chosen = Codegen::CdrCodec::unionCase(*it, discriminator);
        py::setattr(object, "_d", toPython(it->discriminator, discriminator));
        py::setattr(object, "_v", chosen ? toPython(chosen->member.type, value[chosen->member.name]) : py::none());
        return object;
    }
    if (m_model.interfaces.contains(name))
        return referenceToPython(value, name);
    return py::none();
}

py::object PyValueConverter::classOf(const QString &name) const
{
    const py::str key(name.toStdString());
    if (!m_classes.contains(key))
        throw py::type_error(("no Python class for the IDL type " + name).toStdString());
    return m_classes[key];
}

} // namespace RtPython
