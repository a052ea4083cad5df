// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <functional>

namespace Builder {

/**
 * One editable field of a list element, as a table column or a form row: how to read it from an
 * element, how to write it into a copy, and which choices to offer.
 */
struct ItemField
{
    using Getter = std::function<QString(const PartItem &)>;
    using Setter = std::function<void(PartItem &, const QString &)>;
    using Choices = std::function<QStringList()>;

    QString key; ///< the model field ("name", "type" …): problem key and merge key
    QString label; ///< user-visible, e.g. "Data type"
    Getter get;
    Setter set;
    Choices choices; ///< empty function: free text
    bool editableChoices = true; ///< choices are suggestions, any text may be typed
    /// Checks text that cannot be stored as typed (e.g. a constraint string with a syntax
    /// error): a non-empty result is shown and the edit is not applied.
    std::function<QString(const QString &)> check;
};

/// Shorthand for a field of element type T held in a std::optional<QString> member.
template<typename T>
ItemField optionalTextField(const QString &key, const QString &label,
                            std::optional<QString> T::*member)
{
    return {
        key,
        label,
        [member](const PartItem &item) { return (std::get<T>(item).*member).value_or(QString()); },
        [member](PartItem &item, const QString &text) {
            auto &value = std::get<T>(item).*member;
            // Clearing a field that was absent leaves it absent; one that existed stays empty.
            if (text.isEmpty() && !value)
                return;
            value = text;
        },
        {},
        true,
        {}};
}

/// Shorthand for a field of element type T held in a QString member.
template<typename T>
ItemField textField(const QString &key, const QString &label, QString T::*member)
{
    return {key,
            label,
            [member](const PartItem &item) { return std::get<T>(item).*member; },
            [member](PartItem &item, const QString &text) { std::get<T>(item).*member = text; },
            {},
            true,
            {}};
}

/// Shorthand for a text of an optional documentation struct D held in member `doc` of T; the
/// documentation is created when the first text is typed.
template<typename T, typename D>
ItemField docField(const QString &key, const QString &label, std::optional<D> T::*doc,
                   std::optional<QString> D::*member)
{
    return {key,
            label,
            [doc, member](const PartItem &item) {
                const auto &d = std::get<T>(item).*doc;
                return d ? ((*d).*member).value_or(QString()) : QString();
            },
            [doc, member](PartItem &item, const QString &text) {
                auto &d = std::get<T>(item).*doc;
                if (text.isEmpty() && (!d || !((*d).*member)))
                    return;
                if (!d)
                    d = D();
                (*d).*member = text;
            },
            {},
            true,
            {}};
}

} // namespace Builder
