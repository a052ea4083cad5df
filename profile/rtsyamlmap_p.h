// SPDX-License-Identifier: MIT
#pragma once
// Internal to the rtprofile library (uses yaml-cpp, which is linked privately): included only by
// the RTS YAML reader and writer sources, never by a public header.

#include "diagnostic.h"
#include "rtscommon.h"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

namespace Profile::RtsYaml {

QString fromStd(const std::string &text);
std::string toStd(const QString &text);
/// `rtsExt::key`, the dialect's spelling of extension keys.
QString ext(const char *key);

/// Shared state of one read: where to report, and the file name for the reports.
class Context
{
public:
    Context(const QString &fileName, Diagnostics *diagnostics);

    void report(Diagnostic::Severity severity, const YAML::Mark &mark,
                const QString &message) const;
    void error(const YAML::Mark &mark, const QString &message) const;
    void warn(const YAML::Mark &mark, const QString &message) const;

private:
    QString m_fileName;
    Diagnostics *m_diagnostics;
};

/// The 1-based position of a node (invalid for nodes without a mark).
SourceLocation locationOf(const YAML::Node &node);

/// True when valid UTF-8; otherwise reports the first bad line and column.
bool checkUtf8(const QByteArray &data, const Context &context);

/**
 * The YAML counterpart of NodeReader: takes values of one mapping by key, checks their kind and
 * remembers what was taken so that the rest becomes RtsYamlExtras.
 */
class Map
{
public:
    Map(const YAML::Node &node, const Context &context);

    const YAML::Node &node() const { return m_node; }
    SourceLocation location() const { return locationOf(m_node); }

    /// A scalar value; nothing when absent or null (an error when it is not a scalar).
    std::optional<QString> scalar(const QString &key);
    std::optional<QString> scalar(const char *key) { return scalar(QLatin1String(key)); }
    /// A scalar that must be there; an error at the mapping and an empty string when absent.
    QString required(const char *key);

    /// The value of any kind; nothing when absent.
    std::optional<YAML::Node> value(const QString &key);

    /// The value if it is a sequence (an error when it is something else); null = absent.
    std::optional<YAML::Node> sequence(const QString &key) { return typed(key, true); }
    /// The value if it is a mapping (an error when it is something else); null = absent.
    std::optional<YAML::Node> map(const QString &key) { return typed(key, false); }
    std::optional<YAML::Node> map(const char *key) { return typed(QLatin1String(key), false); }

    /// Appends the keys not taken, values as YAML text, with `prefix` put before each key.
    void addExtrasTo(RtsYamlExtras &extras, const QString &prefix = QString()) const;
    RtsYamlExtras extras() const;

private:
    struct Entry
    {
        QString key;
        YAML::Node value;
        bool used = false;
    };

    void addEntry(const YAML::Node &key, const YAML::Node &value);
    bool has(const QString &key) const;
    const YAML::Node *take(const QString &key);
    std::optional<YAML::Node> typed(const QString &key, bool wantSequence);

    YAML::Node m_node;
    const Context &m_context;
    std::vector<Entry> m_entries;
};

} // namespace Profile::RtsYaml
