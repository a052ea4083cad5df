// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "idlmodel.h"
#include "idlpreprocessor.h"

#include <QString>
#include <QStringList>

namespace Codegen {

/// Parses IDL files (with their includes) into one IdlModel. Each file is read once per parser, however
/// often it is named or included. Problems become diagnostics `FILE:LINE:COL: error: message`; a syntax
/// error ends the parse of the file named in that call, what was read before it stays in the model.
///
/// \code
/// IdlParser parser;
/// parser.addSearchDirectory(openRtmIdlDir);
/// parser.parseFile(QStringLiteral("idl/MyService.idl"));
/// for (const IdlOperation &op : parser.model().allOperations(QStringLiteral("SimpleService::MyService")))
///     ...
/// \endcode
class IdlParser
{
public:
    IdlParser();
    IdlParser(const IdlParser &) = delete;
    IdlParser &operator=(const IdlParser &) = delete;

    /// Adds a folder where `#include` looks (after the including file's own folder for "x").
    void addSearchDirectory(const QString &directory);
    void setSearchDirectories(const QStringList &directories);
    QStringList searchDirectories() const { return m_searchDirectories; }
    /// Defines a macro for `#ifdef` (like omniidl's -D).
    void define(const QString &macro);

    /// Parses one file and what it includes. True when no error was reported by this call.
    bool parseFile(const QString &path);
    /// Parses several files in order. True when no error was reported by this call.
    bool parseFiles(const QStringList &paths);
    /// Parses in-memory IDL named `fileName` in diagnostics. True when no error was reported.
    bool parseText(const QString &text, const QString &fileName);

    const IdlModel &model() const { return m_model; }
    const Profile::Diagnostics &diagnostics() const { return m_diagnostics; }

private:
    bool parseTokens(qsizetype errorsBefore);

    QStringList m_searchDirectories;
    Profile::Diagnostics m_diagnostics;
    IdlPreprocessor m_preprocessor;
    IdlModel m_model;
};

} // namespace Codegen
