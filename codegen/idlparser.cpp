// SPDX-License-Identifier: MIT
#include "idlparser.h"

#include "idlsyntax_p.h"

#include <algorithm>

namespace Codegen {

using Profile::Diagnostic;

namespace {

qsizetype errorCount(const Profile::Diagnostics &diagnostics)
{
    return std::count_if(diagnostics.cbegin(), diagnostics.cend(), [](const Diagnostic &diagnostic) {
        return diagnostic.severity == Diagnostic::Severity::Error;
    });
}

} // namespace

IdlParser::IdlParser()
    : m_preprocessor(&m_diagnostics)
{
}

void IdlParser::addSearchDirectory(const QString &directory)
{
    if (!m_searchDirectories.contains(directory))
        m_searchDirectories.append(directory);
    m_preprocessor.setSearchDirectories(m_searchDirectories);
}

void IdlParser::setSearchDirectories(const QStringList &directories)
{
    m_searchDirectories = directories;
    m_preprocessor.setSearchDirectories(m_searchDirectories);
}

void IdlParser::define(const QString &macro)
{
    m_preprocessor.define(macro);
}

bool IdlParser::parseFile(const QString &path)
{
    const qsizetype errorsBefore = errorCount(m_diagnostics);
    m_preprocessor.processFile(path);
    return parseTokens(errorsBefore);
}

bool IdlParser::parseFiles(const QStringList &paths)
{
    bool ok = true;
    for (const QString &path : paths)
        ok = parseFile(path) && ok;
    return ok;
}

bool IdlParser::parseText(const QString &text, const QString &fileName)
{
    const qsizetype errorsBefore = errorCount(m_diagnostics);
    m_preprocessor.processText(text, fileName);
    return parseTokens(errorsBefore);
}

bool IdlParser::parseTokens(qsizetype errorsBefore)
{
    IdlSyntax syntax(m_preprocessor.takeTokens(), m_preprocessor.files(), &m_model, &m_diagnostics);
    syntax.parse();
    m_model.files = m_preprocessor.files();
    m_model.prefixes = m_preprocessor.prefixes();
    return errorCount(m_diagnostics) == errorsBefore;
}

} // namespace Codegen
