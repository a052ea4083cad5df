// SPDX-License-Identifier: MIT
#include "idltypecategory.h"

namespace Codegen {

namespace {

// Deeply nested or (wrongly) self-containing types must not recurse without end.
constexpr int MaxDepth = 64;

bool isVariable(const IdlModel &model, const IdlType &type, int depth);

bool anyMemberVariable(const IdlModel &model, const QList<IdlMember> &members, int depth)
{
    for (const IdlMember &member : members) {
        if (isVariable(model, member.type, depth + 1))
            return true;
    }
    return false;
}

bool isVariableNamed(const IdlModel &model, const QString &name, int depth)
{
    if (model.interfaces.contains(name))
        return true;
    if (const auto it = model.structs.constFind(name); it != model.structs.cend())
        return anyMemberVariable(model, it->members, depth);
    if (const auto it = model.unions.constFind(name); it != model.unions.cend()) {
        for (const IdlUnionCase &unionCase : it->cases) {
            if (isVariable(model, unionCase.member.type, depth + 1))
                return true;
        }
    }
    return false;
}

bool isVariable(const IdlModel &model, const IdlType &type, int depth)
{
    if (depth > MaxDepth)
        return true;
    const IdlType resolved = model.resolve(type);
    switch (resolved.kind) {
    case IdlType::Kind::String:
    case IdlType::Kind::WString:
    case IdlType::Kind::Sequence:
        return true;
    case IdlType::Kind::Array:
        return !resolved.element.empty() && isVariable(model, resolved.element.front(), depth + 1);
    case IdlType::Kind::Named:
        return isVariableNamed(model, resolved.name, depth);
    case IdlType::Kind::Basic: {
        const QString keyword = normalizedKeyword(resolved.name);
        return keyword == QLatin1String("any") || keyword == QLatin1String("Object")
            || keyword == QLatin1String("TypeCode");
    }
    case IdlType::Kind::Fixed:
        return false;
    }
    return false;
}

IdlTypeCategory basicCategory(const QString &keyword)
{
    if (keyword == QLatin1String("void"))
        return IdlTypeCategory::Void;
    if (keyword == QLatin1String("any"))
        return IdlTypeCategory::Any;
    if (keyword == QLatin1String("Object"))
        return IdlTypeCategory::Object;
    if (keyword == QLatin1String("TypeCode"))
        return IdlTypeCategory::TypeCode;
    return IdlTypeCategory::Primitive;
}

IdlTypeCategory namedCategory(const IdlModel &model, const IdlType &type)
{
    const QString &name = type.name;
    if (model.interfaces.contains(name))
        return IdlTypeCategory::ObjectReference;
    if (model.enums.contains(name))
        return IdlTypeCategory::Enum;
    if (model.structs.contains(name) || model.unions.contains(name))
        return isVariable(model, type, 0) ? IdlTypeCategory::VariableStruct
                                          : IdlTypeCategory::FixedStruct;
    return IdlTypeCategory::Unknown;
}

} // namespace

QString normalizedKeyword(const QString &keyword)
{
    return keyword.simplified();
}

IdlType resolvedIdlType(const IdlModel &model, const IdlType &type)
{
    return model.resolve(type);
}

bool isVariableLength(const IdlModel &model, const IdlType &type)
{
    return isVariable(model, type, 0);
}

IdlTypeCategory idlTypeCategory(const IdlModel &model, const IdlType &type)
{
    const IdlType resolved = model.resolve(type);
    switch (resolved.kind) {
    case IdlType::Kind::Basic:
        return basicCategory(normalizedKeyword(resolved.name));
    case IdlType::Kind::String:
        return IdlTypeCategory::String;
    case IdlType::Kind::WString:
        return IdlTypeCategory::WString;
    case IdlType::Kind::Sequence:
        return IdlTypeCategory::Sequence;
    case IdlType::Kind::Array:
        return isVariable(model, resolved, 0) ? IdlTypeCategory::VariableArray
                                              : IdlTypeCategory::FixedArray;
    case IdlType::Kind::Fixed:
        return IdlTypeCategory::FixedStruct;
    case IdlType::Kind::Named:
        return namedCategory(model, resolved);
    }
    return IdlTypeCategory::Unknown;
}

} // namespace Codegen
