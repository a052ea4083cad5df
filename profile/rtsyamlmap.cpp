// SPDX-License-Identifier: MIT
#include "rtsyamlmap_p.h"

#include <QCoreApplication>
#include <QStringDecoder>

namespace Profile::RtsYaml {

namespace {
QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtsYaml", text);
}
} // namespace

QString fromStd(const std::string &text)
{
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

std::string toStd(const QString &text)
{
    return text.toStdString();
}

QString ext(const char *key)
{
    return QStringLiteral("rtsExt::") + QLatin1String(key);
}

Context::Context(const QString &fileName, Diagnostics *diagnostics)
    : m_fileName(fileName)
    , m_diagnostics(diagnostics)
{ }

void Context::report(Diagnostic::Severity severity, const YAML::Mark &mark,
                     const QString &message) const
{
    if (!m_diagnostics)
        return;
    // yaml-cpp counts from 0 and marks "unknown" with -1.
    Diagnostic d = Diagnostic::error(m_fileName, mark.line < 0 ? 0 : mark.line + 1,
                                     mark.column < 0 ? 0 : mark.column + 1, message);
    d.severity = severity;
    m_diagnostics->append(d);
}

void Context::error(const YAML::Mark &mark, const QString &message) const
{
    report(Diagnostic::Severity::Error, mark, message);
}

void Context::warn(const YAML::Mark &mark, const QString &message) const
{
    report(Diagnostic::Severity::Warning, mark, message);
}

SourceLocation locationOf(const YAML::Node &node)
{
    const YAML::Mark mark = node.Mark();
    return mark.line < 0 ? SourceLocation {} : SourceLocation {mark.line + 1, mark.column + 1};
}

bool checkUtf8(const QByteArray &data, const Context &context)
{
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    const QString all = decoder.decode(data);
    if (!decoder.hasError())
        return true;
    // Only on failure: decode line by line to say where.
    int line = 0;
    for (const QByteArray &text : data.split('\n')) {
        QStringDecoder lineDecoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
        const QString decoded = lineDecoder.decode(text);
        if (lineDecoder.hasError()) {
            YAML::Mark mark = YAML::Mark::null_mark();
            mark.line = line;
            mark.column = int(qMax<qsizetype>(decoded.indexOf(QChar::ReplacementCharacter), 0));
            context.error(mark, tr("invalid UTF-8 byte sequence"));
            return false;
        }
        ++line;
    }
    context.error(YAML::Mark::null_mark(), tr("invalid UTF-8 byte sequence"));
    return false;
}

Map::Map(const YAML::Node &node, const Context &context)
    : m_node(node)
    , m_context(context)
{
    for (auto it = node.begin(); it != node.end(); ++it)
        addEntry(it->first, it->second);
}

std::optional<QString> Map::scalar(const QString &key)
{
    const YAML::Node *value = take(key);
    if (!value || value->IsNull())
        return std::nullopt;
    if (!value->IsScalar()) {
        m_context.error(value->Mark(), tr("'%1' must be a single value").arg(key));
        return std::nullopt;
    }
    return fromStd(value->Scalar());
}

std::optional<YAML::Node> Map::value(const QString &key)
{
    const YAML::Node *value = take(key);
    return value ? std::optional<YAML::Node>(*value) : std::nullopt;
}

QString Map::required(const char *key)
{
    const QString name = QLatin1String(key);
    const bool present = has(name);
    const auto value = scalar(name);
    if (!present)
        m_context.error(m_node.Mark(), tr("the mapping lacks the required key '%1'").arg(name));
    return value.value_or(QString());
}

void Map::addExtrasTo(RtsYamlExtras &extras, const QString &prefix) const
{
    for (const Entry &e : m_entries) {
        if (e.used)
            continue;
        YAML::Emitter out;
        out << e.value;
        extras.entries.append({prefix + e.key, QString::fromUtf8(out.c_str())});
    }
}

RtsYamlExtras Map::extras() const
{
    RtsYamlExtras result;
    addExtrasTo(result);
    return result;
}

void Map::addEntry(const YAML::Node &key, const YAML::Node &value)
{
    if (!key.IsScalar()) {
        m_context.warn(key.Mark(), tr("a mapping key that is not text was ignored"));
        return;
    }
    const QString name = fromStd(key.Scalar());
    if (has(name)) {
        m_context.warn(key.Mark(), tr("duplicate key '%1' was ignored").arg(name));
        return;
    }
    m_entries.push_back({name, value, false});
}

bool Map::has(const QString &key) const
{
    for (const Entry &e : m_entries) {
        if (e.key == key)
            return true;
    }
    return false;
}

const YAML::Node *Map::take(const QString &key)
{
    for (Entry &e : m_entries) {
        if (e.key == key && !e.used) {
            e.used = true;
            return &e.value;
        }
    }
    return nullptr;
}

std::optional<YAML::Node> Map::typed(const QString &key, bool wantSequence)
{
    const YAML::Node *value = take(key);
    if (!value || value->IsNull())
        return std::nullopt;
    if (wantSequence ? value->IsSequence() : value->IsMap())
        return *value;
    m_context.error(value->Mark(),
                    wantSequence ? tr("'%1' must be a list").arg(key)
                                 : tr("'%1' must be a mapping").arg(key));
    return std::nullopt;
}

} // namespace Profile::RtsYaml
