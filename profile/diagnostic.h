// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QString>

namespace Profile {

/// One finding about a profile file: a read error, or a validation result, with where it is.
struct Diagnostic
{
    enum class Severity { Error, Warning, Info };

    Severity severity = Severity::Error;
    QString file;     ///< file path as given by the user; may be empty for in-memory data
    int line = 0;     ///< 1-based; 0 when unknown
    int column = 0;   ///< 1-based; 0 when unknown
    QString message;
    QString object;   ///< what it is about, e.g. "component ConsoleIn0" or "port in"; optional

    /// `FILE:LINE:COL: error: message` (parts that are unknown are left out).
    QString toString() const;

    static Diagnostic error(const QString &file, int line, int column, const QString &message);
    static Diagnostic warning(const QString &file, int line, int column, const QString &message);

    bool operator==(const Diagnostic &other) const;
};

using Diagnostics = QList<Diagnostic>;

/// True when any diagnostic in the list is an error.
bool hasErrors(const Diagnostics &diagnostics);

QString severityName(Diagnostic::Severity severity);

} // namespace Profile
