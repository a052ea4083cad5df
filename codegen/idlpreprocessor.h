// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "idllexer.h"

#include <QList>
#include <QSet>
#include <QMap>
#include <QString>
#include <QStringList>

namespace Codegen {

/// Turns IDL files into one token stream: `#include` is replaced by the included file's tokens (each
/// file only once over the preprocessor's lifetime, so cycles are safe), `#ifdef`/`#ifndef`/`#if`/
/// `#else`/`#elif`/`#endif` on macros defined by `#define` select what is kept; of the pragmas only
/// `#pragma prefix "…"` counts (prefixes()), the others are ignored.
/// Macros are only tested, never substituted.
class IdlPreprocessor
{
public:
    explicit IdlPreprocessor(Profile::Diagnostics *diagnostics);

    void setSearchDirectories(const QStringList &directories);
    /// Defines a macro as if by `#define name`.
    void define(const QString &name);

    /// Appends the tokens of `path` (and what it includes). False when it cannot be read. A file read
    /// before is skipped and counts as success.
    bool processFile(const QString &path);
    /// Appends the tokens of in-memory text; includes are resolved against the search directories.
    void processText(const QString &text, const QString &fileName);

    /// The tokens gathered so far (without End tokens), and forgets them.
    QList<IdlToken> takeTokens();
    /// Every file read so far, as opened; IdlToken::file indexes this list.
    const QStringList &files() const { return m_files; }
    /// The `#pragma prefix` lines read so far: file as opened → line → prefix from there on.
    const QMap<QString, QMap<int, QString>> &prefixes() const { return m_prefixes; }

private:
    struct Condition
    {
        bool parentActive = true;
        bool active = true;
        bool taken = false; ///< some branch of this #if group was already chosen
        bool seenElse = false;
        IdlToken where;
    };

    bool processFileAt(const QString &path, const IdlToken *includedFrom, int depth);
    void processTokens(const QList<IdlToken> &tokens, int fileIndex, int depth);
    void directive(const IdlToken &token, int depth, QList<Condition> *conditions);
    void conditional(const QString &keyword, const QString &argument, const IdlToken &token,
                     QList<Condition> *conditions);
    void include(const QString &argument, const IdlToken &token, int depth);
    void pragma(const QString &argument, const IdlToken &token);
    QString findInclude(const QString &name, bool quoted, const QString &fileName) const;
    bool evaluateIf(const QString &expression, const IdlToken &token);
    void report(Profile::Diagnostic::Severity severity, const QString &fileName, const IdlToken &token,
                const QString &message);

    Profile::Diagnostics *m_diagnostics;
    QStringList m_searchDirectories;
    QSet<QString> m_macros;
    QSet<QString> m_seen; ///< canonical paths already read
    QStringList m_files;
    QMap<QString, QMap<int, QString>> m_prefixes;
    QList<IdlToken> m_tokens;
};

} // namespace Codegen
