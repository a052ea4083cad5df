// SPDX-License-Identifier: MIT
#include "cxxtypemapping.h"

#include "idltypecategory.h"

#include <QHash>

namespace Codegen {

namespace {

QString primitiveName(const QString &keyword)
{
    static const QHash<QString, QString> names = {
        {QStringLiteral("short"), QStringLiteral("CORBA::Short")},
        {QStringLiteral("long"), QStringLiteral("CORBA::Long")},
        {QStringLiteral("long long"), QStringLiteral("CORBA::LongLong")},
        {QStringLiteral("unsigned short"), QStringLiteral("CORBA::UShort")},
        {QStringLiteral("unsigned long"), QStringLiteral("CORBA::ULong")},
        {QStringLiteral("unsigned long long"), QStringLiteral("CORBA::ULongLong")},
        {QStringLiteral("float"), QStringLiteral("CORBA::Float")},
        {QStringLiteral("double"), QStringLiteral("CORBA::Double")},
        {QStringLiteral("long double"), QStringLiteral("CORBA::LongDouble")},
        {QStringLiteral("char"), QStringLiteral("CORBA::Char")},
        {QStringLiteral("wchar"), QStringLiteral("CORBA::WChar")},
        {QStringLiteral("boolean"), QStringLiteral("CORBA::Boolean")},
        {QStringLiteral("octet"), QStringLiteral("CORBA::Octet")},
        {QStringLiteral("any"), QStringLiteral("CORBA::Any")},
        {QStringLiteral("Object"), QStringLiteral("CORBA::Object")},
        {QStringLiteral("TypeCode"), QStringLiteral("CORBA::TypeCode")},
        {QStringLiteral("void"), QStringLiteral("void")}};
    return names.value(keyword, keyword);
}

/// The name used for `_out`, `_ptr`, `_slice`: the outermost typedef name, so that a typedef'd
/// sequence stays `EchoList` and does not become the anonymous sequence it stands for.
QString declaredName(const IdlModel &model, const IdlType &type)
{
    return cxxTypeName(model, type);
}

QString outType(const IdlModel &model, const IdlType &type, IdlTypeCategory category)
{
    switch (category) {
    case IdlTypeCategory::String:
        return QStringLiteral("CORBA::String_out");
    case IdlTypeCategory::WString:
        return QStringLiteral("CORBA::WString_out");
    case IdlTypeCategory::Any:
        return QStringLiteral("CORBA::Any_out");
    case IdlTypeCategory::Object:
        return QStringLiteral("CORBA::Object_out");
    default:
        return declaredName(model, type) + QStringLiteral("_out");
    }
}

QString inType(const IdlModel &model, const IdlType &type, IdlTypeCategory category)
{
    const QString name = declaredName(model, type);
    switch (category) {
    case IdlTypeCategory::Primitive:
    case IdlTypeCategory::Enum:
        return name;
    case IdlTypeCategory::String:
        return QStringLiteral("const char*");
    case IdlTypeCategory::WString:
        return QStringLiteral("const CORBA::WChar*");
    case IdlTypeCategory::FixedArray:
    case IdlTypeCategory::VariableArray:
        return QStringLiteral("const ") + name;
    case IdlTypeCategory::ObjectReference:
    case IdlTypeCategory::Object:
    case IdlTypeCategory::TypeCode:
        return name + QStringLiteral("_ptr");
    default:
        return QStringLiteral("const ") + name + QLatin1Char('&');
    }
}

QString inoutType(const IdlModel &model, const IdlType &type, IdlTypeCategory category)
{
    const QString name = declaredName(model, type);
    switch (category) {
    case IdlTypeCategory::String:
        return QStringLiteral("char*&");
    case IdlTypeCategory::WString:
        return QStringLiteral("CORBA::WChar*&");
    case IdlTypeCategory::FixedArray:
    case IdlTypeCategory::VariableArray:
        return name;
    case IdlTypeCategory::ObjectReference:
    case IdlTypeCategory::Object:
    case IdlTypeCategory::TypeCode:
        return name + QStringLiteral("_ptr&");
    default:
        return name + QLatin1Char('&');
    }
}

QString firstEnumerator(const IdlModel &model, const IdlType &type)
{
    const IdlType resolved = model.resolve(type);
    const IdlEnum e = model.enums.value(resolved.name);
    if (e.enumerators.isEmpty())
        return QStringLiteral("%1()").arg(cxxTypeName(model, type));
    const int split = e.scopedName.lastIndexOf(QLatin1String("::"));
    const QString scope = split < 0 ? QString() : e.scopedName.left(split + 2);
    return scope + e.enumerators.first();
}

} // namespace

QString cxxTypeName(const IdlModel &model, const IdlType &type)
{
    Q_UNUSED(model);
    switch (type.kind) {
    case IdlType::Kind::Basic:
        return primitiveName(normalizedKeyword(type.name));
    case IdlType::Kind::String:
        return QStringLiteral("char*");
    case IdlType::Kind::WString:
        return QStringLiteral("CORBA::WChar*");
    default:
        // Anonymous sequences/arrays cannot be parameters in IDL 2.4+; named types keep their
        // scoped name, which is the C++ qualified name.
        return type.name.isEmpty() ? type.toString() : type.name;
    }
}

QString cxxParameterType(const IdlModel &model, const IdlParameter &parameter)
{
    const IdlTypeCategory category = idlTypeCategory(model, parameter.type);
    switch (parameter.mode) {
    case IdlParameter::Mode::In:
        return inType(model, parameter.type, category);
    case IdlParameter::Mode::Out:
        return outType(model, parameter.type, category);
    case IdlParameter::Mode::InOut:
        return inoutType(model, parameter.type, category);
    }
    return {};
}

QString cxxReturnType(const IdlModel &model, const IdlType &type)
{
    const QString name = declaredName(model, type);
    switch (idlTypeCategory(model, type)) {
    case IdlTypeCategory::Void:
        return QStringLiteral("void");
    case IdlTypeCategory::String:
        return QStringLiteral("char*");
    case IdlTypeCategory::WString:
        return QStringLiteral("CORBA::WChar*");
    case IdlTypeCategory::VariableStruct:
    case IdlTypeCategory::Sequence:
    case IdlTypeCategory::Any:
        return name + QLatin1Char('*');
    case IdlTypeCategory::FixedArray:
    case IdlTypeCategory::VariableArray:
        return name + QStringLiteral("_slice*");
    case IdlTypeCategory::ObjectReference:
    case IdlTypeCategory::Object:
    case IdlTypeCategory::TypeCode:
        return name + QStringLiteral("_ptr");
    default:
        return name;
    }
}

QString cxxReturnStatement(const IdlModel &model, const IdlType &type)
{
    const QString name = declaredName(model, type);
    const IdlType resolved = model.resolve(type);
    switch (idlTypeCategory(model, type)) {
    case IdlTypeCategory::Void:
        return {};
    case IdlTypeCategory::Primitive:
        return normalizedKeyword(resolved.name) == QLatin1String("boolean")
            ? QStringLiteral("return false;")
            : QStringLiteral("return 0;");
    case IdlTypeCategory::Enum:
        return QStringLiteral("return %1;").arg(firstEnumerator(model, type));
    case IdlTypeCategory::String:
        return QStringLiteral("return CORBA::string_dup(\"\");");
    case IdlTypeCategory::WString:
        return QStringLiteral("return CORBA::wstring_dup(L\"\");");
    case IdlTypeCategory::FixedStruct:
        return QStringLiteral("return %1();").arg(name);
    case IdlTypeCategory::VariableStruct:
    case IdlTypeCategory::Sequence:
    case IdlTypeCategory::Any:
        return QStringLiteral("return new %1();").arg(name);
    case IdlTypeCategory::FixedArray:
    case IdlTypeCategory::VariableArray:
        return QStringLiteral("return %1_alloc();").arg(name);
    case IdlTypeCategory::ObjectReference:
    case IdlTypeCategory::Object:
    case IdlTypeCategory::TypeCode:
        return QStringLiteral("return %1::_nil();").arg(name);
    case IdlTypeCategory::Unknown:
        return QStringLiteral("return %1();").arg(name);
    }
    return {};
}

} // namespace Codegen
