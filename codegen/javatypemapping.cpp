// SPDX-License-Identifier: MIT
#include "javatypemapping.h"

#include "idltypecategory.h"

#include <QHash>

namespace Codegen {

namespace {

struct JavaPrimitive
{
    QString type;
    QString holder;
    QString zero;
};

const QHash<QString, JavaPrimitive> &javaPrimitives()
{
    static const QHash<QString, JavaPrimitive> primitives = {
        {QStringLiteral("short"), {QStringLiteral("short"), QStringLiteral("Short"), QStringLiteral("(short)0")}},
        {QStringLiteral("unsigned short"), {QStringLiteral("short"), QStringLiteral("Short"), QStringLiteral("(short)0")}},
        {QStringLiteral("long"), {QStringLiteral("int"), QStringLiteral("Int"), QStringLiteral("0")}},
        {QStringLiteral("unsigned long"), {QStringLiteral("int"), QStringLiteral("Int"), QStringLiteral("0")}},
        {QStringLiteral("long long"), {QStringLiteral("long"), QStringLiteral("Long"), QStringLiteral("0L")}},
        {QStringLiteral("unsigned long long"), {QStringLiteral("long"), QStringLiteral("Long"), QStringLiteral("0L")}},
        {QStringLiteral("float"), {QStringLiteral("float"), QStringLiteral("Float"), QStringLiteral("0.0f")}},
        {QStringLiteral("double"), {QStringLiteral("double"), QStringLiteral("Double"), QStringLiteral("0.0")}},
        {QStringLiteral("long double"), {QStringLiteral("double"), QStringLiteral("Double"), QStringLiteral("0.0")}},
        {QStringLiteral("char"), {QStringLiteral("char"), QStringLiteral("Char"), QStringLiteral("'\\0'")}},
        {QStringLiteral("wchar"), {QStringLiteral("char"), QStringLiteral("WChar"), QStringLiteral("'\\0'")}},
        {QStringLiteral("boolean"), {QStringLiteral("boolean"), QStringLiteral("Boolean"), QStringLiteral("false")}},
        {QStringLiteral("octet"), {QStringLiteral("byte"), QStringLiteral("Byte"), QStringLiteral("(byte)0")}},
        {QStringLiteral("any"), {QStringLiteral("org.omg.CORBA.Any"), QStringLiteral("Any"), QStringLiteral("null")}},
        {QStringLiteral("Object"), {QStringLiteral("org.omg.CORBA.Object"), QStringLiteral("Object"), QStringLiteral("null")}},
        {QStringLiteral("TypeCode"), {QStringLiteral("org.omg.CORBA.TypeCode"), QStringLiteral("TypeCode"), QStringLiteral("null")}}};
    return primitives;
}

QString javaScopedName(const QString &scopedName)
{
    QString name = scopedName;
    return name.replace(QLatin1String("::"), QLatin1String("."));
}

QString holderType(const IdlModel &model, const IdlType &type)
{
    // A typedef'd sequence or array has its own holder; other typedefs use the holder of the
    // type they stand for.
    if (type.kind == IdlType::Kind::Named && model.typedefs.contains(type.name)) {
        const IdlType target = model.resolve(type);
        if (target.kind == IdlType::Kind::Sequence || target.kind == IdlType::Kind::Array)
            return javaScopedName(type.name) + QStringLiteral("Holder");
        return holderType(model, target);
    }
    switch (type.kind) {
    case IdlType::Kind::Basic:
        return QStringLiteral("org.omg.CORBA.%1Holder")
            .arg(javaPrimitives().value(normalizedKeyword(type.name)).holder);
    case IdlType::Kind::String:
        return QStringLiteral("org.omg.CORBA.StringHolder");
    case IdlType::Kind::WString:
        return QStringLiteral("org.omg.CORBA.WStringHolder");
    default:
        return javaScopedName(type.name) + QStringLiteral("Holder");
    }
}

} // namespace

QString javaTypeName(const IdlModel &model, const IdlType &type)
{
    const IdlType resolved = model.resolve(type);
    switch (resolved.kind) {
    case IdlType::Kind::Basic:
        return javaPrimitives().value(normalizedKeyword(resolved.name)).type;
    case IdlType::Kind::String:
    case IdlType::Kind::WString:
        return QStringLiteral("String");
    case IdlType::Kind::Fixed:
        return QStringLiteral("java.math.BigDecimal");
    case IdlType::Kind::Sequence:
        return resolved.element.empty() ? QStringLiteral("Object[]")
                                        : javaTypeName(model, resolved.element.front()) + "[]";
    case IdlType::Kind::Array: {
        QString name = resolved.element.empty() ? QStringLiteral("Object")
                                                : javaTypeName(model, resolved.element.front());
        for (int i = 0; i < resolved.dimensions.size(); ++i)
            name += QStringLiteral("[]");
        return name;
    }
    case IdlType::Kind::Named:
        return javaScopedName(resolved.name);
    }
    return {};
}

QString javaParameterType(const IdlModel &model, const IdlParameter &parameter)
{
    if (parameter.mode == IdlParameter::Mode::In)
        return javaTypeName(model, parameter.type);
    return holderType(model, parameter.type);
}

QString javaDefaultValue(const IdlModel &model, const IdlType &type)
{
    const IdlType resolved = model.resolve(type);
    switch (resolved.kind) {
    case IdlType::Kind::Basic:
        return javaPrimitives().value(normalizedKeyword(resolved.name)).zero;
    case IdlType::Kind::String:
    case IdlType::Kind::WString:
        return QStringLiteral("\"\"");
    case IdlType::Kind::Sequence: {
        QString name = javaTypeName(model, resolved);
        // `new T[0]` for `T[]`, `new T[0][]` for `T[][]`.
        return QStringLiteral("new ") + name.insert(name.indexOf(QLatin1Char('[')) + 1, QLatin1Char('0'));
    }
    default:
        return QStringLiteral("null");
    }
}

} // namespace Codegen
