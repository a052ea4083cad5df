// SPDX-License-Identifier: MIT
#include "diagnostic.h"
#include "namespaces.h"

#include <algorithm>

namespace Profile {

QString Ns::preferredPrefix(const QString &uri)
{
    if (uri == Rtc)
        return QStringLiteral("rtc");
    if (uri == RtcDoc)
        return QStringLiteral("rtcDoc");
    if (uri == RtcExt)
        return QStringLiteral("rtcExt");
    if (uri == Rts)
        return QStringLiteral("rts");
    if (uri == RtsExt)
        return QStringLiteral("rtsExt");
    if (uri == Xsi)
        return QStringLiteral("xsi");
    return {};
}

QString severityName(Diagnostic::Severity severity)
{
    switch (severity) {
    case Diagnostic::Severity::Error:
        return QStringLiteral("error");
    case Diagnostic::Severity::Warning:
        return QStringLiteral("warning");
    case Diagnostic::Severity::Info:
        return QStringLiteral("note");
    }
    return {};
}

QString Diagnostic::toString() const
{
    QString where = file;
    if (line > 0) {
        where += QLatin1Char(':') + QString::number(line);
        if (column > 0)
            where += QLatin1Char(':') + QString::number(column);
    }
    QString text;
    if (!where.isEmpty())
        text = where + QStringLiteral(": ");
    text += severityName(severity) + QStringLiteral(": ");
    if (!object.isEmpty())
        text += object + QStringLiteral(": ");
    return text + message;
}

Diagnostic Diagnostic::error(const QString &file, int line, int column, const QString &message)
{
    return Diagnostic{Severity::Error, file, line, column, message, {}};
}

Diagnostic Diagnostic::warning(const QString &file, int line, int column, const QString &message)
{
    return Diagnostic{Severity::Warning, file, line, column, message, {}};
}

bool Diagnostic::operator==(const Diagnostic &other) const
{
    return severity == other.severity && file == other.file && line == other.line
        && column == other.column && message == other.message && object == other.object;
}

bool hasErrors(const Diagnostics &diagnostics)
{
    return std::any_of(diagnostics.cbegin(), diagnostics.cend(), [](const Diagnostic &d) {
        return d.severity == Diagnostic::Severity::Error;
    });
}

} // namespace Profile
