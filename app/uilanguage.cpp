// SPDX-License-Identifier: MIT
#include "uilanguage.h"

#include <QCoreApplication>
#include <QFile>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace Studio::UiLanguage {

namespace {

const QString LanguageKey = QStringLiteral("ui/language");

} // namespace

QStringList translatedLanguages()
{
    return {QStringLiteral("ja")};
}

QString chosen()
{
    const QString value = QSettings().value(LanguageKey).toString();
    return value == QLatin1String("en") || translatedLanguages().contains(value) ? value : QString();
}

void choose(const QString &language)
{
    if (language.isEmpty())
        QSettings().remove(LanguageKey);
    else
        QSettings().setValue(LanguageKey, language);
}

QString resolve(const QString &choice, const QLocale &system)
{
    if (!choice.isEmpty())
        return choice;
    // The first of the user's preferred languages that we have wins; English otherwise.
    for (const QString &name : system.uiLanguages()) {
        const QString language = name.section(QLatin1Char('-'), 0, 0).toLower();
        if (language == QLatin1String("en"))
            return language;
        if (translatedLanguages().contains(language))
            return language;
    }
    return QStringLiteral("en");
}

QString catalogue(const QString &language)
{
    return QStringLiteral(":/i18n/rtstudio_%1.qm").arg(language);
}

bool install(QCoreApplication *app, const QString &language, QString *error)
{
    if (language == QLatin1String("en"))
        return true;
    auto *own = new QTranslator(app);
    if (!own->load(catalogue(language))) {
        delete own;
        if (error)
            *error = QStringLiteral("No translation of RT Studio into \"%1\" (%2).")
                         .arg(language, catalogue(language));
        return false;
    }
    QCoreApplication::installTranslator(own);
    // Qt's standard dialogs and buttons (Debian's qt6-translations-l10n); English when absent.
    auto *qt = new QTranslator(app);
    if (qt->load(QStringLiteral("qtbase_") + language,
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;
    return true;
}

} // namespace Studio::UiLanguage
