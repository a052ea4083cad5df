// SPDX-License-Identifier: MIT
// The YAML plumbing of the RTC Profile: mapping reader, unknown keys ↔ XmlExtras, dates, emitter.
#include "namespaces.h"
#include "rtcyamlinternal.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>

namespace Profile::RtcYaml {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcYaml", text);
}

const QString TextKey = QStringLiteral("#text");

/// `rtcExt::name` → (rtc_ext, name); `{uri}name` → (uri, name); a plain key is in rtc.
std::pair<QString, QString> nameOfKey(const QString &key)
{
    if (key.startsWith(QLatin1Char('{'))) {
        const qsizetype close = key.indexOf(QLatin1Char('}'));
        if (close > 0)
            return {key.mid(1, close - 1), key.mid(close + 1)};
    }
    const qsizetype sep = key.indexOf(QLatin1String("::"));
    if (sep > 0) {
        const QString prefix = key.left(sep);
        const QString local = key.mid(sep + 2);
        if (prefix == QLatin1String("rtcExt"))
            return {Ns::RtcExt, local};
        if (prefix == QLatin1String("rtcDoc"))
            return {Ns::RtcDoc, local};
        if (prefix == QLatin1String("rtc"))
            return {Ns::Rtc, local};
    }
    return {Ns::Rtc, key};
}

QString keyOfName(const QString &ns, const QString &name)
{
    if (ns == Ns::Rtc)
        return name;
    if (ns == Ns::RtcExt)
        return QLatin1String("rtcExt::") + name;
    if (ns == Ns::RtcDoc)
        return QLatin1String("rtcDoc::") + name;
    return QLatin1Char('{') + ns + QLatin1Char('}') + name;
}

XmlNode newElement(const QString &ns, const QString &name)
{
    XmlNode node(ns, name);
    node.prefix = Ns::preferredPrefix(ns);
    return node;
}

void appendElements(std::vector<XmlNode> &out, const QString &key, const YAML::Node &value,
                    int depth, Context &context);

XmlNode elementFrom(const QString &key, const YAML::Node &value, int depth, Context &context)
{
    const auto [ns, name] = nameOfKey(key);
    XmlNode node = newElement(ns, name);
    node.location = locationOf(value);
    if (depth > MaxDepth) {
        context.error(value.Mark(), tr("nested deeper than %1 levels").arg(MaxDepth));
        return node;
    }
    if (value.IsScalar()) {
        node.text = fromStd(value.Scalar());
    } else if (value.IsSequence()) {
        appendElements(node.children, key, value, depth + 1, context);
    } else if (value.IsMap()) {
        for (const auto &entry : value) {
            if (!entry.first.IsScalar()) {
                context.error(entry.first.Mark(), tr("a mapping key must be a plain value"));
                continue;
            }
            const QString childKey = fromStd(entry.first.Scalar());
            const YAML::Node &child = entry.second;
            if (childKey == TextKey && child.IsScalar()) {
                node.text = fromStd(child.Scalar());
            } else if (child.IsScalar() || child.IsNull()) {
                const auto [attrNs, attrName] = nameOfKey(childKey);
                node.setAttribute(attrNs, attrName,
                                  child.IsNull() ? QString() : fromStd(child.Scalar()));
            } else {
                appendElements(node.children, childKey, child, depth + 1, context);
            }
        }
    }
    return node;
}

void appendElements(std::vector<XmlNode> &out, const QString &key, const YAML::Node &value,
                    int depth, Context &context)
{
    if (!value.IsSequence()) {
        out.push_back(elementFrom(key, value, depth, context));
        return;
    }
    for (const YAML::Node &item : value)
        out.push_back(elementFrom(key, item, depth, context));
}

bool isTextOnly(const XmlNode &node)
{
    return node.attributes.isEmpty() && node.children.empty();
}

Value valueOfElements(const std::vector<const XmlNode *> &group);

Value valueOf(const XmlNode &node)
{
    if (isTextOnly(node) && !node.text.isEmpty())
        return Value::string(node.text);
    Value value;
    for (const XmlAttribute &a : node.attributes)
        value.set(keyOfName(a.namespaceUri, a.name), Value::string(a.value));
    if (!node.text.isEmpty())
        value.set(TextKey, Value::string(node.text));
    std::vector<std::pair<QString, std::vector<const XmlNode *>>> groups;
    for (const XmlNode &child : node.children) {
        const QString key = keyOfName(child.namespaceUri, child.name);
        auto it = std::find_if(groups.begin(), groups.end(),
                               [&key](const auto &g) { return g.first == key; });
        if (it == groups.end())
            groups.push_back({key, {&child}});
        else
            it->second.push_back(&child);
    }
    for (const auto &group : groups)
        value.set(group.first, valueOfElements(group.second));
    return value;
}

/// One element that is not just text becomes a mapping; anything else a list, so that reading
/// it back gives elements again (a scalar would come back as an attribute).
Value valueOfElements(const std::vector<const XmlNode *> &group)
{
    if (group.size() == 1 && !isTextOnly(*group.front()))
        return valueOf(*group.front());
    Value list = Value::sequence();
    for (const XmlNode *node : group)
        list.items.push_back(valueOf(*node));
    return list;
}

QString localKey(const QString &key)
{
    const qsizetype sep = key.indexOf(QLatin1String("::"));
    return sep < 0 ? key : key.mid(sep + 2);
}

bool looksTyped(const QString &text)
{
    static const QRegularExpression number(QStringLiteral(
        R"(^[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?$|^0x[0-9a-fA-F]+$|^[-+]?\.(inf|Inf|INF)$|^\.(nan|NaN|NAN)$)"));
    static const QRegularExpression date(QStringLiteral(R"(^[0-9]{4}-[0-9]{1,2}-[0-9]{1,2})"));
    static const QStringList words {QStringLiteral("true"), QStringLiteral("false"),
                                    QStringLiteral("yes"),  QStringLiteral("no"),
                                    QStringLiteral("on"),   QStringLiteral("off"),
                                    QStringLiteral("null"), QStringLiteral("~"),
                                    QStringLiteral("y"),    QStringLiteral("n")};
    return number.match(text).hasMatch() || date.match(text).hasMatch()
        || words.contains(text.toLower());
}

bool needsQuotes(const QString &text)
{
    if (text.isEmpty() || looksTyped(text) || text.trimmed() != text)
        return true;
    // RTC Builder quotes values with separators ("RTC::TimedLong", "Push,Pull").
    static const QRegularExpression special(QStringLiteral(R"([:,#\[\]{}&*!|>'"%@`\n\t\\])"));
    return special.match(text).hasMatch() || text.startsWith(QLatin1Char('-'))
        || text.startsWith(QLatin1Char('?'));
}

void emitValue(YAML::Emitter &out, const Value &value)
{
    switch (value.kind) {
    case Value::Kind::Scalar:
        if (value.quoted)
            out << YAML::DoubleQuoted;
        out << toStd(value.text);
        break;
    case Value::Kind::Map: {
        if (value.entries.empty()) {
            out << YAML::Flow << YAML::BeginMap << YAML::EndMap;
            break;
        }
        auto entries = value.entries;
        std::stable_sort(entries.begin(), entries.end(), [](const auto &a, const auto &b) {
            return localKey(a.first) < localKey(b.first);
        });
        out << YAML::BeginMap;
        for (const auto &entry : entries) {
            out << YAML::Key;
            // YAML allows 1024 characters in a plain `key:`; a longer one (once escaped) must be `? key`.
            if (entry.first.size() > 128)
                out << YAML::LongKey;
            if (needsQuotes(entry.first))
                out << YAML::DoubleQuoted;
            out << toStd(entry.first) << YAML::Value;
            emitValue(out, entry.second);
            // After a `? key` (asked for, or yaml-cpp's own choice for a key over 1,024
            // characters) yaml-cpp writes every later key so, flow mappings' too, where no reader
            // takes it: back to plain keys.
            out.SetMapFormat(YAML::Auto);
        }
        out << YAML::EndMap;
        break;
    }
    case Value::Kind::Sequence:
        if (value.items.empty()) {
            out << YAML::Flow << YAML::BeginSeq << YAML::EndSeq;
            break;
        }
        out << YAML::BeginSeq;
        for (const Value &item : value.items)
            emitValue(out, item);
        out << YAML::EndSeq;
        break;
    }
}

} // namespace

QString fromStd(const std::string &text)
{
    return QString::fromStdString(text);
}

std::string toStd(const QString &text)
{
    return text.toStdString();
}

Context::Context(const QString &fileName, Diagnostics *diagnostics)
    : m_fileName(fileName)
    , m_diagnostics(diagnostics)
{ }

void Context::error(const YAML::Mark &mark, const QString &message)
{
    m_failed = true;
    if (m_diagnostics) {
        m_diagnostics->append(Diagnostic::error(m_fileName, mark.is_null() ? 0 : mark.line + 1,
                                                mark.is_null() ? 0 : mark.column + 1, message));
    }
}

void Context::warn(const YAML::Mark &mark, const QString &message)
{
    if (m_diagnostics) {
        m_diagnostics->append(Diagnostic::warning(m_fileName, mark.is_null() ? 0 : mark.line + 1,
                                                  mark.is_null() ? 0 : mark.column + 1, message));
    }
}

SourceLocation locationOf(const YAML::Node &node)
{
    const YAML::Mark mark = node.Mark();
    if (mark.is_null())
        return {};
    return SourceLocation {mark.line + 1, mark.column + 1};
}

MapReader::MapReader(const YAML::Node &node, Context &context)
    : m_node(node)
    , m_context(context)
{
    if (node.IsNull())
        return;
    if (!node.IsMap()) {
        context.error(node.Mark(), tr("expected a mapping (key: value lines) here"));
        return;
    }
    for (const auto &entry : node) {
        if (!entry.first.IsScalar()) {
            context.error(entry.first.Mark(), tr("a mapping key must be a plain value"));
            continue;
        }
        const QString key = fromStd(entry.first.Scalar());
        // YAML wants each key once; the first one counts, as in the RTS Profile reader.
        const bool seen = std::any_of(m_entries.cbegin(), m_entries.cend(),
                                      [&key](const Entry &e) { return e.key == key; });
        if (seen) {
            context.warn(entry.first.Mark(), tr("duplicate key '%1' was ignored").arg(key));
            continue;
        }
        m_entries.push_back(Entry {key, entry.second, false});
    }
}

Keys::Keys(std::initializer_list<const char *> keys)
{
    for (const char *key : keys)
        append(key);
}

Keys::Keys(const char *key, const std::array<const char *, 2> &legacy)
{
    append(key);
    for (const char *other : legacy) {
        if (other)
            append(other);
    }
}

void Keys::append(const char *key)
{
    Q_ASSERT(m_count < m_keys.size());
    if (m_count < m_keys.size())
        m_keys[m_count++] = key;
}

MapReader::Entry *MapReader::find(const Keys &keys)
{
    for (const char *key : keys) {
        for (Entry &entry : m_entries) {
            if (!entry.used && entry.key == QLatin1String(key))
                return &entry;
        }
    }
    return nullptr;
}

std::optional<YAML::Node> MapReader::take(const Keys &keys)
{
    Entry *entry = find(keys);
    if (!entry)
        return std::nullopt;
    entry->used = true;
    return entry->value;
}

std::optional<QString> MapReader::scalar(const Keys &keys)
{
    const auto value = take(keys);
    if (!value || value->IsNull())
        return std::nullopt;
    if (!value->IsScalar()) {
        m_context.error(value->Mark(),
                        tr("'%1' should be a single value, not a list or mapping")
                            .arg(QLatin1String(*keys.begin())));
        return std::nullopt;
    }
    return fromStd(value->Scalar());
}

QString MapReader::required(const Keys &keys, RtcMissing &missing, const char *schemaName)
{
    if (auto value = scalar(keys))
        return *value;
    const QString name
        = schemaName ? QLatin1String(schemaName) : localKey(QLatin1String(*keys.begin()));
    missing.append(name);
    m_context.warn(m_node.Mark(), tr("the required key '%1' is missing").arg(name));
    return {};
}

std::optional<YAML::Node> MapReader::map(const Keys &keys)
{
    const auto value = take(keys);
    if (!value)
        return std::nullopt;
    if (value->IsNull())
        return YAML::Node(YAML::NodeType::Map);
    if (!value->IsMap()) {
        m_context.error(
            value->Mark(),
            tr("'%1' should be a mapping (key: value lines)").arg(QLatin1String(*keys.begin())));
        return std::nullopt;
    }
    return value;
}

std::vector<YAML::Node> MapReader::list(const Keys &keys)
{
    const auto value = take(keys);
    if (!value || value->IsNull())
        return {};
    if (value->IsMap())
        return {*value};
    if (!value->IsSequence()) {
        m_context.error(value->Mark(),
                        tr("'%1' should be a list").arg(QLatin1String(*keys.begin())));
        return {};
    }
    return std::vector<YAML::Node>(value->begin(), value->end());
}

QStringList MapReader::scalarList(const Keys &keys)
{
    QStringList result;
    const auto value = take(keys);
    if (!value || value->IsNull())
        return result;
    if (value->IsScalar())
        return {fromStd(value->Scalar())};
    if (!value->IsSequence()) {
        m_context.error(value->Mark(),
                        tr("'%1' should be a list of values").arg(QLatin1String(*keys.begin())));
        return result;
    }
    for (const YAML::Node &item : *value) {
        if (item.IsScalar())
            result.append(fromStd(item.Scalar()));
        else if (item.IsNull())
            result.append(QString());
        else
            m_context.error(item.Mark(), tr("expected a single value in the list"));
    }
    return result;
}

XmlExtras MapReader::extras(int schemaChildCount) const
{
    XmlExtras extras;
    std::vector<XmlNode> elements;
    for (const Entry &entry : m_entries) {
        if (entry.used)
            continue;
        if (entry.value.IsScalar() || entry.value.IsNull()) {
            const auto [ns, name] = nameOfKey(entry.key);
            extras.attributes.append(
                XmlAttribute {ns, Ns::preferredPrefix(ns), name,
                              entry.value.IsNull() ? QString() : fromStd(entry.value.Scalar())});
        } else {
            appendElements(elements, entry.key, entry.value, 1, m_context);
        }
    }
    int position = schemaChildCount;
    for (XmlNode &element : elements)
        extras.children.push_back(XmlExtras::Child {position++, std::move(element)});
    return extras;
}

// ---- values

Value Value::string(const QString &text)
{
    Value v;
    v.kind = Kind::Scalar;
    v.text = text;
    v.quoted = needsQuotes(text);
    return v;
}

Value Value::plain(const QString &text)
{
    Value v;
    v.kind = Kind::Scalar;
    v.text = text;
    return v;
}

Value Value::number(const QString &text)
{
    bool ok = false;
    text.toDouble(&ok);
    return ok && text.trimmed() == text ? plain(text) : string(text);
}

Value Value::boolean(const QString &text)
{
    const auto value = parseBoolean(text);
    return value ? plain(booleanText(*value)) : string(text);
}

Value Value::sequence(std::vector<Value> items)
{
    Value v;
    v.kind = Kind::Sequence;
    v.items = std::move(items);
    return v;
}

Value Value::stringList(const QStringList &texts)
{
    Value v = sequence();
    for (const QString &text : texts)
        v.items.push_back(string(text));
    return v;
}

void Value::set(const QString &key, Value value)
{
    entries.emplace_back(key, std::move(value));
}

void Value::set(const QString &key, const std::optional<QString> &text)
{
    if (text)
        set(key, string(*text));
}

void Value::setRequired(const QString &key, const QString &text, const RtcMissing &missing,
                        const QString &schemaName)
{
    if (text.isEmpty() && missing.contains(schemaName.isEmpty() ? localKey(key) : schemaName))
        return;
    set(key, string(text));
}

void Value::addExtras(const XmlExtras &extras)
{
    XmlNode holder;
    holder.attributes = extras.attributes;
    for (const XmlExtras::Child &child : extras.children)
        holder.children.push_back(child.node);
    const Value converted = valueOf(holder);
    if (converted.kind == Kind::Map) {
        for (const auto &entry : converted.entries)
            entries.push_back(entry);
    }
}

QByteArray emitDocument(const Value &root)
{
    YAML::Emitter out;
    out.SetIndent(2);
    out << YAML::BeginDoc;
    emitValue(out, root);
    QByteArray text(out.c_str(), qsizetype(out.size()));
    text.append('\n');
    return text;
}

} // namespace Profile::RtcYaml
