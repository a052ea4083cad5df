// SPDX-License-Identifier: MIT
// Constant expressions of IDL: integers (64-bit), floats, strings, chars, booleans and enumerators,
// with the C operators IDL allows and references to other constants.
#include "idlsyntax_p.h"

#include <limits>

namespace Codegen {

QString IdlSyntax::Value::toLiteral() const
{
    switch (kind) {
    case Kind::Integer:
        return QString::number(integer);
    case Kind::Float:
        return QString::number(real, 'g', 17);
    case Kind::String:
        return QLatin1Char('"') + text + QLatin1Char('"');
    case Kind::Char:
        return QLatin1Char('\'') + text + QLatin1Char('\'');
    case Kind::Boolean:
        return integer ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
    case Kind::Enumerator:
        return text;
    }
    return text;
}

qint64 IdlSyntax::integerOf(const Value &value, const IdlToken &at)
{
    if (value.kind != Value::Kind::Integer)
        error(at, QStringLiteral("expected an integer constant, found %1").arg(value.toLiteral()));
    return value.integer;
}

IdlSyntax::Value IdlSyntax::constExpression()
{
    enterNesting();
    const Value value = orExpression();
    leaveNesting();
    return value;
}

IdlSyntax::Value IdlSyntax::orExpression()
{
    Value value = xorExpression();
    while (current().isPunctuator(QLatin1String("|"))) {
        const IdlToken at = current();
        next();
        value = binary(value, xorExpression(), QLatin1Char('|'), at);
    }
    return value;
}

IdlSyntax::Value IdlSyntax::xorExpression()
{
    Value value = andExpression();
    while (current().isPunctuator(QLatin1String("^"))) {
        const IdlToken at = current();
        next();
        value = binary(value, andExpression(), QLatin1Char('^'), at);
    }
    return value;
}

IdlSyntax::Value IdlSyntax::andExpression()
{
    Value value = shiftExpression();
    while (current().isPunctuator(QLatin1String("&"))) {
        const IdlToken at = current();
        next();
        value = binary(value, shiftExpression(), QLatin1Char('&'), at);
    }
    return value;
}

IdlSyntax::Value IdlSyntax::shiftExpression()
{
    Value value = addExpression();
    while (current().isPunctuator(QLatin1String("<<")) || current().isPunctuator(QLatin1String(">>"))) {
        const IdlToken at = current();
        next();
        value = binary(value, addExpression(), at.text == QLatin1String("<<") ? QLatin1Char('<') : QLatin1Char('>'),
                       at);
    }
    return value;
}

IdlSyntax::Value IdlSyntax::addExpression()
{
    Value value = mulExpression();
    while (current().isPunctuator(QLatin1String("+")) || current().isPunctuator(QLatin1String("-"))) {
        const IdlToken at = current();
        next();
        value = binary(value, mulExpression(), at.text.at(0), at);
    }
    return value;
}

IdlSyntax::Value IdlSyntax::mulExpression()
{
    Value value = unaryExpression();
    while (current().isPunctuator(QLatin1String("*")) || current().isPunctuator(QLatin1String("/"))
           || current().isPunctuator(QLatin1String("%"))) {
        const IdlToken at = current();
        next();
        value = binary(value, unaryExpression(), at.text.at(0), at);
    }
    return value;
}

IdlSyntax::Value IdlSyntax::unaryExpression()
{
    const IdlToken at = current();
    if (accept(QLatin1String("-")) || accept(QLatin1String("+")) || accept(QLatin1String("~"))) {
        enterNesting(); // `- - - - ...` must not exhaust the stack
        Value value = unaryExpression();
        leaveNesting();
        if (at.text == QLatin1String("+"))
            return value;
        if (value.kind == Value::Kind::Float && at.text == QLatin1String("-")) {
            value.real = -value.real;
            return value;
        }
        const qint64 operand = integerOf(value, at);
        value.kind = Value::Kind::Integer;
        // Negating through unsigned arithmetic keeps INT64_MIN from being undefined behaviour.
        value.integer = at.text == QLatin1String("-") ? qint64(0ULL - quint64(operand)) : ~operand;
        return value;
    }
    return primaryExpression();
}

IdlSyntax::Value IdlSyntax::primaryExpression()
{
    if (accept(QLatin1String("("))) {
        const Value value = constExpression();
        expect(QLatin1String(")"));
        return value;
    }
    if (current().kind == IdlToken::Kind::Identifier || current().isPunctuator(QLatin1String("::"))) {
        if (current().text == QLatin1String("TRUE") || current().text == QLatin1String("FALSE")) {
            Value value;
            value.kind = Value::Kind::Boolean;
            value.integer = current().text == QLatin1String("TRUE");
            next();
            return value;
        }
        IdlToken at;
        const QString written = scopedNameText(&at);
        const QString scoped = lookup(written);
        Value value;
        if (m_model->consts.contains(scoped)) {
            // Re-reading the stored literal keeps the model the only place where constants live.
            const IdlConst &constant = m_model->consts.value(scoped);
            if (const auto integer = constant.integerValue()) {
                value.integer = *integer;
            } else if (constant.value.startsWith(QLatin1Char('"')) || constant.value.startsWith(QLatin1Char('\''))) {
                value.kind = constant.value.startsWith(QLatin1Char('"')) ? Value::Kind::String : Value::Kind::Char;
                value.text = constant.value.mid(1, constant.value.size() - 2);
            } else if (constant.value == QLatin1String("TRUE") || constant.value == QLatin1String("FALSE")) {
                value.kind = Value::Kind::Boolean;
                value.integer = constant.value == QLatin1String("TRUE");
            } else if (bool ok = false; value.real = constant.value.toDouble(&ok), ok) {
                value.kind = Value::Kind::Float;
            } else {
                value.kind = Value::Kind::Enumerator;
                value.text = constant.value;
            }
            return value;
        }
        if (m_declared.value(scoped) == IdlDeclaration::Kind::Enumerator && !scoped.isEmpty()) {
            value.kind = Value::Kind::Enumerator;
            value.text = scoped;
            return value;
        }
        error(at, QStringLiteral("unknown constant '%1'").arg(written));
        return value;
    }
    return literal();
}

IdlSyntax::Value IdlSyntax::literal()
{
    const IdlToken at = current();
    Value value;
    switch (at.kind) {
    case IdlToken::Kind::Integer: {
        bool ok = false;
        // Base 0 reads 0x.. as hex and 0.. as octal, as IDL (and C) do.
        const quint64 number = at.text.toULongLong(&ok, 0);
        if (!ok || number > quint64(std::numeric_limits<qint64>::max()))
            error(at, QStringLiteral("integer literal '%1' out of range").arg(at.text));
        value.integer = qint64(number);
        break;
    }
    case IdlToken::Kind::Float:
        value.kind = Value::Kind::Float;
        value.real = QString(at.text).remove(QLatin1Char('d')).remove(QLatin1Char('D')).toDouble();
        break;
    case IdlToken::Kind::String:
        value.kind = Value::Kind::String;
        value.text = at.text;
        // Adjacent string literals are one string, as in C.
        while (peekToken(1).kind == IdlToken::Kind::String) {
            next();
            value.text += current().text;
        }
        break;
    case IdlToken::Kind::Char:
        value.kind = Value::Kind::Char;
        value.text = at.text;
        break;
    default:
        syntaxError(QStringLiteral("expected a constant expression"));
    }
    next();
    return value;
}

IdlSyntax::Value IdlSyntax::binary(const Value &left, const Value &right, QChar op, const IdlToken &at)
{
    const bool floating = left.kind == Value::Kind::Float || right.kind == Value::Kind::Float;
    Value result;
    if (floating && QStringLiteral("+-*/").contains(op)) {
        const double a = left.kind == Value::Kind::Float ? left.real : double(left.integer);
        const double b = right.kind == Value::Kind::Float ? right.real : double(right.integer);
        result.kind = Value::Kind::Float;
        result.real = op == QLatin1Char('+') ? a + b : op == QLatin1Char('-') ? a - b : op == QLatin1Char('*') ? a * b : a / b;
        return result;
    }
    // Unsigned arithmetic wraps instead of overflowing into undefined behaviour.
    const quint64 a = quint64(integerOf(left, at));
    const quint64 b = quint64(integerOf(right, at));
    const bool divides = op == QLatin1Char('/') || op == QLatin1Char('%');
    if (divides && b == 0) {
        error(at, QStringLiteral("division by zero in a constant expression"));
        return result;
    }
    if ((op == QLatin1Char('<') || op == QLatin1Char('>')) && b >= 64) {
        error(at, QStringLiteral("shift by %1 bits is out of range").arg(qint64(b)));
        return result;
    }
    switch (op.toLatin1()) {
    case '|': result.integer = qint64(a | b); break;
    case '^': result.integer = qint64(a ^ b); break;
    case '&': result.integer = qint64(a & b); break;
    case '<': result.integer = qint64(a << b); break;
    case '>': result.integer = qint64(a) >> b; break;
    case '+': result.integer = qint64(a + b); break;
    case '-': result.integer = qint64(a - b); break;
    case '*': result.integer = qint64(a * b); break;
    case '/': result.integer = qint64(a) == std::numeric_limits<qint64>::min() && qint64(b) == -1
                                   ? qint64(a) : qint64(a) / qint64(b); break;
    case '%': result.integer = qint64(b) == -1 ? 0 : qint64(a) % qint64(b); break;
    default: break;
    }
    return result;
}

} // namespace Codegen
