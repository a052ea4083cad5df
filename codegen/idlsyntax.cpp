// SPDX-License-Identifier: MIT
#include "idlsyntax_p.h"

namespace Codegen {

using Profile::Diagnostic;

namespace {

// Modules, interfaces, structs and nested template types each take a level; real IDL stays far below.
constexpr int MaxNesting = 64;

QString joinScope(const QStringList &scope, const QString &name)
{
    return scope.isEmpty() ? name : scope.join(QLatin1String("::")) + QLatin1String("::") + name;
}

} // namespace

IdlSyntax::IdlSyntax(QList<IdlToken> tokens, const QStringList &files, IdlModel *model,
                     Profile::Diagnostics *diagnostics)
    : m_tokens(std::move(tokens))
    , m_files(files)
    , m_model(model)
    , m_diagnostics(diagnostics)
{
    // The End token sits where the last real token is, so "unexpected end" points into the right file.
    IdlToken end;
    if (!m_tokens.isEmpty()) {
        end.file = m_tokens.last().file;
        end.line = m_tokens.last().line;
        end.column = m_tokens.last().column + int(m_tokens.last().text.size());
    }
    m_tokens.append(end);
    for (const IdlDeclaration &declaration : std::as_const(m_model->declarations))
        m_declared.insert(declaration.scopedName, declaration.kind);
    // Pseudo-objects that IDL compilers know without a declaration (corbaidl.idl uses them).
    m_declared.insert(QStringLiteral("CORBA::TypeCode"), IdlDeclaration::Kind::Native);
}

bool IdlSyntax::parse()
{
    try {
        while (current().kind != IdlToken::Kind::End)
            definition();
    } catch (const SyntaxError &) {
        return false;
    }
    return true;
}

const IdlToken &IdlSyntax::current() const
{
    return m_tokens.at(m_pos);
}

const IdlToken &IdlSyntax::peekToken(int ahead) const
{
    return m_tokens.at(std::min<qsizetype>(m_pos + ahead, m_tokens.size() - 1));
}

void IdlSyntax::next()
{
    if (m_pos < m_tokens.size() - 1)
        ++m_pos;
}

bool IdlSyntax::accept(QLatin1String punctuator)
{
    if (current().isPunctuator(punctuator)) {
        next();
        return true;
    }
    // `>>` closes two nested templates: take one `>` and leave the other in place.
    if (punctuator == QLatin1String(">") && current().isPunctuator(QLatin1String(">>"))) {
        m_tokens[m_pos].text = QStringLiteral(">");
        m_tokens[m_pos].column += 1;
        return true;
    }
    return false;
}

bool IdlSyntax::acceptKeyword(QLatin1String keyword)
{
    if (current().isIdentifier(keyword)) {
        next();
        return true;
    }
    return false;
}

void IdlSyntax::expect(QLatin1String punctuator)
{
    if (!accept(punctuator))
        syntaxError(QStringLiteral("expected '%1'").arg(punctuator));
}

QString IdlSyntax::expectIdentifier(const QString &what)
{
    if (current().kind != IdlToken::Kind::Identifier)
        syntaxError(QStringLiteral("expected %1").arg(what));
    const QString text = current().text;
    next();
    return text;
}

void IdlSyntax::syntaxError(const QString &message)
{
    const IdlToken &token = current();
    QString found;
    if (token.kind == IdlToken::Kind::End)
        found = QStringLiteral("end of file");
    else if (token.kind == IdlToken::Kind::String)
        found = QStringLiteral("a string");
    else
        found = QStringLiteral("'%1'").arg(token.text);
    error(token, QStringLiteral("%1, found %2").arg(message, found));
    throw SyntaxError();
}

void IdlSyntax::error(const IdlToken &at, const QString &message)
{
    if (m_diagnostics)
        m_diagnostics->append(Diagnostic::error(m_files.value(at.file), at.line, at.column, message));
}

IdlSource IdlSyntax::sourceOf(const IdlToken &token) const
{
    return IdlSource{m_files.value(token.file), token.line, token.column};
}

QString IdlSyntax::qualify(const QString &name) const
{
    return joinScope(m_scope, name);
}

bool IdlSyntax::declare(IdlDeclaration::Kind kind, const QString &name, const IdlToken &at)
{
    const QString scoped = qualify(name);
    const auto existing = m_declared.constFind(scoped);
    if (existing == m_declared.cend()) {
        m_declared.insert(scoped, kind);
        m_model->declarations.append(IdlDeclaration{kind, scoped, sourceOf(at)});
        return true;
    }
    const bool reopenedModule = kind == IdlDeclaration::Kind::Module && *existing == kind;
    const bool forwardInterface = kind == IdlDeclaration::Kind::Interface && *existing == kind
        && !m_model->interfaces.value(scoped).defined;
    if (reopenedModule || forwardInterface)
        return true;
    const auto first = m_model->find(scoped);
    const QString where = first ? QStringLiteral(" (first declared at %1:%2)")
                                      .arg(first->source.file)
                                      .arg(first->source.line)
                                : QString();
    error(at, QStringLiteral("redefinition of '%1'%2").arg(scoped, where));
    return false;
}

QString IdlSyntax::lookup(const QString &written) const
{
    if (written.startsWith(QLatin1String("::"))) {
        const QString absolute = written.mid(2);
        return m_declared.contains(absolute) ? absolute : QString();
    }
    // Innermost scope first; inside an interface the names of its bases are visible too.
    for (int depth = int(m_scope.size()); depth >= 0; --depth) {
        const QStringList scope = m_scope.mid(0, depth);
        const QString candidate = joinScope(scope, written);
        if (m_declared.contains(candidate))
            return candidate;
        const QString scopeName = scope.join(QLatin1String("::"));
        if (m_model->interfaces.contains(scopeName)) {
            for (const QString &base : m_model->allBases(scopeName)) {
                if (m_declared.contains(base + QLatin1String("::") + written))
                    return base + QLatin1String("::") + written;
            }
        }
    }
    return {};
}

QString IdlSyntax::scopedNameText(IdlToken *first)
{
    *first = current();
    QString text;
    if (accept(QLatin1String("::")))
        text = QStringLiteral("::");
    text += expectIdentifier(QStringLiteral("a name"));
    while (accept(QLatin1String("::")))
        text += QLatin1String("::") + expectIdentifier(QStringLiteral("a name after '::'"));
    return text;
}

void IdlSyntax::enterNesting()
{
    if (++m_depth > MaxNesting)
        syntaxError(QStringLiteral("declarations nested too deeply"));
}

void IdlSyntax::definition()
{
    const IdlToken start = current();
    if (acceptKeyword(QLatin1String("module"))) {
        module();
    } else if (current().isIdentifier(QLatin1String("abstract"))
               || current().isIdentifier(QLatin1String("local"))
               || current().isIdentifier(QLatin1String("interface"))) {
        const bool isAbstract = acceptKeyword(QLatin1String("abstract"));
        const bool isLocal = acceptKeyword(QLatin1String("local"));
        if (current().isIdentifier(QLatin1String("valuetype")))
            syntaxError(QStringLiteral("valuetypes are not supported"));
        if (!acceptKeyword(QLatin1String("interface")))
            syntaxError(QStringLiteral("expected 'interface'"));
        interfaceDeclaration(start, isAbstract, isLocal);
    } else if (acceptKeyword(QLatin1String("exception"))) {
        exceptionDeclaration();
    } else if (acceptKeyword(QLatin1String("const"))) {
        constDeclaration();
    } else if (acceptKeyword(QLatin1String("valuetype"))) {
        valueBox(start);
    } else if (current().isIdentifier(QLatin1String("custom"))
               || current().isIdentifier(QLatin1String("eventtype"))
               || current().isIdentifier(QLatin1String("component"))
               || current().isIdentifier(QLatin1String("home"))) {
        syntaxError(QStringLiteral("valuetypes and components are not supported"));
    } else {
        typeDeclaration();
    }
    expect(QLatin1String(";"));
}

void IdlSyntax::module()
{
    const IdlToken at = current();
    const QString name = expectIdentifier(QStringLiteral("a module name"));
    declare(IdlDeclaration::Kind::Module, name, at);
    expect(QLatin1String("{"));
    enterNesting();
    m_scope.append(name);
    while (!accept(QLatin1String("}"))) {
        if (current().kind == IdlToken::Kind::End)
            syntaxError(QStringLiteral("expected '}' to close module '%1'").arg(name));
        definition();
    }
    m_scope.removeLast();
    leaveNesting();
}

void IdlSyntax::interfaceDeclaration(const IdlToken &start, bool isAbstract, bool isLocal)
{
    const IdlToken at = current();
    const QString name = expectIdentifier(QStringLiteral("an interface name"));
    const QString scoped = qualify(name);
    const bool isNew = declare(IdlDeclaration::Kind::Interface, name, at);
    const bool wasKnown = m_model->interfaces.contains(scoped);
    IdlInterface interface = m_model->interfaces.value(scoped);
    interface.scopedName = scoped;
    interface.isAbstract = isAbstract;
    interface.isLocal = isLocal;
    if (!wasKnown)
        interface.source = sourceOf(start);
    if (current().isPunctuator(QLatin1String(";"))) {
        if (isNew && !wasKnown)
            m_model->interfaces.insert(scoped, interface);
        return; // forward declaration
    }
    interface.source = sourceOf(start);
    if (accept(QLatin1String(":"))) {
        do {
            IdlToken baseToken;
            const QString written = scopedNameText(&baseToken);
            const QString base = lookup(written);
            if (base.isEmpty() || m_declared.value(base) != IdlDeclaration::Kind::Interface)
                error(baseToken, QStringLiteral("unknown interface '%1'").arg(written));
            else
                interface.bases.append(base);
        } while (accept(QLatin1String(",")));
    }
    expect(QLatin1String("{"));
    interface.defined = true;
    // Store before the body, so operations can name the interface itself (e.g. return a reference).
    if (isNew)
        m_model->interfaces.insert(scoped, interface);
    enterNesting();
    m_scope.append(name);
    interfaceBody(&interface);
    m_scope.removeLast();
    leaveNesting();
    if (isNew)
        m_model->interfaces.insert(scoped, interface);
}

void IdlSyntax::interfaceBody(IdlInterface *interface)
{
    while (!accept(QLatin1String("}"))) {
        if (current().kind == IdlToken::Kind::End)
            syntaxError(QStringLiteral("expected '}' to close interface '%1'").arg(interface->scopedName));
        if (acceptKeyword(QLatin1String("exception")))
            exceptionDeclaration();
        else if (acceptKeyword(QLatin1String("const")))
            constDeclaration();
        else if (current().isIdentifier(QLatin1String("readonly"))
                 || current().isIdentifier(QLatin1String("attribute")))
            attribute(interface);
        else if (current().isIdentifier(QLatin1String("typedef")) || current().isIdentifier(QLatin1String("struct"))
                 || current().isIdentifier(QLatin1String("union")) || current().isIdentifier(QLatin1String("enum"))
                 || current().isIdentifier(QLatin1String("native")))
            typeDeclaration();
        else
            operation(interface);
        expect(QLatin1String(";"));
    }
}

void IdlSyntax::operation(IdlInterface *interface)
{
    IdlOperation operation;
    operation.interfaceName = interface->scopedName;
    operation.source = sourceOf(current());
    operation.oneway = acceptKeyword(QLatin1String("oneway"));
    operation.returnType = acceptKeyword(QLatin1String("void")) ? IdlType::basic(QStringLiteral("void"))
                                                                 : simpleTypeSpec();
    const IdlToken at = current();
    operation.name = expectIdentifier(QStringLiteral("an operation name"));
    declare(IdlDeclaration::Kind::Operation, operation.name, at);
    expect(QLatin1String("("));
    if (!accept(QLatin1String(")"))) {
        do {
            operation.parameters.append(parameter());
        } while (accept(QLatin1String(",")));
        expect(QLatin1String(")"));
    }
    operation.raises = raisesClause();
    if (acceptKeyword(QLatin1String("context"))) {
        expect(QLatin1String("("));
        do {
            if (current().kind != IdlToken::Kind::String)
                syntaxError(QStringLiteral("expected a string in context(...)"));
            operation.contexts.append(current().text);
            next();
        } while (accept(QLatin1String(",")));
        expect(QLatin1String(")"));
    }
    interface->operations.append(operation);
}

IdlParameter IdlSyntax::parameter()
{
    IdlParameter parameter;
    parameter.source = sourceOf(current());
    if (acceptKeyword(QLatin1String("in")))
        parameter.mode = IdlParameter::Mode::In;
    else if (acceptKeyword(QLatin1String("out")))
        parameter.mode = IdlParameter::Mode::Out;
    else if (acceptKeyword(QLatin1String("inout")))
        parameter.mode = IdlParameter::Mode::InOut;
    else
        syntaxError(QStringLiteral("expected 'in', 'out' or 'inout'"));
    parameter.type = simpleTypeSpec();
    parameter.name = expectIdentifier(QStringLiteral("a parameter name"));
    return parameter;
}

QStringList IdlSyntax::raisesClause()
{
    QStringList raises;
    if (!acceptKeyword(QLatin1String("raises")))
        return raises;
    expect(QLatin1String("("));
    do {
        IdlToken at;
        const QString written = scopedNameText(&at);
        const QString scoped = lookup(written);
        if (scoped.isEmpty() || m_declared.value(scoped) != IdlDeclaration::Kind::Exception)
            error(at, QStringLiteral("unknown exception '%1'").arg(written));
        raises.append(scoped.isEmpty() ? written : scoped);
    } while (accept(QLatin1String(",")));
    expect(QLatin1String(")"));
    return raises;
}

void IdlSyntax::attribute(IdlInterface *interface)
{
    IdlAttribute attribute;
    attribute.interfaceName = interface->scopedName;
    attribute.source = sourceOf(current());
    attribute.readonly = acceptKeyword(QLatin1String("readonly"));
    if (!acceptKeyword(QLatin1String("attribute")))
        syntaxError(QStringLiteral("expected 'attribute'"));
    attribute.type = simpleTypeSpec();
    do {
        const IdlToken at = current();
        attribute.name = expectIdentifier(QStringLiteral("an attribute name"));
        declare(IdlDeclaration::Kind::Attribute, attribute.name, at);
        interface->attributes.append(attribute);
    } while (accept(QLatin1String(",")));
    raisesClause(); // getraises/setraises are rare in component IDL; plain raises is accepted
}

void IdlSyntax::exceptionDeclaration()
{
    const IdlToken at = current();
    IdlException exception;
    exception.source = sourceOf(at);
    const QString name = expectIdentifier(QStringLiteral("an exception name"));
    exception.scopedName = qualify(name);
    const bool isNew = declare(IdlDeclaration::Kind::Exception, name, at);
    expect(QLatin1String("{"));
    enterNesting();
    m_scope.append(name);
    exception.members = memberList(QStringLiteral("exception '%1'").arg(exception.scopedName));
    m_scope.removeLast();
    leaveNesting();
    if (isNew)
        m_model->exceptions.insert(exception.scopedName, exception);
}

void IdlSyntax::constDeclaration()
{
    IdlConst constant;
    constant.type = simpleTypeSpec();
    const IdlToken at = current();
    constant.source = sourceOf(at);
    const QString name = expectIdentifier(QStringLiteral("a constant name"));
    constant.scopedName = qualify(name);
    expect(QLatin1String("="));
    constant.value = constExpression().toLiteral();
    if (declare(IdlDeclaration::Kind::Const, name, at))
        m_model->consts.insert(constant.scopedName, constant);
}

void IdlSyntax::valueBox(const IdlToken &start)
{
    const IdlToken at = current();
    const QString name = expectIdentifier(QStringLiteral("a valuetype name"));
    if (current().isPunctuator(QLatin1String("{")) || current().isPunctuator(QLatin1String(":"))
        || current().isPunctuator(QLatin1String(";")) || current().isIdentifier(QLatin1String("supports")))
        syntaxError(QStringLiteral("valuetypes are not supported (only value boxes)"));
    IdlTypedef box{qualify(name), typeSpec(), sourceOf(start)};
    if (declare(IdlDeclaration::Kind::Typedef, name, at))
        m_model->typedefs.insert(box.scopedName, box);
}

} // namespace Codegen
