// SPDX-License-Identifier: MIT
#include "idlsyntax_p.h"

namespace Codegen {

namespace {

bool isTypeKind(IdlDeclaration::Kind kind)
{
    switch (kind) {
    case IdlDeclaration::Kind::Interface:
    case IdlDeclaration::Kind::Struct:
    case IdlDeclaration::Kind::Union:
    case IdlDeclaration::Kind::Enum:
    case IdlDeclaration::Kind::Typedef:
    case IdlDeclaration::Kind::Native:
        return true;
    default:
        return false;
    }
}

const QStringList &singleWordTypes()
{
    static const QStringList words{
        QStringLiteral("float"),  QStringLiteral("double"), QStringLiteral("short"),  QStringLiteral("char"),
        QStringLiteral("wchar"),  QStringLiteral("boolean"), QStringLiteral("octet"), QStringLiteral("any"),
        QStringLiteral("Object"), QStringLiteral("ValueBase"), QStringLiteral("int8"), QStringLiteral("uint8"),
        QStringLiteral("int16"),  QStringLiteral("uint16"), QStringLiteral("int32"),  QStringLiteral("uint32"),
        QStringLiteral("int64"),  QStringLiteral("uint64")};
    return words;
}

} // namespace

void IdlSyntax::typeDeclaration()
{
    if (acceptKeyword(QLatin1String("typedef"))) {
        typedefDeclaration();
    } else if (acceptKeyword(QLatin1String("struct"))) {
        structDeclaration();
    } else if (acceptKeyword(QLatin1String("union"))) {
        unionDeclaration();
    } else if (acceptKeyword(QLatin1String("enum"))) {
        enumDeclaration();
    } else if (acceptKeyword(QLatin1String("native"))) {
        const IdlToken at = current();
        declare(IdlDeclaration::Kind::Native, expectIdentifier(QStringLiteral("a native type name")), at);
    } else {
        syntaxError(QStringLiteral("expected a definition"));
    }
}

void IdlSyntax::typedefDeclaration()
{
    const IdlType type = typeSpec();
    do {
        QString name;
        IdlToken at;
        IdlTypedef alias;
        alias.type = declarator(type, &name, &at);
        alias.scopedName = qualify(name);
        alias.source = sourceOf(at);
        if (declare(IdlDeclaration::Kind::Typedef, name, at))
            m_model->typedefs.insert(alias.scopedName, alias);
    } while (accept(QLatin1String(",")));
}

IdlType IdlSyntax::structDeclaration()
{
    const IdlToken at = current();
    const QString name = expectIdentifier(QStringLiteral("a struct name"));
    IdlStruct type{qualify(name), {}, sourceOf(at)};
    if (current().isPunctuator(QLatin1String(";")) && !m_declared.contains(type.scopedName))
        return IdlType::named(type.scopedName); // forward declaration; the definition follows later
    const bool isNew = declare(IdlDeclaration::Kind::Struct, name, at);
    expect(QLatin1String("{"));
    enterNesting();
    m_scope.append(name);
    type.members = memberList(QStringLiteral("struct '%1'").arg(type.scopedName));
    m_scope.removeLast();
    leaveNesting();
    if (isNew)
        m_model->structs.insert(type.scopedName, type);
    return IdlType::named(type.scopedName);
}

QList<IdlMember> IdlSyntax::memberList(const QString &closing)
{
    QList<IdlMember> members;
    while (!accept(QLatin1String("}"))) {
        if (current().kind == IdlToken::Kind::End)
            syntaxError(QStringLiteral("expected '}' to close %1").arg(closing));
        const IdlType type = typeSpec();
        do {
            IdlMember member;
            IdlToken at;
            member.type = declarator(type, &member.name, &at);
            member.source = sourceOf(at);
            members.append(member);
        } while (accept(QLatin1String(",")));
        expect(QLatin1String(";"));
    }
    return members;
}

IdlType IdlSyntax::unionDeclaration()
{
    const IdlToken at = current();
    const QString name = expectIdentifier(QStringLiteral("a union name"));
    IdlUnion type;
    type.scopedName = qualify(name);
    type.source = sourceOf(at);
    const bool isNew = declare(IdlDeclaration::Kind::Union, name, at);
    if (!acceptKeyword(QLatin1String("switch")))
        syntaxError(QStringLiteral("expected 'switch'"));
    expect(QLatin1String("("));
    type.discriminator = typeSpec();
    expect(QLatin1String(")"));
    expect(QLatin1String("{"));
    enterNesting();
    m_scope.append(name);
    while (!accept(QLatin1String("}"))) {
        IdlUnionCase unionCase;
        do {
            if (acceptKeyword(QLatin1String("default"))) {
                unionCase.isDefault = true;
            } else if (acceptKeyword(QLatin1String("case"))) {
                unionCase.labels.append(constExpression().toLiteral());
            } else {
                syntaxError(QStringLiteral("expected 'case' or 'default' in union '%1'").arg(type.scopedName));
            }
            expect(QLatin1String(":"));
        } while (current().isIdentifier(QLatin1String("case")) || current().isIdentifier(QLatin1String("default")));
        const IdlType memberType = typeSpec();
        IdlToken memberAt;
        unionCase.member.type = declarator(memberType, &unionCase.member.name, &memberAt);
        unionCase.member.source = sourceOf(memberAt);
        expect(QLatin1String(";"));
        type.cases.append(unionCase);
    }
    m_scope.removeLast();
    leaveNesting();
    if (isNew)
        m_model->unions.insert(type.scopedName, type);
    return IdlType::named(type.scopedName);
}

IdlType IdlSyntax::enumDeclaration()
{
    const IdlToken at = current();
    const QString name = expectIdentifier(QStringLiteral("an enum name"));
    IdlEnum type{qualify(name), {}, sourceOf(at)};
    const bool isNew = declare(IdlDeclaration::Kind::Enum, name, at);
    expect(QLatin1String("{"));
    do {
        const IdlToken enumeratorAt = current();
        const QString enumerator = expectIdentifier(QStringLiteral("an enumerator"));
        // Enumerators belong to the scope around the enum, as in C.
        declare(IdlDeclaration::Kind::Enumerator, enumerator, enumeratorAt);
        type.enumerators.append(enumerator);
    } while (accept(QLatin1String(",")) && !current().isPunctuator(QLatin1String("}")));
    expect(QLatin1String("}"));
    if (isNew)
        m_model->enums.insert(type.scopedName, type);
    return IdlType::named(type.scopedName);
}

IdlType IdlSyntax::typeSpec()
{
    if (acceptKeyword(QLatin1String("struct")))
        return structDeclaration();
    if (acceptKeyword(QLatin1String("union")))
        return unionDeclaration();
    if (acceptKeyword(QLatin1String("enum")))
        return enumDeclaration();
    return simpleTypeSpec();
}

IdlType IdlSyntax::simpleTypeSpec()
{
    if (isBaseTypeStart())
        return baseType();
    if (current().isIdentifier(QLatin1String("sequence")) || current().isIdentifier(QLatin1String("string"))
        || current().isIdentifier(QLatin1String("wstring")) || current().isIdentifier(QLatin1String("fixed")))
        return templateType();
    if (current().kind == IdlToken::Kind::Identifier || current().isPunctuator(QLatin1String("::")))
        return namedType();
    syntaxError(QStringLiteral("expected a type"));
}

bool IdlSyntax::isBaseTypeStart() const
{
    const IdlToken &token = current();
    if (token.kind != IdlToken::Kind::Identifier)
        return false;
    return singleWordTypes().contains(token.text) || token.text == QLatin1String("long")
        || token.text == QLatin1String("unsigned");
}

IdlType IdlSyntax::baseType()
{
    QString text;
    if (acceptKeyword(QLatin1String("unsigned")))
        text = QStringLiteral("unsigned ");
    if (acceptKeyword(QLatin1String("long"))) {
        if (acceptKeyword(QLatin1String("long")))
            return IdlType::basic(text + QStringLiteral("long long"));
        if (text.isEmpty() && acceptKeyword(QLatin1String("double")))
            return IdlType::basic(QStringLiteral("long double"));
        return IdlType::basic(text + QStringLiteral("long"));
    }
    if (acceptKeyword(QLatin1String("short")))
        return IdlType::basic(text + QStringLiteral("short"));
    if (!text.isEmpty())
        syntaxError(QStringLiteral("expected 'short' or 'long' after 'unsigned'"));
    const QString keyword = current().text;
    next();
    return IdlType::basic(keyword);
}

IdlType IdlSyntax::templateType()
{
    IdlType type;
    const QString keyword = current().text;
    next();
    enterNesting();
    if (keyword == QLatin1String("sequence")) {
        type.kind = IdlType::Kind::Sequence;
        expect(QLatin1String("<"));
        type.element.push_back(simpleTypeSpec());
        if (accept(QLatin1String(",")))
            type.bound = positiveBound();
        expect(QLatin1String(">"));
    } else if (keyword == QLatin1String("fixed")) {
        type.kind = IdlType::Kind::Fixed;
        if (accept(QLatin1String("<"))) {
            type.bound = positiveBound();
            expect(QLatin1String(","));
            type.scale = QString::number(integerOf(constExpression(), current()));
            expect(QLatin1String(">"));
        }
    } else {
        type.kind = keyword == QLatin1String("string") ? IdlType::Kind::String : IdlType::Kind::WString;
        if (accept(QLatin1String("<"))) {
            type.bound = positiveBound();
            expect(QLatin1String(">"));
        }
    }
    leaveNesting();
    return type;
}

QString IdlSyntax::positiveBound()
{
    const IdlToken at = current();
    const qint64 bound = integerOf(constExpression(), at);
    if (bound <= 0)
        error(at, QStringLiteral("a bound must be a positive integer, not %1").arg(bound));
    return QString::number(bound);
}

IdlType IdlSyntax::namedType()
{
    IdlToken at;
    const QString written = scopedNameText(&at);
    const QString scoped = lookup(written);
    if (scoped.isEmpty()) {
        error(at, QStringLiteral("unknown type '%1'").arg(written));
        return IdlType::named(written.startsWith(QLatin1String("::")) ? written.mid(2) : written);
    }
    if (!isTypeKind(m_declared.value(scoped)))
        error(at, QStringLiteral("'%1' is not a type").arg(scoped));
    return IdlType::named(scoped);
}

IdlType IdlSyntax::declarator(const IdlType &type, QString *name, IdlToken *at)
{
    *at = current();
    *name = expectIdentifier(QStringLiteral("a name"));
    if (!current().isPunctuator(QLatin1String("[")))
        return type;
    IdlType array;
    array.kind = IdlType::Kind::Array;
    array.element.push_back(type);
    while (accept(QLatin1String("["))) {
        array.dimensions.append(positiveBound());
        expect(QLatin1String("]"));
    }
    return array;
}

} // namespace Codegen
