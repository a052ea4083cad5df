// SPDX-License-Identifier: MIT
#include "kindchoices.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace Builder::KindChoices {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Builder::KindChoices)
};

const QString ComponentSuffix = QStringLiteral("Component");

} // namespace

const QStringList &componentKindParts()
{
    static const QStringList parts {QStringLiteral("DataFlow"),
                                    QStringLiteral("FiniteStateMachine"),
                                    QStringLiteral("MultiMode")};
    return parts;
}

bool hasComponentKind(const QString &kind, const QString &part)
{
    return kind.contains(part);
}

QString withComponentKind(const QString &kind, const QString &part, bool on)
{
    QString text;
    for (const QString &known : componentKindParts()) {
        if (known == part ? on : hasComponentKind(kind, known))
            text += known;
    }
    return text.isEmpty() ? QString() : text + ComponentSuffix;
}

QString componentKindProblem(const QString &kind)
{
    for (const QString &part : componentKindParts()) {
        if (hasComponentKind(kind, part))
            return {};
    }
    if (kind.trimmed().isEmpty())
        return Text::tr("Choose at least one component kind (DataFlow, FSM or MultiMode).");
    return Text::tr("\"%1\" names none of the kinds DataFlow, FiniteStateMachine or MultiMode.")
        .arg(kind);
}

const QStringList &languages()
{
    static const QStringList names {QStringLiteral("C++"), QStringLiteral("Python"),
                                    QStringLiteral("Java")};
    return names;
}

QStringList languageEntries(const QString &kind)
{
    static const QRegularExpression separators(QStringLiteral("[,;]"));
    QStringList entries;
    for (const QString &entry : kind.split(separators, Qt::SkipEmptyParts)) {
        if (!entry.trimmed().isEmpty())
            entries << entry.trimmed();
    }
    return entries;
}

bool hasLanguage(const QString &kind, const QString &language)
{
    return languageEntries(kind).contains(language, Qt::CaseInsensitive);
}

QString withLanguage(const QString &kind, const QString &language, bool on)
{
    QStringList entries = languageEntries(kind);
    entries.removeIf(
        [&](const QString &entry) { return entry.compare(language, Qt::CaseInsensitive) == 0; });
    if (on)
        entries << language;
    return entries.join(QStringLiteral(", "));
}

QString languageProblem(const QString &kind)
{
    const QStringList entries = languageEntries(kind);
    if (entries.isEmpty())
        return Text::tr("Choose at least one language.");
    QStringList unknown;
    for (const QString &entry : entries) {
        if (!languages().contains(entry, Qt::CaseInsensitive))
            unknown << entry;
    }
    if (unknown.isEmpty())
        return {};
    return Text::tr("No code can be generated for %1 (C++, Python or Java).")
        .arg(unknown.join(QStringLiteral(", ")));
}

} // namespace Builder::KindChoices
