// SPDX-License-Identifier: MIT
#include "targetlanguage.h"

#include <QSet>

namespace Codegen {

namespace {

// Keywords (and a few predefined names that cannot be redefined) of each language. Generated
// code uses names from the profile verbatim, so one of these would not compile or would shadow
// something the generated code relies on.
const QSet<QString> &cppReserved()
{
    static const QSet<QString> words = {
        "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break",
        "case", "catch", "char", "char16_t", "char32_t", "class", "compl", "const", "constexpr",
        "const_cast", "continue", "decltype", "default", "delete", "do", "double", "dynamic_cast",
        "else", "enum", "explicit", "export", "extern", "false", "float", "for", "friend", "goto",
        "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
        "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register",
        "reinterpret_cast", "return", "short", "signed", "sizeof", "static", "static_assert",
        "static_cast", "struct", "switch", "template", "this", "thread_local", "throw", "true",
        "try", "typedef", "typeid", "typename", "union", "unsigned", "using", "virtual", "void",
        "volatile", "wchar_t", "while", "xor", "xor_eq", "RTC", "CORBA", "PortableServer"};
    return words;
}

const QSet<QString> &pythonKeywords()
{
    static const QSet<QString> words = {
        "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class",
        "continue", "def", "del", "elif", "else", "except", "finally", "for", "from", "global",
        "if", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return",
        "try", "while", "with", "yield", "print", "exec"};
    return words;
}

const QSet<QString> &pythonReserved()
{
    static const QSet<QString> words = {
        "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class",
        "continue", "def", "del", "elif", "else", "except", "finally", "for", "from", "global",
        "if", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return",
        "try", "while", "with", "yield", "RTC", "OpenRTM_aist", "CORBA", "sys", "time"};
    return words;
}

const QSet<QString> &javaReserved()
{
    static const QSet<QString> words = {
        "abstract", "assert", "boolean", "break", "byte", "case", "catch", "char", "class",
        "const", "continue", "default", "do", "double", "else", "enum", "extends", "final",
        "finally", "float", "for", "goto", "if", "implements", "import", "instanceof", "int",
        "interface", "long", "native", "new", "package", "private", "protected", "public",
        "return", "short", "static", "strictfp", "super", "switch", "synchronized", "this",
        "throw", "throws", "transient", "try", "void", "volatile", "while", "true", "false",
        "null", "var", "RTC", "String", "Object"};
    return words;
}

bool isAsciiIdentifier(const QString &name)
{
    return !name.isEmpty() && !name.front().isDigit() && isIdentifierText(name);
}

} // namespace

bool isIdentifierText(const QString &name)
{
    if (name.isEmpty())
        return false;
    for (const QChar c : name) {
        const bool ok = (c >= QLatin1Char('a') && c <= QLatin1Char('z'))
            || (c >= QLatin1Char('A') && c <= QLatin1Char('Z'))
            || (c >= QLatin1Char('0') && c <= QLatin1Char('9')) || c == QLatin1Char('_');
        if (!ok)
            return false;
    }
    return true;
}

const QList<TargetLanguage> &allTargetLanguages()
{
    static const QList<TargetLanguage> languages = {TargetLanguage::Cpp, TargetLanguage::Python,
                                                    TargetLanguage::Java};
    return languages;
}

QString targetLanguageKey(TargetLanguage language)
{
    switch (language) {
    case TargetLanguage::Cpp:
        return QStringLiteral("cpp");
    case TargetLanguage::Python:
        return QStringLiteral("python");
    case TargetLanguage::Java:
        return QStringLiteral("java");
    }
    return {};
}

QString targetLanguageProfileName(TargetLanguage language)
{
    switch (language) {
    case TargetLanguage::Cpp:
        return QStringLiteral("C++");
    case TargetLanguage::Python:
        return QStringLiteral("Python");
    case TargetLanguage::Java:
        return QStringLiteral("Java");
    }
    return {};
}

std::optional<TargetLanguage> targetLanguageFromString(const QString &text)
{
    const QString key = text.trimmed().toLower();
    if (key == QLatin1String("cpp") || key == QLatin1String("c++") || key == QLatin1String("cxx"))
        return TargetLanguage::Cpp;
    if (key == QLatin1String("python") || key == QLatin1String("py"))
        return TargetLanguage::Python;
    if (key == QLatin1String("java"))
        return TargetLanguage::Java;
    return std::nullopt;
}

QString mappedIdlName(TargetLanguage language, const QString &name)
{
    switch (language) {
    case TargetLanguage::Cpp:
        return cppReserved().contains(name) && name.front().isLower()
            ? QStringLiteral("_cxx_") + name
            : name;
    case TargetLanguage::Python:
        return pythonKeywords().contains(name) ? QLatin1Char('_') + name : name;
    case TargetLanguage::Java:
        return javaReserved().contains(name) && name.front().isLower() ? QLatin1Char('_') + name
                                                                        : name;
    }
    return name;
}

bool isReservedWord(TargetLanguage language, const QString &name)
{
    switch (language) {
    case TargetLanguage::Cpp:
        return cppReserved().contains(name);
    case TargetLanguage::Python:
        return pythonReserved().contains(name);
    case TargetLanguage::Java:
        return javaReserved().contains(name);
    }
    return false;
}

bool isValidIdentifier(TargetLanguage language, const QString &name)
{
    // A leading double underscore is reserved to the implementation in C++ and name-mangled in
    // Python classes; refuse it everywhere so that one profile generates the same names.
    return isAsciiIdentifier(name) && !name.startsWith(QLatin1String("__"))
        && !isReservedWord(language, name);
}

} // namespace Codegen
