// SPDX-License-Identifier: MIT
// What omniORBpy's CORBA.TypeCode tells of a type (kind, id, members, content), from the IDL model
// the runtime marshals by; a TypeCode is the name of its IDL type (Codegen::CdrTypeCode's text).
#include "bindings.h"
#include "pydatatypes.h"

#include "cdrcodec.h"
#include "cdrtypecode.h"

#include <QJsonValue>

namespace py = pybind11;
using Codegen::IdlType;

namespace RtPython {

namespace {

/// CORBA's TCKind of the types with parameters, as CORBA.tk_* numbers them.
enum TcKind { TkObjref = 14, TkStruct = 15, TkUnion = 16, TkEnum = 17, TkString = 18, TkSequence = 19,
              TkArray = 20, TkAlias = 21, TkExcept = 22, TkWString = 27 };

py::list memberList(const QList<Codegen::IdlMember> &members)
{
    py::list list;
    for (const Codegen::IdlMember &member : members)
        list.append(py::make_tuple(member.name.toStdString(), member.type.toString().toStdString()));
    return list;
}

/// A named type's kind, id, simple name and members (name, type) or enumerators.
py::dict namedInfo(const Codegen::IdlModel &model, const QString &name)
{
    py::dict info;
    info["id"] = model.repositoryId(name).toStdString();
    info["name"] = name.section(QStringLiteral("::"), -1).toStdString();
    if (const auto it = model.typedefs.constFind(name); it != model.typedefs.constEnd()) {
        info["kind"] = int(TkAlias);
        info["content"] = it->type.toString().toStdString();
    } else if (const auto it = model.exceptions.constFind(name); it != model.exceptions.constEnd()) {
        // (before structs: the runtime's model lists exceptions as structs too)
        info["kind"] = int(TkExcept);
        info["members"] = memberList(it->members);
    } else if (const auto it = model.structs.constFind(name); it != model.structs.constEnd()) {
        info["kind"] = int(TkStruct);
        info["members"] = memberList(it->members);
    } else if (const auto it = model.unions.constFind(name); it != model.unions.constEnd()) {
        QList<Codegen::IdlMember> members;
        for (const Codegen::IdlUnionCase &c : it->cases)
            members.append(c.member);
        info["kind"] = int(TkUnion);
        info["members"] = memberList(members);
        info["discriminator"] = it->discriminator.toString().toStdString();
    } else if (const auto it = model.enums.constFind(name); it != model.enums.constEnd()) {
        py::list members;
        for (const QString &enumerator : it->enumerators)
            members.append(py::make_tuple(enumerator.toStdString(), py::none()));
        info["kind"] = int(TkEnum);
        info["members"] = members;
    } else {
        info["kind"] = int(TkObjref);
    }
    return info;
}

/// The type's kind and parameters; basic types are CORBA.TypeCode's own business.
py::dict typeCodeInfo(const std::string &text)
{
    const Codegen::IdlModel &model = PyDataTypes::instance().model();
    IdlType type;
    try {
        type = Codegen::CdrTypeCode::fromText(model, QString::fromStdString(text));
    } catch (const Codegen::CdrTypeCode::Error &error) {
        throw py::value_error(error.message.toStdString());
    }
    if (type.kind == IdlType::Kind::Named && !Codegen::CdrTypeCode::isTypeCode(type))
        return namedInfo(model, type.name);
    py::dict info;
    info["length"] = type.bound.toLongLong();
    switch (type.kind) {
    case IdlType::Kind::String:
    case IdlType::Kind::WString:
        info["kind"] = int(type.kind == IdlType::Kind::String ? TkString : TkWString);
        break;
    case IdlType::Kind::Sequence:
        info["kind"] = int(TkSequence);
        info["content"] = type.element.front().toString().toStdString();
        break;
    case IdlType::Kind::Array: {
        // The outermost dimension; the content is the array of the others.
        IdlType inner = type;
        inner.dimensions.removeFirst();
        info["kind"] = int(TkArray);
        info["length"] = type.dimensions.front().toLongLong();
        info["content"] = (inner.dimensions.isEmpty() ? type.element.front() : inner).toString().toStdString();
        break;
    }
    default:
        info["kind"] = py::none();
    }
    return info;
}

/// omniORBpy's cdrMarshal(): @p value of the type @p name names as plain CDR (no byte-order octet).
py::bytes marshal(const std::string &name, py::handle value, bool littleEndian)
{
    const PyDataTypes &types = PyDataTypes::instance();
    const QString text = QString::fromStdString(name);
    const IdlType type = types.converter().typeNamed(text, text);
    QString error;
    const QByteArray bytes = types.codec().encodeValue(type, types.converter().toJson(type, value, text), littleEndian, &error);
    if (!error.isEmpty())
        throw py::type_error(error.toStdString());
    return py::bytes(bytes.constData(), size_t(bytes.size()));
}

/// omniORBpy's cdrUnmarshal(): a value of the type @p name names from plain CDR.
py::object unmarshal(const std::string &name, const py::bytes &data, bool littleEndian)
{
    const PyDataTypes &types = PyDataTypes::instance();
    const QString text = QString::fromStdString(name);
    const IdlType type = types.converter().typeNamed(text, text);
    QString error;
    const QJsonValue value = types.codec().decodeValue(type, QByteArray::fromStdString(data), littleEndian, &error);
    if (!error.isEmpty())
        throw py::value_error(error.toStdString());
    return types.converter().toPython(type, value);
}

} // namespace

void bindTypeCodes(py::module_ &module)
{
    module.def("cdr_marshal", &marshal, py::arg("name"), py::arg("value"), py::arg("little_endian"),
               "@p value of the type @p name names as CDR bytes.");
    module.def("cdr_unmarshal", &unmarshal, py::arg("name"), py::arg("data"), py::arg("little_endian"),
               "A value of the type @p name names from CDR bytes.");
    module.def("typecode_info", &typeCodeInfo, py::arg("name"),
               "The kind, id, name, members, content and length of the type @p name names; ValueError "
               "when the IDL declares no such type.");
    module.def("scoped_name_of", [](const std::string &repositoryId) {
        return PyDataTypes::instance().scopedNameOf(repositoryId).toStdString();
    }, py::arg("repository_id"), "The scoped name of the IDL type of @p repository_id; empty when none.");
}

} // namespace RtPython
