// SPDX-License-Identifier: MIT
// Writes rtsprofile's YAML dialect. Values keep the model's text; the scalar style is chosen so
// that YAML tools see text as text (a version "0.2" stays a string) and numbers as numbers.
#include "rtsfields_p.h"
#include "rtsyaml.h"
#include "rtsyamlmap_p.h"

#include <QRegularExpression>

#include <algorithm>

namespace Profile {

namespace {

using namespace RtsYaml;

/// YAML 1.1 (PyYAML, used by rtsprofile) would resolve this plain scalar to a number.
bool looksNumeric(const QString &text)
{
    static const QRegularExpression number(QStringLiteral(
        R"(^[-+]?(\d[\d_]*(\.[\d_]*)?|\.\d+)([eE][-+]?\d+)?$|^0x[0-9a-fA-F_]+$|^[-+]?\.(inf|Inf|INF)$)"
        R"(|^\.(nan|NaN|NAN)$|^[-+]?[1-9][\d_]*(:[0-5]?\d)+(\.[\d_]*)?$)"));
    return number.match(text).hasMatch();
}

/// This text would not come back as the same text from a plain scalar: a number, a YAML 1.1
/// boolean or null, or nothing at all.
bool needsQuotes(const QString &text)
{
    static const QRegularExpression special(QStringLiteral(
        R"(^(y|Y|yes|Yes|YES|n|N|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF|null|Null|NULL|~)$)"));
    return text.isEmpty() || looksNumeric(text) || special.match(text).hasMatch();
}

class RtsYamlWriter
{
public:
    explicit RtsYamlWriter(YAML::Emitter &out)
        : m_out(out)
    { }

    void writeProfile(const RtsProfile &p)
    {
        m_out << YAML::BeginMap << YAML::Key << "rtsProfile" << YAML::Value;
        writeElement(p);
        m_out << YAML::EndMap;
    }

private:
    void key(const QString &name)
    {
        m_out << YAML::Key;
        // YAML allows 1024 characters in a plain `key:`; longer ones (once escaped) need `? key`.
        if (name.size() > 128)
            m_out << YAML::LongKey;
        // The dialect quotes its namespaced keys.
        if (name.contains(QLatin1String("::")))
            m_out << YAML::DoubleQuoted;
        m_out << toStd(name) << YAML::Value;
    }
    void key(const char *name) { key(QString::fromLatin1(name)); }

    void scalar(const QString &name, Fields::Style style, const QString &value)
    {
        switch (style) {
        case Fields::Style::Text:
            text(name, value);
            break;
        case Fields::Style::Number:
            number(name, value);
            break;
        case Fields::Style::Boolean:
            boolean(name, value);
            break;
        case Fields::Style::Date:
            date(name, value);
            break;
        }
    }

    /// Text that must stay text for YAML readers.
    void text(const QString &name, const QString &value)
    {
        key(name);
        if (needsQuotes(value))
            m_out << YAML::SingleQuoted;
        m_out << toStd(value);
    }

    /// A number written plain; text that is no number is written as text so that it survives.
    void number(const QString &name, const QString &value)
    {
        key(name);
        if (!looksNumeric(value))
            m_out << YAML::SingleQuoted;
        m_out << toStd(value);
    }

    /// rtsprofile writes its booleans as the strings 'true'/'false' (and compares them so).
    void boolean(const QString &name, const QString &value)
    {
        key(name);
        m_out << YAML::SingleQuoted << toStd(value);
    }

    void date(const QString &name, const QString &value)
    {
        static const QRegularExpression pattern(QStringLiteral(
            R"(^(\d{4})-(\d{2})-(\d{2})T(\d{2}):(\d{2}):(\d{2})(?:\.(\d+))?(Z|[+-]\d{2}:\d{2})?$)"));
        const QRegularExpressionMatch match = pattern.match(value);
        if (!match.hasMatch()) {
            text(name, value); // not rtsprofile's form, but nothing is lost
            return;
        }
        key(name);
        m_out << YAML::BeginMap;
        static const char *const parts[] = {"year", "month", "day", "hour", "minute", "second"};
        for (int i = 0; i < 6; ++i)
            m_out << YAML::Key << parts[i] << YAML::Value << match.captured(i + 1).toInt();
        // Quoted: "+10:00" would be a base-60 number to YAML 1.1, "500" a number.
        if (match.hasCaptured(7))
            m_out << YAML::Key << "fraction" << YAML::Value << YAML::SingleQuoted
                  << toStd(match.captured(7));
        if (match.hasCaptured(8))
            m_out << YAML::Key << "timeZone" << YAML::Value << YAML::SingleQuoted
                  << toStd(match.captured(8));
        m_out << YAML::EndMap;
    }

    void writeStrings(const QString &name, const QStringList &values)
    {
        if (values.isEmpty())
            return;
        key(name);
        m_out << YAML::BeginSeq;
        for (const QString &value : values) {
            if (needsQuotes(value))
                m_out << YAML::SingleQuoted;
            m_out << toStd(value);
        }
        m_out << YAML::EndSeq;
    }

    /// Unknown keys as read: those under `prefix` (a YamlGroup's), or with no prefix those not
    /// under any of `groupPrefixes`. An entry whose text no longer parses is dropped rather than
    /// breaking the file (it was produced by yaml-cpp, so this does not happen in practice).
    void extras(const RtsYamlExtras &extras, const QString &prefix,
                const QStringList &groupPrefixes = {})
    {
        for (const RtsYamlExtras::Entry &e : extras.entries) {
            const auto under = [&](const QString &p) { return e.key.startsWith(p); };
            if (prefix.isEmpty() ? std::any_of(groupPrefixes.begin(), groupPrefixes.end(), under)
                                 : !under(prefix))
                continue;
            try {
                const YAML::Node value = YAML::Load(toStd(e.yaml));
                key(e.key.mid(prefix.size()));
                m_out << value;
                // After a `? key` (asked for, or yaml-cpp's own choice for a key over 1,024
                // characters) yaml-cpp writes every later key so, flow mappings' too, where no
                // reader takes it: back to plain keys.
                m_out.SetMapFormat(YAML::Auto);
            } catch (const YAML::Exception &) {
                continue;
            }
        }
    }

    /// Keys in table order, then the unknown keys as read.
    template<typename T> void writeElement(const T &item)
    {
        m_out << YAML::BeginMap;
        QStringList groupPrefixes;
        Fields::forEachRow(Fields::RtsElement<T>::fields, [&](const auto &row) {
            writeRow(item, row);
            addGroupPrefix(groupPrefixes, row);
        });
        extras(item.yamlExtras, QString(), groupPrefixes);
        m_out << YAML::EndMap;
    }

    template<typename Row> static void addGroupPrefix(QStringList &, const Row &) { }
    template<typename... Rows>
    static void addGroupPrefix(QStringList &prefixes, const Fields::YamlGroup<Rows...> &group)
    {
        prefixes.append(groupPrefix(group));
    }
    template<typename... Rows> static QString groupPrefix(const Fields::YamlGroup<Rows...> &group)
    {
        return QLatin1String(group.yamlKey) + QLatin1Char('/');
    }

    template<typename T, typename Owner, typename Value>
    void writeRow(const T &item, const Fields::Scalar<Owner, Value> &row)
    {
        const QString name = QLatin1String(row.yamlKey);
        const Value &value = item.*row.member;
        if constexpr (Fields::Scalar<Owner, Value>::required)
            scalar(name, row.style, value);
        else if (value)
            scalar(name, row.style, *value);
    }

    template<typename T, typename Owner, typename Item>
    void writeRow(const T &item, const Fields::Child<Owner, QList<Item>> &row)
    {
        const QList<Item> &items = item.*row.member;
        if (items.isEmpty())
            return;
        key(row.yamlKey);
        m_out << YAML::BeginSeq;
        for (const Item &child : items)
            writeElement(child);
        m_out << YAML::EndSeq;
    }

    template<typename T, typename Owner, typename Item>
    void writeRow(const T &item, const Fields::Child<Owner, std::optional<Item>> &row)
    {
        if (const std::optional<Item> &child = item.*row.member) {
            key(row.yamlKey);
            writeElement(*child);
        }
    }

    template<typename T, typename Owner, typename Item>
    void writeRow(const T &item, const Fields::Child<Owner, Item> &row)
    {
        key(row.yamlKey);
        writeElement(item.*row.member);
    }

    template<typename T, typename Owner>
    void writeRow(const T &item, const Fields::TextList<Owner> &row)
    {
        writeStrings(QLatin1String(row.yamlKey), item.*row.member);
    }

    template<typename T, typename... Rows>
    void writeRow(const T &item, const Fields::YamlGroup<Rows...> &group)
    {
        key(group.yamlKey);
        m_out << YAML::BeginMap;
        Fields::forEachRow(group.rows, [&](const auto &row) { writeRow(item, row); });
        extras(item.yamlExtras, groupPrefix(group));
        m_out << YAML::EndMap;
    }

    YAML::Emitter &m_out;
};

} // namespace

QByteArray writeRtsYaml(const RtsProfile &profile)
{
    YAML::Emitter out;
    out.SetIndent(4);
    RtsYamlWriter(out).writeProfile(profile);
    QByteArray result(out.c_str(), qsizetype(out.size()));
    result.append('\n');
    return result;
}

} // namespace Profile
