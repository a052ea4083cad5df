// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "idllexer.h"
#include "idlmodel.h"

#include <QHash>
#include <QList>
#include <QStringList>

namespace Codegen {

/// Recursive-descent parser over a preprocessed token stream, adding what it reads to an IdlModel.
/// Internal to IdlParser. A syntax error is reported and ends the parse of the stream; unknown names
/// and redefinitions are reported and parsing goes on.
class IdlSyntax
{
public:
    IdlSyntax(QList<IdlToken> tokens, const QStringList &files, IdlModel *model,
              Profile::Diagnostics *diagnostics);

    /// Parses every definition; returns false when a syntax error stopped it.
    bool parse();

private:
    /// Thrown after a syntax error was reported, to unwind to parse().
    struct SyntaxError
    {
    };

    /// The value of a constant expression while it is evaluated.
    struct Value
    {
        enum class Kind { Integer, Float, String, Char, Boolean, Enumerator };
        Kind kind = Kind::Integer;
        qint64 integer = 0;
        double real = 0;
        QString text; ///< String/Char/Enumerator (scoped name)

        QString toLiteral() const;
    };

    // tokens (idlsyntax.cpp)
    const IdlToken &current() const;
    const IdlToken &peekToken(int ahead) const;
    void next();
    bool accept(QLatin1String punctuator);
    bool acceptKeyword(QLatin1String keyword);
    void expect(QLatin1String punctuator);
    QString expectIdentifier(const QString &what);
    [[noreturn]] void syntaxError(const QString &message);
    void error(const IdlToken &at, const QString &message);
    IdlSource sourceOf(const IdlToken &token) const;

    // scopes and names
    QString qualify(const QString &name) const;
    bool declare(IdlDeclaration::Kind kind, const QString &name, const IdlToken &at);
    QString lookup(const QString &written) const;
    QString scopedNameText(IdlToken *first);
    void enterNesting();
    void leaveNesting() { --m_depth; }

    // definitions (idlsyntax.cpp)
    void definition();
    void module();
    void interfaceDeclaration(const IdlToken &start, bool isAbstract, bool isLocal);
    void interfaceBody(IdlInterface *interface);
    void operation(IdlInterface *interface);
    IdlParameter parameter();
    QStringList raisesClause();
    void attribute(IdlInterface *interface);
    void exceptionDeclaration();
    void constDeclaration();
    void valueBox(const IdlToken &start);

    // types (idlsyntaxtypes.cpp)
    void typeDeclaration();
    void typedefDeclaration();
    IdlType structDeclaration();
    IdlType unionDeclaration();
    IdlType enumDeclaration();
    QList<IdlMember> memberList(const QString &closing);
    IdlType typeSpec();
    IdlType simpleTypeSpec();
    bool isBaseTypeStart() const;
    IdlType baseType();
    IdlType templateType();
    IdlType namedType();
    QString positiveBound();
    IdlType declarator(const IdlType &type, QString *name, IdlToken *at);

    // expressions (idlexpression.cpp)
    Value constExpression();
    Value orExpression();
    Value xorExpression();
    Value andExpression();
    Value shiftExpression();
    Value addExpression();
    Value mulExpression();
    Value unaryExpression();
    Value primaryExpression();
    Value literal();
    Value binary(const Value &left, const Value &right, QChar op, const IdlToken &at);
    qint64 integerOf(const Value &value, const IdlToken &at);

    QList<IdlToken> m_tokens;
    QStringList m_files;
    IdlModel *m_model;
    Profile::Diagnostics *m_diagnostics;
    QHash<QString, IdlDeclaration::Kind> m_declared;
    QStringList m_scope;
    int m_pos = 0;
    int m_depth = 0;
};

} // namespace Codegen
