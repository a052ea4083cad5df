// SPDX-License-Identifier: MIT
#include "idllexer.h"

namespace Codegen {

using Profile::Diagnostic;
using Profile::Diagnostics;

IdlLexer::IdlLexer(const QString &text, const QString &fileName)
    : m_text(text)
    , m_fileName(fileName)
{
}

QChar IdlLexer::peek(int ahead) const
{
    const int index = m_pos + ahead;
    return index < m_text.size() ? m_text.at(index) : QChar();
}

void IdlLexer::advance(int count)
{
    for (int i = 0; i < count && m_pos < m_text.size(); ++i) {
        if (m_text.at(m_pos) == QLatin1Char('\n')) {
            ++m_line;
            m_column = 1;
            m_lineStart = true;
        } else {
            ++m_column;
        }
        ++m_pos;
    }
}

void IdlLexer::error(Diagnostics *diagnostics, int line, int column, const QString &message) const
{
    if (diagnostics)
        diagnostics->append(Diagnostic::error(m_fileName, line, column, message));
}

QList<IdlToken> IdlLexer::tokenize(Diagnostics *diagnostics)
{
    QList<IdlToken> tokens;
    for (;;) {
        skipSpaceAndComments(diagnostics);
        const QChar c = peek();
        if (c.isNull())
            break;
        const bool wideLiteral = c == QLatin1Char('L')
            && (peek(1) == QLatin1Char('"') || peek(1) == QLatin1Char('\''));
        if (c == QLatin1Char('#') && m_lineStart)
            tokens.append(readDirective());
        else if (wideLiteral) {
            advance();
            tokens.append(readQuoted(peek(), diagnostics));
            tokens.last().wide = true;
            tokens.last().column -= 1;
        } else if (c.isDigit() || (c == QLatin1Char('.') && peek(1).isDigit()))
            tokens.append(readNumber());
        else if (c.isLetter() || c == QLatin1Char('_'))
            tokens.append(readIdentifier());
        else if (c == QLatin1Char('"') || c == QLatin1Char('\''))
            tokens.append(readQuoted(c, diagnostics));
        else if (QStringLiteral("{}()<>[];:,=+-*/%&|^~!").contains(c))
            tokens.append(readPunctuator());
        else {
            error(diagnostics, m_line, m_column, QStringLiteral("unexpected character '%1'").arg(c));
            advance();
        }
        m_lineStart = false;
    }
    IdlToken end;
    end.line = m_line;
    end.column = m_column;
    tokens.append(end);
    return tokens;
}

void IdlLexer::skipSpaceAndComments(Diagnostics *diagnostics)
{
    for (;;) {
        const QChar c = peek();
        if (c == QLatin1Char('\n') || c.isSpace()) {
            advance(); // advance() keeps m_lineStart true across a newline
        } else if (c == QLatin1Char('/') && peek(1) == QLatin1Char('/')) {
            while (!peek().isNull() && peek() != QLatin1Char('\n'))
                advance();
        } else if (c == QLatin1Char('/') && peek(1) == QLatin1Char('*')) {
            const int line = m_line;
            const int column = m_column;
            const bool atLineStart = m_lineStart;
            advance(2);
            while (!peek().isNull() && !(peek() == QLatin1Char('*') && peek(1) == QLatin1Char('/')))
                advance();
            if (peek().isNull()) {
                error(diagnostics, line, column, QStringLiteral("unterminated comment"));
                return;
            }
            advance(2);
            // A comment does not end "start of line" for a following directive only when it began there.
            m_lineStart = m_lineStart || atLineStart;
        } else {
            return;
        }
    }
}

IdlToken IdlLexer::readDirective()
{
    IdlToken token;
    token.kind = IdlToken::Kind::Directive;
    token.line = m_line;
    token.column = m_column;
    advance(); // '#'
    QString text;
    while (!peek().isNull() && peek() != QLatin1Char('\n')) {
        if (peek() == QLatin1Char('\\') && peek(1) == QLatin1Char('\n')) {
            advance(2);
            text += QLatin1Char(' ');
            continue;
        }
        if (peek() == QLatin1Char('/') && peek(1) == QLatin1Char('/'))
            break; // a trailing comment is no part of the directive
        text += peek();
        advance();
    }
    token.text = text.trimmed();
    return token;
}

IdlToken IdlLexer::readNumber()
{
    IdlToken token;
    token.kind = IdlToken::Kind::Integer;
    token.line = m_line;
    token.column = m_column;
    const int start = m_pos;
    if (peek() == QLatin1Char('0') && (peek(1) == QLatin1Char('x') || peek(1) == QLatin1Char('X'))) {
        advance(2);
        while (isxdigit(peek().toLatin1()) && !peek().isNull())
            advance();
    } else {
        while (peek().isDigit())
            advance();
        if (peek() == QLatin1Char('.')) {
            token.kind = IdlToken::Kind::Float;
            advance();
            while (peek().isDigit())
                advance();
        }
        const bool exponent = peek() == QLatin1Char('e') || peek() == QLatin1Char('E');
        const bool signedExponent = (peek(1) == QLatin1Char('+') || peek(1) == QLatin1Char('-'))
            && peek(2).isDigit();
        if (exponent && (peek(1).isDigit() || signedExponent)) {
            token.kind = IdlToken::Kind::Float;
            advance(signedExponent ? 2 : 1);
            while (peek().isDigit())
                advance();
        }
        if (peek() == QLatin1Char('d') || peek() == QLatin1Char('D')) {
            token.kind = IdlToken::Kind::Float; // fixed-point literal; kept as a number
            advance();
        }
    }
    token.text = m_text.mid(start, m_pos - start);
    return token;
}

IdlToken IdlLexer::readIdentifier()
{
    IdlToken token;
    token.kind = IdlToken::Kind::Identifier;
    token.line = m_line;
    token.column = m_column;
    const int start = m_pos;
    while (peek().isLetterOrNumber() || peek() == QLatin1Char('_'))
        advance();
    token.text = m_text.mid(start, m_pos - start);
    // An escaped identifier `_name` stands for `name` (it lets IDL use keywords as names).
    if (token.text.size() > 1 && token.text.startsWith(QLatin1Char('_')))
        token.text.remove(0, 1);
    return token;
}

IdlToken IdlLexer::readQuoted(QChar quote, Diagnostics *diagnostics)
{
    IdlToken token;
    token.kind = quote == QLatin1Char('"') ? IdlToken::Kind::String : IdlToken::Kind::Char;
    token.line = m_line;
    token.column = m_column;
    advance();
    while (!peek().isNull() && peek() != quote && peek() != QLatin1Char('\n')) {
        if (peek() == QLatin1Char('\\')) {
            token.text += readEscape(diagnostics);
        } else {
            token.text += peek();
            advance();
        }
    }
    if (peek() != quote) {
        error(diagnostics, token.line, token.column,
              token.kind == IdlToken::Kind::String ? QStringLiteral("unterminated string literal")
                                                   : QStringLiteral("unterminated character literal"));
        return token;
    }
    advance();
    if (token.kind == IdlToken::Kind::Char && token.text.size() != 1)
        error(diagnostics, token.line, token.column,
              QStringLiteral("a character literal holds exactly one character"));
    return token;
}

QChar IdlLexer::readEscape(Diagnostics *diagnostics)
{
    const int line = m_line;
    const int column = m_column;
    advance(); // backslash
    const QChar c = peek();
    advance();
    switch (c.toLatin1()) {
    case 'n': return QLatin1Char('\n');
    case 't': return QLatin1Char('\t');
    case 'v': return QLatin1Char('\v');
    case 'b': return QLatin1Char('\b');
    case 'r': return QLatin1Char('\r');
    case 'f': return QLatin1Char('\f');
    case 'a': return QLatin1Char('\a');
    case '\\': return QLatin1Char('\\');
    case '?': return QLatin1Char('?');
    case '\'': return QLatin1Char('\'');
    case '"': return QLatin1Char('"');
    case 'x': {
        QString digits;
        while (digits.size() < 2 && isxdigit(peek().toLatin1()) && !peek().isNull()) {
            digits += peek();
            advance();
        }
        return QChar(digits.toUShort(nullptr, 16));
    }
    default:
        break;
    }
    if (c >= QLatin1Char('0') && c <= QLatin1Char('7')) {
        QString digits(c);
        while (digits.size() < 3 && peek() >= QLatin1Char('0') && peek() <= QLatin1Char('7')) {
            digits += peek();
            advance();
        }
        return QChar(digits.toUShort(nullptr, 8));
    }
    error(diagnostics, line, column, QStringLiteral("unknown escape sequence '\\%1'").arg(c));
    return c;
}

IdlToken IdlLexer::readPunctuator()
{
    IdlToken token;
    token.kind = IdlToken::Kind::Punctuator;
    token.line = m_line;
    token.column = m_column;
    const QString two = m_text.mid(m_pos, 2);
    if (two == QLatin1String("::") || two == QLatin1String("<<") || two == QLatin1String(">>")) {
        token.text = two;
        advance(2);
    } else {
        token.text = peek();
        advance();
    }
    return token;
}

} // namespace Codegen
