// SPDX-License-Identifier: MIT
#include "builderfieldrules.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace Builder::FieldRules {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Builder::FieldRules)
};

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
        return Text::tr("A name is required.");
    QString bad;
    for (QChar c : text) {
        if (!isNameCharacter(c) && !bad.contains(c))
            bad += c;
    }
    if (bad.isEmpty())
        return {};
    return Text::tr("Only letters A-Z a-z, digits, '_', '-' and ':' are allowed (found %1).")
        .arg(listOf(bad));
}

QString requiredProblem(const QString &text)
{
    return text.trimmed().isEmpty() ? Text::tr("This field is required.") : QString();
}

QString nonNegativeIntegerProblem(const QString &text)
{
    if (text.isEmpty())
        return {};
    bool ok = false;
    const qlonglong value = text.trimmed().toLongLong(&ok);
    if (!ok || value < 0)
        return Text::tr("Enter a whole number of 0 or more (0 = unlimited).");
    return {};
}

QString nonNegativeNumberProblem(const QString &text)
{
    if (text.isEmpty())
        return {};
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || value < 0 || qIsNaN(value) || qIsInf(value))
        return Text::tr("Enter a number of 0 or more.");
    return {};
}

QString enumerationProblem(const QString &text, const QStringList &allowed)
{
    if (allowed.contains(text))
        return {};
    return Text::tr("\"%1\" is not one of %2.").arg(text, allowed.join(QStringLiteral(", ")));
}

QString identifierProblem(const QString &text)
{
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*$"));
    if (text.isEmpty() || identifier.match(text).hasMatch())
        return {};
    return Text::tr("A variable name is a letter or '_' followed by letters, digits or '_'.");
}

} // namespace Builder::FieldRules
