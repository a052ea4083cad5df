// SPDX-License-Identifier: MIT
// Reads rtsprofile's YAML dialect into RtsProfile. Every yaml-cpp call that can throw runs inside
// readRtsYaml's try block; structural problems (a list where a value belongs …) are reported at the
// node's mark and the reader carries on, so one file shows all its problems at once.
#include "rtsfields_p.h"
#include "rtsyaml.h"
#include "rtsyamlmap_p.h"

#include <QCoreApplication>

namespace Profile {

namespace {

using namespace RtsYaml;

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtsYaml", text);
}

constexpr qint64 MaxYamlBytes = 512LL * 1024 * 1024;

/// Maps the YAML nodes of a profile onto the model by walking the field tables.
class RtsYamlReader
{
public:
    explicit RtsYamlReader(const Context &context)
        : m_context(context)
    { }

    /// Keys in table order (the order of diagnostics); what is left becomes the extras.
    template<typename T> T readElement(const YAML::Node &node)
    {
        Map m(node, m_context);
        T item;
        Fields::forEachRow(Fields::RtsElement<T>::fields,
                           [&](const auto &row) { readRow(m, item, row); });
        m.addExtrasTo(item.yamlExtras);
        item.location = m.location();
        return item;
    }

private:
    template<typename T, typename Owner, typename Value>
    void readRow(Map &m, T &item, const Fields::Scalar<Owner, Value> &row)
    {
        constexpr bool required = Fields::Scalar<Owner, Value>::required;
        std::optional<QString> value;
        // Unlike XML, a legacy key wins over the schema's (a converted file may carry it).
        for (const char *key : row.yamlLegacyKeys) {
            if (key && !value)
                value = m.scalar(key);
        }
        if (!value)
            value = readScalar(m, row.yamlKey, row.style, required);
        if (value && row.normalize)
            value = row.normalize(*value);
        if constexpr (required)
            item.*row.member = value.value_or(QString());
        else
            item.*row.member = value;
    }

    /// A required key is reported when absent (and read as empty text).
    std::optional<QString> readScalar(Map &m, const char *key, Fields::Style style, bool required)
    {
        if (style == Fields::Style::Date)
            return readDate(m, key);
        if (required)
            return m.required(key);
        return m.scalar(key);
    }

    /// Each list entry must be a mapping; others are reported and skipped.
    template<typename T, typename Owner, typename Item>
    void readRow(Map &m, T &item, const Fields::Child<Owner, QList<Item>> &row)
    {
        const QString key = QLatin1String(row.yamlKey);
        const auto list = m.sequence(key);
        if (!list)
            return;
        QList<Item> &result = item.*row.member;
        result.reserve(qsizetype(list->size()));
        for (const YAML::Node &entry : *list) {
            if (entry.IsMap())
                result.append(readElement<Item>(entry));
            else
                m_context.error(entry.Mark(), tr("each entry of '%1' must be a mapping").arg(key));
        }
    }

    template<typename T, typename Owner, typename Item>
    void readRow(Map &m, T &item, const Fields::Child<Owner, std::optional<Item>> &row)
    {
        if (const auto child = m.map(row.yamlKey))
            item.*row.member = readElement<Item>(*child);
    }

    template<typename T, typename Owner, typename Item>
    void readRow(Map &m, T &item, const Fields::Child<Owner, Item> &row)
    {
        if (const auto child = m.map(row.yamlKey))
            item.*row.member = readElement<Item>(*child);
        else
            m_context.error(m.node().Mark(), tr(row.yamlMissing).arg(QLatin1String(row.yamlKey)));
    }

    template<typename T, typename Owner>
    void readRow(Map &m, T &item, const Fields::TextList<Owner> &row)
    {
        const QString key = QLatin1String(row.yamlKey);
        const auto list = m.sequence(key);
        if (!list)
            return;
        for (const YAML::Node &entry : *list) {
            if (entry.IsScalar())
                (item.*row.member).append(fromStd(entry.Scalar()));
            else
                m_context.error(entry.Mark(), tr("each entry of '%1' must be text").arg(key));
        }
    }

    template<typename T, typename... Rows>
    void readRow(Map &m, T &item, const Fields::YamlGroup<Rows...> &group)
    {
        const auto node = m.map(group.yamlKey);
        if (!node)
            return;
        Map inner(*node, m_context);
        Fields::forEachRow(group.rows, [&](const auto &row) { readRow(inner, item, row); });
        inner.addExtrasTo(item.yamlExtras, QLatin1String(group.yamlKey) + QLatin1Char('/'));
    }

    /// rtsprofile's {year, month, day, hour, minute, second} (+ this project's fraction and
    /// timeZone, which keep OpenRTP's milliseconds and offsets); plain text is taken as it is.
    QString readDate(Map &m, const char *key)
    {
        const QString name = QLatin1String(key);
        const auto date = m.value(name);
        if (!date || date->IsNull()) {
            m_context.error(m.node().Mark(),
                            tr("the mapping lacks the required key '%1'").arg(name));
            return {};
        }
        if (date->IsMap())
            return readDateMap(*date, name);
        if (date->IsScalar())
            return fromStd(date->Scalar());
        m_context.error(date->Mark(), tr("'%1' must be a date").arg(name));
        return {};
    }

    int readDatePart(Map &m, const char *part, const QString &name)
    {
        const auto value = m.value(QLatin1String(part));
        bool ok = false;
        const int number = value && value->IsScalar() ? fromStd(value->Scalar()).toInt(&ok) : 0;
        if (!value)
            m_context.error(m.node().Mark(), tr("'%1' lacks '%2'").arg(name, QLatin1String(part)));
        else if (!ok)
            m_context.error(value->Mark(),
                            tr("'%1.%2' must be a whole number").arg(name, QLatin1String(part)));
        return number;
    }

    QString readDateMap(const YAML::Node &node, const QString &name)
    {
        Map m(node, m_context);
        const int year = readDatePart(m, "year", name);
        const int month = readDatePart(m, "month", name);
        const int day = readDatePart(m, "day", name);
        const int hour = readDatePart(m, "hour", name);
        const int minute = readDatePart(m, "minute", name);
        const int second = readDatePart(m, "second", name);
        QString text = QStringLiteral("%1-%2-%3T%4:%5:%6")
                           .arg(year, 4, 10, QLatin1Char('0'))
                           .arg(month, 2, 10, QLatin1Char('0'))
                           .arg(day, 2, 10, QLatin1Char('0'))
                           .arg(hour, 2, 10, QLatin1Char('0'))
                           .arg(minute, 2, 10, QLatin1Char('0'))
                           .arg(second, 2, 10, QLatin1Char('0'));
        if (const auto fraction = m.scalar("fraction"))
            text += QLatin1Char('.') + *fraction;
        if (const auto zone = m.scalar("timeZone"))
            text += *zone;
        return text;
    }

    const Context &m_context;
};

std::optional<RtsProfile> readDocument(const YAML::Node &document, const Context &context)
{
    if (!document.IsMap() || !document["rtsProfile"]) {
        context.error(document.Mark(),
                      tr("not an RTS Profile: expected a top-level 'rtsProfile:' mapping"));
        return std::nullopt;
    }
    for (auto it = document.begin(); it != document.end(); ++it) {
        if (it->first.Scalar() != "rtsProfile")
            context.warn(it->first.Mark(),
                         tr("the top-level key '%1' was ignored").arg(fromStd(it->first.Scalar())));
    }
    const YAML::Node profile = document["rtsProfile"];
    if (!profile.IsMap()) {
        context.error(profile.Mark(), tr("'rtsProfile' must be a mapping"));
        return std::nullopt;
    }
    return RtsYamlReader(context).readElement<RtsProfile>(profile);
}

} // namespace

std::optional<RtsProfile> readRtsYaml(const QByteArray &data, const QString &fileName,
                                      Diagnostics *diagnostics)
{
    const Context context(fileName, diagnostics);
    if (data.size() > MaxYamlBytes) {
        context.error(YAML::Mark::null_mark(),
                      tr("file is larger than %1 bytes").arg(MaxYamlBytes));
        return std::nullopt;
    }
    if (!checkUtf8(data, context))
        return std::nullopt;
    try {
        const YAML::Node document = YAML::Load(data.toStdString());
        return readDocument(document, context);
    } catch (const YAML::Exception &e) {
        context.error(e.mark, fromStd(e.msg));
    } catch (const std::exception &e) {
        context.error(YAML::Mark::null_mark(),
                      tr("cannot read YAML: %1").arg(QString::fromLocal8Bit(e.what())));
    }
    return std::nullopt;
}

} // namespace Profile
