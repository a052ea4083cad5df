// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"

#include <QList>
#include <QString>

namespace Codegen {

/// One lexical token of an IDL file.
struct IdlToken
{
    enum class Kind {
        Identifier, ///< identifiers and keywords (IDL keywords are told apart by the parser); `_x` is `x`
        Integer,    ///< text as written: `42`, `0x1F`, `017`
        Float,      ///< text as written: `1.5e3`
        Char,       ///< decoded value in `text`; `wide` for L'x'
        String,     ///< decoded value in `text`; `wide` for L"x"
        Punctuator, ///< `::`, `<<`, `>>` or one character
        Directive,  ///< a whole preprocessor line without the `#`, continuation lines joined
        End         ///< end of the input
    };

    Kind kind = Kind::End;
    QString text;
    bool wide = false;
    int line = 1;   ///< 1-based
    int column = 1; ///< 1-based
    int file = 0;   ///< index into the preprocessor's file list

    bool is(Kind k, QLatin1String value) const { return kind == k && text == value; }
    bool isPunctuator(QLatin1String value) const { return is(Kind::Punctuator, value); }
    bool isIdentifier(QLatin1String value) const { return is(Kind::Identifier, value); }
};

/// Splits IDL text into tokens with positions. Comments are dropped; a `#` first on a line starts a
/// Directive token. Lexical errors are reported and the offending characters skipped.
class IdlLexer
{
public:
    IdlLexer(const QString &text, const QString &fileName);

    /// All tokens, ending with one End token.
    QList<IdlToken> tokenize(Profile::Diagnostics *diagnostics);

private:
    QChar peek(int ahead = 0) const;
    void advance(int count = 1);
    void skipSpaceAndComments(Profile::Diagnostics *diagnostics);
    IdlToken readDirective();
    IdlToken readNumber();
    IdlToken readIdentifier();
    IdlToken readQuoted(QChar quote, Profile::Diagnostics *diagnostics);
    QChar readEscape(Profile::Diagnostics *diagnostics);
    IdlToken readPunctuator();
    void error(Profile::Diagnostics *diagnostics, int line, int column, const QString &message) const;

    QString m_text;
    QString m_fileName;
    int m_pos = 0;
    int m_line = 1;
    int m_column = 1;
    bool m_lineStart = true; ///< only whitespace since the last newline
};

} // namespace Codegen
