// SPDX-License-Identifier: MIT
#include "idlmodel.h"

#include <QSet>

#include <algorithm>

namespace Codegen {

IdlType IdlType::basic(const QString &keyword)
{
    IdlType type;
    type.kind = Kind::Basic;
    type.name = keyword;
    return type;
}

IdlType IdlType::named(const QString &scopedName)
{
    IdlType type;
    type.kind = Kind::Named;
    type.name = scopedName;
    return type;
}

QString IdlType::toString() const
{
    const QString inner = element.empty() ? QString() : element.front().toString();
    switch (kind) {
    case Kind::Basic:
    case Kind::Named:
        return name;
    case Kind::Sequence:
        return bound.isEmpty() ? QStringLiteral("sequence<%1>").arg(inner)
                               : QStringLiteral("sequence<%1, %2>").arg(inner, bound);
    case Kind::String:
        return bound.isEmpty() ? QStringLiteral("string") : QStringLiteral("string<%1>").arg(bound);
    case Kind::WString:
        return bound.isEmpty() ? QStringLiteral("wstring") : QStringLiteral("wstring<%1>").arg(bound);
    case Kind::Fixed:
        return bound.isEmpty() ? QStringLiteral("fixed") : QStringLiteral("fixed<%1, %2>").arg(bound, scale);
    case Kind::Array: {
        QString text = inner;
        for (const QString &dimension : dimensions)
            text += QLatin1Char('[') + dimension + QLatin1Char(']');
        return text;
    }
    }
    return name;
}

bool IdlType::operator==(const IdlType &other) const
{
    return kind == other.kind && name == other.name && element == other.element && bound == other.bound
        && scale == other.scale && dimensions == other.dimensions;
}

bool IdlMember::operator==(const IdlMember &other) const
{
    return name == other.name && type == other.type;
}

bool IdlStruct::operator==(const IdlStruct &other) const
{
    return scopedName == other.scopedName && members == other.members;
}

bool IdlUnionCase::operator==(const IdlUnionCase &other) const
{
    return labels == other.labels && isDefault == other.isDefault && member == other.member;
}

bool IdlUnion::operator==(const IdlUnion &other) const
{
    return scopedName == other.scopedName && discriminator == other.discriminator && cases == other.cases;
}

bool IdlEnum::operator==(const IdlEnum &other) const
{
    return scopedName == other.scopedName && enumerators == other.enumerators;
}

bool IdlTypedef::operator==(const IdlTypedef &other) const
{
    return scopedName == other.scopedName && type == other.type;
}

std::optional<qint64> IdlConst::integerValue() const
{
    bool ok = false;
    const qint64 number = value.toLongLong(&ok);
    if (ok)
        return number;
    return std::nullopt;
}

bool IdlConst::operator==(const IdlConst &other) const
{
    return scopedName == other.scopedName && type == other.type && value == other.value;
}

bool IdlException::operator==(const IdlException &other) const
{
    return scopedName == other.scopedName && members == other.members;
}

QString IdlParameter::modeName(Mode mode)
{
    switch (mode) {
    case Mode::In:
        return QStringLiteral("in");
    case Mode::Out:
        return QStringLiteral("out");
    case Mode::InOut:
        return QStringLiteral("inout");
    }
    return {};
}

bool IdlParameter::operator==(const IdlParameter &other) const
{
    return mode == other.mode && type == other.type && name == other.name;
}

bool IdlOperation::operator==(const IdlOperation &other) const
{
    return name == other.name && interfaceName == other.interfaceName && oneway == other.oneway
        && returnType == other.returnType && parameters == other.parameters && raises == other.raises
        && contexts == other.contexts;
}

bool IdlAttribute::operator==(const IdlAttribute &other) const
{
    return name == other.name && interfaceName == other.interfaceName && readonly == other.readonly
        && type == other.type;
}

bool IdlInterface::operator==(const IdlInterface &other) const
{
    return scopedName == other.scopedName && defined == other.defined && isAbstract == other.isAbstract
        && isLocal == other.isLocal && bases == other.bases && operations == other.operations
        && attributes == other.attributes;
}

QString IdlDeclaration::parentScope() const
{
    const int separator = scopedName.lastIndexOf(QLatin1String("::"));
    return separator < 0 ? QString() : scopedName.left(separator);
}

QString IdlDeclaration::name() const
{
    const int separator = scopedName.lastIndexOf(QLatin1String("::"));
    return separator < 0 ? scopedName : scopedName.mid(separator + 2);
}

bool IdlDeclaration::operator==(const IdlDeclaration &other) const
{
    return kind == other.kind && scopedName == other.scopedName;
}

bool IdlDataType::operator==(const IdlDataType &other) const
{
    return scopedName == other.scopedName && timed == other.timed;
}

std::optional<IdlDeclaration> IdlModel::find(const QString &scopedName) const
{
    for (const IdlDeclaration &declaration : declarations) {
        if (declaration.scopedName == scopedName)
            return declaration;
    }
    return std::nullopt;
}

QList<IdlDeclaration> IdlModel::children(const QString &scope) const
{
    QList<IdlDeclaration> result;
    for (const IdlDeclaration &declaration : declarations) {
        if (declaration.parentScope() == scope)
            result.append(declaration);
    }
    return result;
}

IdlType IdlModel::resolve(const IdlType &type) const
{
    IdlType current = type;
    QSet<QString> seen; // a typedef cycle cannot be declared, but a merged model must not hang either
    while (current.kind == IdlType::Kind::Named && typedefs.contains(current.name)
           && !seen.contains(current.name)) {
        seen.insert(current.name);
        current = typedefs.value(current.name).type;
    }
    return current;
}

QStringList IdlModel::typedefChain(const QString &scopedName) const
{
    QStringList chain;
    QString name = scopedName;
    while (typedefs.contains(name) && !chain.contains(name)) {
        chain.append(name);
        const IdlType &next = typedefs.value(name).type;
        if (next.kind != IdlType::Kind::Named)
            break;
        name = next.name;
    }
    return chain;
}

bool IdlModel::isTimed(const IdlStruct &type) const
{
    return std::any_of(type.members.cbegin(), type.members.cend(), [this](const IdlMember &member) {
        const IdlType resolved = resolve(member.type);
        return member.name == QLatin1String("tm") && resolved.kind == IdlType::Kind::Named
            && resolved.name == QLatin1String("RTC::Time");
    });
}

QList<IdlDataType> IdlModel::dataTypes() const
{
    QList<IdlDataType> result;
    for (const IdlStruct &type : structs)
        result.append(IdlDataType{type.scopedName, isTimed(type), type.source});
    return result; // QMap iterates in key order, so the list is sorted by scoped name
}

QList<IdlInterface> IdlModel::definedInterfaces() const
{
    QList<IdlInterface> result;
    for (const IdlInterface &interface : interfaces) {
        if (interface.defined)
            result.append(interface);
    }
    return result;
}

QStringList IdlModel::allBases(const QString &scopedName) const
{
    // Breadth first, so direct bases come before their own bases; a diamond yields each base once.
    QStringList result;
    QStringList queue = interfaces.value(scopedName).bases;
    while (!queue.isEmpty()) {
        const QString base = queue.takeFirst();
        if (base == scopedName || result.contains(base))
            continue;
        result.append(base);
        queue.append(interfaces.value(base).bases);
    }
    return result;
}

QList<IdlOperation> IdlModel::allOperations(const QString &scopedName) const
{
    QList<IdlOperation> result;
    const QStringList bases = allBases(scopedName);
    for (auto it = bases.crbegin(); it != bases.crend(); ++it)
        result.append(interfaces.value(*it).operations);
    result.append(interfaces.value(scopedName).operations);
    return result;
}

QList<IdlAttribute> IdlModel::allAttributes(const QString &scopedName) const
{
    QList<IdlAttribute> result;
    const QStringList bases = allBases(scopedName);
    for (auto it = bases.crbegin(); it != bases.crend(); ++it)
        result.append(interfaces.value(*it).attributes);
    result.append(interfaces.value(scopedName).attributes);
    return result;
}

QString IdlModel::repositoryId(const QString &scopedName) const
{
    QString prefix;
    if (const std::optional<IdlDeclaration> declaration = find(scopedName)) {
        const QMap<int, QString> lines = prefixes.value(declaration->source.file);
        auto after = lines.upperBound(declaration->source.line);
        if (after != lines.constBegin())
            prefix = std::prev(after).value();
    }
    const QString path = QString(scopedName).replace(QStringLiteral("::"), QStringLiteral("/"));
    return QStringLiteral("IDL:%1%2:1.0").arg(prefix.isEmpty() ? QString() : prefix + QLatin1Char('/'), path);
}

QString IdlModel::scopedNameOf(const QString &repositoryId) const
{
    if (!repositoryId.startsWith(QLatin1String("IDL:")))
        return {};
    // Most ids have no prefix: their path is the scoped name.
    QString path = repositoryId.mid(4);
    path = path.left(path.lastIndexOf(QLatin1Char(':')));
    const QString plain = QString(path).replace(QLatin1Char('/'), QStringLiteral("::"));
    if (find(plain) && this->repositoryId(plain) == repositoryId)
        return plain;
    // A prefixed id ends with the scoped name's path; the prefix may itself contain '/'.
    for (qsizetype slash = path.indexOf(QLatin1Char('/')); slash >= 0; slash = path.indexOf(QLatin1Char('/'), slash + 1)) {
        const QString candidate = path.mid(slash + 1).replace(QLatin1Char('/'), QStringLiteral("::"));
        if (find(candidate) && this->repositoryId(candidate) == repositoryId)
            return candidate;
    }
    return {};
}

bool IdlModel::operator==(const IdlModel &other) const
{
    return declarations == other.declarations && structs == other.structs && unions == other.unions
        && enums == other.enums && typedefs == other.typedefs && consts == other.consts
        && exceptions == other.exceptions && interfaces == other.interfaces && files == other.files
        && prefixes == other.prefixes;
}

} // namespace Codegen
