// SPDX-License-Identifier: MIT
#include "fieldrules.h"

#include <QCoreApplication>

namespace Studio::FieldRules {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Studio::FieldRules", text);
}

bool isNameCharacter(QChar c)
{
    return (c >= QLatin1Char('0') && c <= QLatin1Char('9'))
        || (c >= QLatin1Char('A') && c <= QLatin1Char('Z'))
        || (c >= QLatin1Char('a') && c <= QLatin1Char('z')) || c == QLatin1Char('_')
        || c == QLatin1Char('-') || c == QLatin1Char(':');
}

/// The distinct offending characters, quoted, in order of appearance ("' ', 'é'").
QString listOf(const QString &characters)
{
    QStringList quoted;
    for (QChar c : characters)
        quoted << QStringLiteral("'%1'").arg(c);
    return quoted.join(QStringLiteral(", "));
}

} // namespace

QString componentNameProblem(const QString &text)
{
    if (text.isEmpty())
        return tr("A name is required.");
    QString bad;
    for (QChar c : text) {
        if (!isNameCharacter(c) && !bad.contains(c))
            bad += c;
    }
    if (bad.isEmpty())
        return {};
    return tr("Only letters A-Z a-z, digits, '_', '-' and ':' are allowed (found %1).")
        .arg(listOf(bad));
}

QString requiredProblem(const QString &text)
{
    return text.trimmed().isEmpty() ? tr("This field is required.") : QString();
}

QString systemIdPartProblem(const QString &text)
{
    if (text.trimmed().isEmpty())
        return tr("This field is required (it is part of the system id).");
    if (text.contains(QLatin1Char(':')))
        return tr("':' separates the parts of the system id and cannot be used here.");
    return {};
}

QString nonNegativeIntegerProblem(const QString &text)
{
    if (text.isEmpty())
        return {};
    bool ok = false;
    const qlonglong value = text.trimmed().toLongLong(&ok);
    if (!ok || value < 0)
        return tr("Enter a whole number of 0 or more (0 = unlimited).");
    return {};
}

QString nonNegativeNumberProblem(const QString &text)
{
    if (text.isEmpty())
        return {};
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || value < 0 || qIsNaN(value) || qIsInf(value))
        return tr("Enter a number of 0 or more.");
    return {};
}

QString enumerationProblem(const QString &text, const QStringList &allowed)
{
    if (allowed.contains(text))
        return {};
    return tr("\"%1\" is not one of %2.").arg(text, allowed.join(QStringLiteral(", ")));
}

} // namespace Studio::FieldRules
