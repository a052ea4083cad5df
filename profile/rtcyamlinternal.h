// SPDX-License-Identifier: MIT
#pragma once
// Internal to the rtprofile library (uses yaml-cpp, which is linked privately): included only by
// the RTC YAML reader and writer sources, never by a public header.

#include "diagnostic.h"
#include "rtccommon.h"

#include <yaml-cpp/yaml.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace Profile::RtcYaml {

QString fromStd(const std::string &text);
std::string toStd(const QString &text);

/// Deepest nesting of unknown content or constraints the reader follows.
inline constexpr int MaxDepth = 256;

/// Where the reports of one read go; counts errors so that the reader can fail at the end.
class Context
{
public:
    Context(const QString &fileName, Diagnostics *diagnostics);

    void error(const YAML::Mark &mark, const QString &message);
    void warn(const YAML::Mark &mark, const QString &message);
    bool failed() const { return m_failed; }
    const QString &fileName() const { return m_fileName; }

private:
    QString m_fileName;
    Diagnostics *m_diagnostics;
    bool m_failed = false;
};

/// The 1-based position of a node (invalid for nodes without a mark).
SourceLocation locationOf(const YAML::Node &node);

/// The keys one value may be found under: the dialect's spelling first, then older ones.
class Keys
{
public:
    Keys(std::initializer_list<const char *> keys);
    /// `key`, then those of `legacy` that are not null.
    Keys(const char *key, const std::array<const char *, 2> &legacy);

    const char *const *begin() const { return m_keys.data(); }
    const char *const *end() const { return m_keys.data() + m_count; }

private:
    void append(const char *key);

    std::array<const char *, 4> m_keys {};
    std::size_t m_count = 0;
};

/**
 * The YAML counterpart of NodeReader: takes the values of one mapping by key (trying the
 * dialect's alternative spellings), checks their kind, and remembers what was taken so that the
 * rest can be kept as extras. A null value counts as absent.
 */
class MapReader
{
public:
    /// `node` must be a mapping or null (an error is reported otherwise).
    MapReader(const YAML::Node &node, Context &context);

    const YAML::Node &node() const { return m_node; }
    SourceLocation location() const { return locationOf(m_node); }
    Context &context() const { return m_context; }

    /// The value of the first present key among `keys` (consumed); nothing when none is there.
    std::optional<YAML::Node> take(const Keys &keys);
    /// A scalar; nothing when absent or null (an error when it is a mapping or a sequence).
    std::optional<QString> scalar(const Keys &keys);
    /// A required scalar; when absent a warning, the schema name (the first key without its
    /// `rtcExt::` prefix, or `schemaName`) recorded in `missing`, and "".
    QString required(const Keys &keys, RtcMissing &missing, const char *schemaName = nullptr);
    /// A mapping value; a null value counts as an empty mapping; nothing when absent (or, with
    /// an error, when it is not a mapping).
    std::optional<YAML::Node> map(const Keys &keys);
    /// The items of a sequence value; a single mapping counts as a one-item list.
    std::vector<YAML::Node> list(const Keys &keys);
    /// A sequence of scalars.
    QStringList scalarList(const Keys &keys);

    /// Keys not taken, as XmlExtras: scalars become attributes, mappings and sequences child
    /// elements placed after `schemaChildCount` children (where the XML writer puts them last).
    XmlExtras extras(int schemaChildCount) const;

private:
    struct Entry
    {
        QString key;
        YAML::Node value;
        bool used = false;
    };

    Entry *find(const Keys &keys);

    YAML::Node m_node;
    Context &m_context;
    std::vector<Entry> m_entries;
};

/// An xs:dateTime text from a YAML date: the text itself, or {year, month, day, hour, minute,
/// second, fractionalSecond?/millisecond?, timezone?} (an error when neither).
std::optional<QString> readDate(const YAML::Node &node, Context &context);

// ---- Writing

/**
 * A YAML value being written: a scalar (plain or quoted), a mapping with keys in the order
 * RTC Builder writes them (sorted by the key's local name), or a sequence.
 */
struct Value
{
    enum class Kind { Scalar, Map, Sequence };
    Kind kind = Kind::Map;
    QString text;
    bool quoted = false;
    std::vector<std::pair<QString, Value>> entries;
    std::vector<Value> items;

    static Value string(const QString &text); ///< quoted when it would read as non-string
    static Value plain(const QString &text); ///< numbers and booleans as they are
    static Value number(const QString &text); ///< plain when numeric, else quoted
    static Value boolean(const QString &text); ///< plain true/false when boolean, else quoted
    static Value sequence(std::vector<Value> items = {});
    static Value stringList(const QStringList &texts);

    bool isEmpty() const { return kind != Kind::Scalar && entries.empty() && items.empty(); }
    void set(const QString &key, Value value);
    void set(const QString &key, const std::optional<QString> &text);
    /// Writes a required string unless it is empty and the source lacked it.
    void setRequired(const QString &key, const QString &text, const RtcMissing &missing,
                     const QString &schemaName = {});
    /// Adds the XmlExtras the other way round (attributes as scalars, elements as values).
    void addExtras(const XmlExtras &extras);
};

/// A date written as a mapping when that reproduces the text exactly, else as a string.
Value dateValue(const QString &text);
/// The document `rtcProfile: …` as text.
QByteArray emitDocument(const Value &root);

} // namespace Profile::RtcYaml
