// SPDX-License-Identifier: MIT
#pragma once

#include <QLocale>
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace Studio::UiLanguage {

/// The languages the GUI is translated into, besides English (the language of the sources).
QStringList translatedLanguages();

/// The language chosen in the settings: "" follows the system's locale, otherwise "en" or "ja".
QString chosen();
void choose(const QString &language);

/// The language the GUI shows for a choice ("" = the system's) and a system locale: "en" or one of
/// translatedLanguages().
QString resolve(const QString &choice, const QLocale &system = QLocale::system());

/// Installs RT Studio's and Qt's own catalogues for @p language into @p app (nothing for "en").
/// Returns false, with the reason in @p error, when RT Studio's catalogue is missing.
bool install(QCoreApplication *app, const QString &language, QString *error = nullptr);

/// The resource path of RT Studio's catalogue for @p language.
QString catalogue(const QString &language);

} // namespace Studio::UiLanguage
