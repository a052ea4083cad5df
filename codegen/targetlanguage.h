// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QString>

#include <optional>

namespace Codegen {

/// A language the generator writes a component project in.
enum class TargetLanguage { Cpp, Python, Java };

/// All target languages in a fixed order (C++, Python, Java).
const QList<TargetLanguage> &allTargetLanguages();
/// The folder name of the language's templates and its command-line spelling: cpp, python, java.
QString targetLanguageKey(TargetLanguage language);
/// The RTC Profile's `rtc:Language @kind` spelling: C++, Python, Java.
QString targetLanguageProfileName(TargetLanguage language);
/// Reads `cpp`, `c++`, `cxx`, `python`, `py`, `java` (any case); nothing for anything else.
std::optional<TargetLanguage> targetLanguageFromString(const QString &text);

/**
 * True when `name` can be used as an identifier (class, variable, function name) in generated
 * code of `language`: ASCII letters, digits and `_`, not starting with a digit, and not one of
 * the language's reserved words.
 */
bool isValidIdentifier(TargetLanguage language, const QString &name);
/// True when `name` is made of ASCII letters, digits and `_` only (possibly starting with a
/// digit): usable after a prefix such as `m_` or `self._`, in every language.
bool isIdentifierText(const QString &name);
/// An IDL identifier as omniidl / idlj spell it in `language`: keywords of the language get
/// `_cxx_` (C++) or `_` (Python, Java) in front.
QString mappedIdlName(TargetLanguage language, const QString &name);
/// True when `name` is a reserved word of `language`.
bool isReservedWord(TargetLanguage language, const QString &name);

} // namespace Codegen
