// SPDX-License-Identifier: MIT
#include "idlpreprocessor.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

namespace Codegen {

using Profile::Diagnostic;
using Profile::Diagnostics;

namespace {

// Deeper include chains than this are surely a mistake; stopping keeps the stack bounded.
constexpr int MaxIncludeDepth = 64;
// IDL files are small; refusing huge files keeps a wrong path (a disk image, say) from eating memory.
constexpr qint64 MaxFileSize = 16 * 1024 * 1024;

QString canonicalPath(const QString &path)
{
    const QString canonical = QFileInfo(path).canonicalFilePath();
    return canonical.isEmpty() ? QFileInfo(path).absoluteFilePath() : canonical;
}

} // namespace

IdlPreprocessor::IdlPreprocessor(Diagnostics *diagnostics)
    : m_diagnostics(diagnostics)
{
}

void IdlPreprocessor::setSearchDirectories(const QStringList &directories)
{
    m_searchDirectories = directories;
}

void IdlPreprocessor::define(const QString &name)
{
    m_macros.insert(name);
}

bool IdlPreprocessor::processFile(const QString &path)
{
    return processFileAt(path, nullptr, 0);
}

void IdlPreprocessor::processText(const QString &text, const QString &fileName)
{
    m_files.append(fileName);
    const int index = int(m_files.size()) - 1;
    IdlLexer lexer(text, fileName);
    processTokens(lexer.tokenize(m_diagnostics), index, 0);
}

QList<IdlToken> IdlPreprocessor::takeTokens()
{
    QList<IdlToken> tokens;
    tokens.swap(m_tokens);
    return tokens;
}

bool IdlPreprocessor::processFileAt(const QString &path, const IdlToken *includedFrom, int depth)
{
    const QString canonical = canonicalPath(path);
    if (m_seen.contains(canonical))
        return true;
    QFile file(path);
    QString problem;
    if (!file.open(QIODevice::ReadOnly))
        problem = QStringLiteral("cannot open '%1': %2").arg(path, file.errorString());
    else if (file.size() > MaxFileSize)
        problem = QStringLiteral("'%1' is too large for an IDL file").arg(path);
    if (!problem.isEmpty()) {
        if (includedFrom)
            report(Diagnostic::Severity::Error, m_files.value(includedFrom->file), *includedFrom, problem);
        else if (m_diagnostics)
            m_diagnostics->append(Diagnostic::error(path, 0, 0, problem));
        return false;
    }
    m_seen.insert(canonical);
    m_files.append(path);
    const int index = int(m_files.size()) - 1;
    IdlLexer lexer(QString::fromUtf8(file.readAll()), path);
    processTokens(lexer.tokenize(m_diagnostics), index, depth);
    return true;
}

void IdlPreprocessor::processTokens(const QList<IdlToken> &tokens, int fileIndex, int depth)
{
    const QString fileName = m_files.at(fileIndex);
    QList<Condition> conditions;
    for (IdlToken token : tokens) {
        token.file = fileIndex;
        const bool active = conditions.isEmpty() || conditions.last().active;
        if (token.kind == IdlToken::Kind::Directive)
            directive(token, depth, &conditions);
        else if (token.kind != IdlToken::Kind::End && active)
            m_tokens.append(token);
    }
    for (const Condition &open : conditions)
        report(Diagnostic::Severity::Error, fileName, open.where,
               QStringLiteral("#if/#ifdef/#ifndef without #endif"));
}

void IdlPreprocessor::directive(const IdlToken &token, int depth, QList<Condition> *conditions)
{
    const QString fileName = m_files.at(token.file);
    static const QRegularExpression split(QStringLiteral("^\\s*(\\w*)\\s*(.*)$"));
    const QRegularExpressionMatch match = split.match(token.text);
    const QString keyword = match.captured(1);
    const QString argument = match.captured(2).trimmed();
    static const QStringList conditionals{QStringLiteral("if"), QStringLiteral("ifdef"),
                                          QStringLiteral("ifndef"), QStringLiteral("elif"),
                                          QStringLiteral("else"), QStringLiteral("endif")};
    if (conditionals.contains(keyword)) {
        conditional(keyword, argument, token, conditions);
        return;
    }
    if (!conditions->isEmpty() && !conditions->last().active)
        return;
    if (keyword == QLatin1String("include"))
        include(argument, token, depth);
    else if (keyword == QLatin1String("define"))
        m_macros.insert(argument.section(QRegularExpression(QStringLiteral("[\\s(]")), 0, 0));
    else if (keyword == QLatin1String("undef"))
        m_macros.remove(argument);
    else if (keyword == QLatin1String("error"))
        report(Diagnostic::Severity::Error, fileName, token, QStringLiteral("#error %1").arg(argument));
    else if (keyword == QLatin1String("pragma"))
        pragma(argument, token);
    else if (keyword == QLatin1String("line") || keyword == QLatin1String("warning") || keyword.isEmpty())
        return;
    else
        report(Diagnostic::Severity::Warning, fileName, token,
               QStringLiteral("unknown preprocessor directive '#%1' ignored").arg(keyword));
}

void IdlPreprocessor::pragma(const QString &argument, const IdlToken &token)
{
    // `#pragma prefix "acme.com"` prefixes the type ids of what the file declares after it; the
    // other pragmas (version, ID, omniORB's hh) do not change what the types are.
    static const QRegularExpression prefix(QStringLiteral("^prefix\\s+\"([^\"]*)\"$"));
    const QRegularExpressionMatch match = prefix.match(argument);
    if (match.hasMatch())
        m_prefixes[m_files.at(token.file)].insert(token.line, match.captured(1));
}

void IdlPreprocessor::conditional(const QString &keyword, const QString &argument, const IdlToken &token,
                                  QList<Condition> *conditions)
{
    const QString fileName = m_files.at(token.file);
    const bool outerActive = conditions->isEmpty() || conditions->last().active;
    if (keyword.startsWith(QLatin1String("if"))) {
        Condition condition;
        condition.parentActive = outerActive;
        condition.where = token;
        bool value = false;
        if (keyword == QLatin1String("ifdef"))
            value = m_macros.contains(argument);
        else if (keyword == QLatin1String("ifndef"))
            value = !m_macros.contains(argument);
        else
            value = evaluateIf(argument, token);
        condition.active = outerActive && value;
        condition.taken = value;
        conditions->append(condition);
        return;
    }
    if (conditions->isEmpty()) {
        report(Diagnostic::Severity::Error, fileName, token, QStringLiteral("#%1 without #if").arg(keyword));
        return;
    }
    Condition &condition = conditions->last();
    if (keyword == QLatin1String("endif")) {
        conditions->removeLast();
    } else if (condition.seenElse) {
        report(Diagnostic::Severity::Error, fileName, token, QStringLiteral("#%1 after #else").arg(keyword));
    } else if (keyword == QLatin1String("else")) {
        condition.seenElse = true;
        condition.active = condition.parentActive && !condition.taken;
        condition.taken = true;
    } else { // elif
        const bool value = !condition.taken && evaluateIf(argument, token);
        condition.active = condition.parentActive && value;
        condition.taken = condition.taken || value;
    }
}

bool IdlPreprocessor::evaluateIf(const QString &expression, const IdlToken &token)
{
    // Enough for what IDL files use: a number, or `[!]defined(NAME)` / `[!]defined NAME` joined by
    // `&&` or `||` (evaluated left to right).
    static const QRegularExpression term(
        QStringLiteral("^\\s*(!?)\\s*(?:(\\d+)|defined\\s*\\(\\s*(\\w+)\\s*\\)|defined\\s+(\\w+))\\s*"));
    QString rest = expression;
    bool result = false;
    QString joiner;
    for (;;) {
        const QRegularExpressionMatch match = term.match(rest);
        if (!match.hasMatch()) {
            report(Diagnostic::Severity::Warning, m_files.at(token.file), token,
                   QStringLiteral("cannot evaluate '#if %1'; taken as false").arg(expression));
            return false;
        }
        bool value = match.captured(2).isEmpty()
            ? m_macros.contains(match.captured(3) + match.captured(4))
            : match.captured(2).toLongLong() != 0;
        if (!match.captured(1).isEmpty())
            value = !value;
        result = joiner.isEmpty() ? value : joiner == QLatin1String("&&") ? result && value : result || value;
        rest = rest.mid(match.capturedLength());
        if (rest.isEmpty())
            return result;
        joiner = rest.left(2);
        if (joiner != QLatin1String("&&") && joiner != QLatin1String("||")) {
            report(Diagnostic::Severity::Warning, m_files.at(token.file), token,
                   QStringLiteral("cannot evaluate '#if %1'; taken as false").arg(expression));
            return false;
        }
        rest = rest.mid(2);
    }
}

void IdlPreprocessor::include(const QString &argument, const IdlToken &token, int depth)
{
    const QString fileName = m_files.at(token.file);
    const bool quoted = argument.startsWith(QLatin1Char('"')) && argument.indexOf(QLatin1Char('"'), 1) > 0;
    const bool angled = argument.startsWith(QLatin1Char('<')) && argument.indexOf(QLatin1Char('>')) > 0;
    if (!quoted && !angled) {
        report(Diagnostic::Severity::Error, fileName, token,
               QStringLiteral("#include expects \"file\" or <file>"));
        return;
    }
    const QString name = quoted ? argument.mid(1, argument.indexOf(QLatin1Char('"'), 1) - 1)
                                : argument.mid(1, argument.indexOf(QLatin1Char('>')) - 1);
    if (depth >= MaxIncludeDepth) {
        report(Diagnostic::Severity::Error, fileName, token,
               QStringLiteral("includes nested too deeply at '%1'").arg(name));
        return;
    }
    const QString path = findInclude(name, quoted, fileName);
    if (path.isEmpty()) {
        report(Diagnostic::Severity::Error, fileName, token,
               QStringLiteral("cannot find include file '%1'").arg(name));
        return;
    }
    processFileAt(path, &token, depth + 1);
}

QString IdlPreprocessor::findInclude(const QString &name, bool quoted, const QString &fileName) const
{
    if (QFileInfo(name).isAbsolute())
        return QFileInfo::exists(name) ? name : QString();
    // "x" looks beside the including file first; <x> looks there last, because OpenRTP users write
    // both forms for the same project files.
    const QString own = QFileInfo(fileName).absolutePath();
    QStringList directories = m_searchDirectories;
    if (quoted)
        directories.prepend(own);
    else
        directories.append(own);
    for (const QString &directory : directories) {
        const QString candidate = QDir(directory).filePath(name);
        if (QFileInfo(candidate).isFile())
            return candidate;
    }
    return {};
}

void IdlPreprocessor::report(Diagnostic::Severity severity, const QString &fileName, const IdlToken &token,
                             const QString &message)
{
    if (!m_diagnostics)
        return;
    m_diagnostics->append(severity == Diagnostic::Severity::Error
                              ? Diagnostic::error(fileName, token.line, token.column, message)
                              : Diagnostic::warning(fileName, token.line, token.column, message));
}

} // namespace Codegen
