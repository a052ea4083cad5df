// SPDX-License-Identifier: MIT
#pragma once
// Internal to the rtprofile library: the kinds of rows a profile element's field table is made of.
// A table is a std::tuple of rows (see rtsfields_p.h and rtcfields_p.h); the XML and YAML readers
// and writers walk it, so a field is described once for all four. What a row means in detail
// (is a missing required field an error or a warning …) is each profile's walkers' business.

#include "xmlextras.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <array>
#include <optional>
#include <tuple>
#include <type_traits>

namespace Profile::Fields {

/// How a scalar looks in YAML; in XML every scalar is plain attribute text.
enum class Style {
    Text, ///< quoted when a YAML reader would take it for something else
    Number, ///< plain when it is a number, quoted otherwise so that the text survives
    Boolean, ///< xs:boolean, written as the dialect writes booleans
    Date, ///< xs:dateTime, which the YAML dialects spell as a {year, month, …} mapping
};

/// Other keys a YAML reader accepts for a row (old spellings); never written.
using YamlLegacyKeys = std::array<const char *, 2>;

/**
 * An attribute (XML) or scalar key (YAML). A `QString` member is required (readers report its
 * absence), a `std::optional<QString>` one optional.
 */
template<typename Owner, typename Value> struct Scalar
{
    static_assert(std::is_same_v<Value, QString> || std::is_same_v<Value, std::optional<QString>>);
    static constexpr bool required = std::is_same_v<Value, QString>;

    Value Owner::*member;
    const QString *xmlNamespace;
    const char *xmlName;
    const char *yamlKey;
    Style style = Style::Text;
    /// Another attribute name the XML reader accepts, never written.
    const char *xmlLegacyName = nullptr;
    /// A second namespace the XML reader tries the legacy name in, after the row's own.
    const QString *xmlLegacyNamespace = nullptr;
    YamlLegacyKeys yamlLegacyKeys {};
    /// The value a YAML reader takes for an absent required key instead of reporting it (EMF
    /// leaves out attributes at their default).
    const char *yamlDefault = nullptr;
    /// Applied to the text read (e.g. a boolean's `1` becomes `true`).
    QString (*normalize)(const QString &) = nullptr;

    constexpr Scalar withXmlLegacyName(const char *name) const
    {
        Scalar row = *this;
        row.xmlLegacyName = name;
        return row;
    }
    constexpr Scalar withXmlLegacyName(const char *name, const QString &alsoInNamespace) const
    {
        Scalar row = withXmlLegacyName(name);
        row.xmlLegacyNamespace = &alsoInNamespace;
        return row;
    }
    constexpr Scalar withYamlLegacyKeys(const char *key, const char *another = nullptr) const
    {
        Scalar row = *this;
        row.yamlLegacyKeys = {key, another};
        return row;
    }
    constexpr Scalar withYamlDefault(const char *value) const
    {
        Scalar row = *this;
        row.yamlDefault = value;
        return row;
    }
    constexpr Scalar normalizedBy(QString (*function)(const QString &)) const
    {
        Scalar row = *this;
        row.normalize = function;
        return row;
    }
};

/// Where a child element goes among its siblings in XML. YAML keys always follow the table.
enum class XmlPlace {
    InOrder, ///< at its row's position among the child rows
    First, ///< before the other child rows (the schema's order differs from the dialect's)
};

/// Child elements of a type with its own table: a list, one required or one optional element.
template<typename Owner, typename Member> struct Child
{
    Member Owner::*member;
    const QString *xmlNamespace;
    const char *xmlName;
    const char *yamlKey;
    /// The xsi:type the writer gives the child element (the namespace is null when none).
    const QString *xsiTypeNamespace = nullptr;
    const char *xsiTypeName = nullptr;
    /// For a required child: the RTS YAML reader's message when it is missing, `%1` being the
    /// key; marked with QT_TRANSLATE_NOOP in the reader's translation context.
    const char *yamlMissing = nullptr;
    XmlPlace xmlPlace = XmlPlace::InOrder;
    YamlLegacyKeys yamlLegacyKeys {};

    constexpr Child withXsiType(const QString &ns, const char *name) const
    {
        Child row = *this;
        row.xsiTypeNamespace = &ns;
        row.xsiTypeName = name;
        return row;
    }
    constexpr Child missingInYaml(const char *message) const
    {
        Child row = *this;
        row.yamlMissing = message;
        return row;
    }
    constexpr Child firstInXml() const
    {
        Child row = *this;
        row.xmlPlace = XmlPlace::First;
        return row;
    }
    constexpr Child withYamlLegacyKeys(const char *key, const char *another = nullptr) const
    {
        Child row = *this;
        row.yamlLegacyKeys = {key, another};
        return row;
    }
};

/// Repeated text elements (XML) or a list of text (YAML).
template<typename Owner> struct TextList
{
    QStringList Owner::*member;
    const QString *xmlNamespace;
    const char *xmlName;
    const char *yamlKey;
    /// Another element name the XML reader accepts, never written.
    const char *xmlLegacyName = nullptr;
    YamlLegacyKeys yamlLegacyKeys {};

    constexpr TextList withXmlLegacyName(const char *name) const
    {
        TextList row = *this;
        row.xmlLegacyName = name;
        return row;
    }
    constexpr TextList withYamlLegacyKeys(const char *key, const char *another = nullptr) const
    {
        TextList row = *this;
        row.yamlLegacyKeys = {key, another};
        return row;
    }
};

/**
 * Rows that YAML nests in a mapping of their own under `yamlKey` (always written, so that readers
 * that look the key up find it), while XML has them directly on the element. Unknown keys of the
 * nested mapping are kept in the element's YAML extras as `yamlKey/key`.
 */
template<typename... Rows> struct YamlGroup
{
    const char *yamlKey;
    std::tuple<Rows...> rows;
};

/**
 * A place in the table for an element part that does not fit the row kinds (the RTC Profile's
 * constraint trees, its configuration set wrapper …). Each walker handles `Special<Tag>` in a
 * function of its own, at the row's position.
 */
template<typename Tag> struct Special
{
};

// Row constructors, so that a table reads as a list of fields.

template<typename Owner, typename Value>
constexpr Scalar<Owner, Value> text(Value Owner::*member, const QString &ns, const char *xmlName,
                                    const char *yamlKey)
{
    return {member, &ns, xmlName, yamlKey, Style::Text};
}

template<typename Owner, typename Value>
constexpr Scalar<Owner, Value> number(Value Owner::*member, const QString &ns, const char *xmlName,
                                      const char *yamlKey)
{
    return {member, &ns, xmlName, yamlKey, Style::Number};
}

/// Booleans are read in the form the writers use (`1` → `true`); other text is kept for the
/// validator.
inline QString normalizedBoolean(const QString &text)
{
    const std::optional<bool> value = parseBoolean(text);
    return value ? booleanText(*value) : text;
}

template<typename Owner, typename Value>
constexpr Scalar<Owner, Value> boolean(Value Owner::*member, const QString &ns, const char *xmlName,
                                       const char *yamlKey)
{
    Scalar<Owner, Value> row {member, &ns, xmlName, yamlKey, Style::Boolean};
    row.normalize = &normalizedBoolean;
    return row;
}

template<typename Owner>
constexpr Scalar<Owner, QString> date(QString Owner::*member, const QString &ns,
                                      const char *xmlName, const char *yamlKey)
{
    return {member, &ns, xmlName, yamlKey, Style::Date};
}

template<typename Owner, typename Item>
constexpr Child<Owner, QList<Item>> list(QList<Item> Owner::*member, const QString &ns,
                                         const char *xmlName, const char *yamlKey)
{
    return {member, &ns, xmlName, yamlKey};
}

template<typename Owner, typename Item>
constexpr Child<Owner, Item> element(Item Owner::*member, const QString &ns, const char *xmlName,
                                     const char *yamlKey)
{
    return {member, &ns, xmlName, yamlKey};
}

template<typename Owner, typename Item>
constexpr Child<Owner, std::optional<Item>> optionalElement(std::optional<Item> Owner::*member,
                                                            const QString &ns, const char *xmlName,
                                                            const char *yamlKey)
{
    return {member, &ns, xmlName, yamlKey};
}

template<typename Owner>
constexpr TextList<Owner> textList(QStringList Owner::*member, const QString &ns,
                                   const char *xmlName, const char *yamlKey)
{
    return {member, &ns, xmlName, yamlKey};
}

template<typename Tag> constexpr Special<Tag> special()
{
    return {};
}

template<typename... Rows> constexpr YamlGroup<Rows...> yamlGroup(const char *yamlKey, Rows... rows)
{
    return {yamlKey, std::tuple<Rows...>(rows...)};
}

// Walking a table.

/// Calls `visit` on each row of a table, in order; a YamlGroup is one row.
template<typename Table, typename Visit> void forEachRow(const Table &table, Visit &&visit)
{
    std::apply([&](const auto &...row) { (visit(row), ...); }, table);
}

namespace Internal {
template<typename Row, typename Visit> void visitFlat(const Row &row, Visit &visit)
{
    visit(row);
}
template<typename... Rows, typename Visit>
void visitFlat(const YamlGroup<Rows...> &group, Visit &visit)
{
    std::apply([&](const auto &...row) { (visitFlat(row, visit), ...); }, group.rows);
}
} // namespace Internal

/// Like forEachRow(), but with the rows of YamlGroups in place of the groups: the XML view.
template<typename Table, typename Visit> void forEachXmlRow(const Table &table, Visit &&visit)
{
    std::apply([&](const auto &...row) { (Internal::visitFlat(row, visit), ...); }, table);
}

} // namespace Profile::Fields
