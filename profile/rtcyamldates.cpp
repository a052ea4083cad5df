// SPDX-License-Identifier: MIT
// Dates in RTC Builder's YAML: xs:dateTime text, or EMF's mapping of the XMLGregorianCalendar
// fields ({year, month, day, hour, minute, second, fractionalSecond, millisecond, timezone}).
#include "rtcyamlinternal.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace Profile::RtcYaml {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcYaml", text);
}

/// A mapping's value by key without yaml-cpp's throwing look-up of absent keys.
YAML::Node field(const YAML::Node &map, const char *key)
{
    for (const auto &entry : map) {
        if (entry.first.IsScalar() && entry.first.Scalar() == key)
            return entry.second;
    }
    return YAML::Node(YAML::NodeType::Undefined);
}

std::optional<int> intField(const YAML::Node &map, const char *key)
{
    const YAML::Node value = field(map, key);
    if (!value.IsScalar())
        return std::nullopt;
    bool ok = false;
    const int number = fromStd(value.Scalar()).toInt(&ok);
    return ok ? std::optional<int>(number) : std::nullopt;
}

QString fractionOf(const YAML::Node &map)
{
    const YAML::Node fraction = field(map, "fractionalSecond");
    if (fraction.IsScalar()) {
        const QString text = fromStd(fraction.Scalar());
        if (text.startsWith(QLatin1String("0.")))
            return text.mid(1);
    }
    if (const auto ms = intField(map, "millisecond"))
        return QStringLiteral(".%1").arg(*ms, 3, 10, QLatin1Char('0'));
    return {};
}

QString zoneOf(const YAML::Node &map)
{
    const auto minutes = intField(map, "timezone");
    if (!minutes)
        return {};
    const int total = std::abs(*minutes);
    return QStringLiteral("%1%2:%3")
        .arg(*minutes < 0 ? QLatin1Char('-') : QLatin1Char('+'))
        .arg(total / 60, 2, 10, QLatin1Char('0'))
        .arg(total % 60, 2, 10, QLatin1Char('0'));
}

std::optional<QString> dateFromMap(const YAML::Node &map)
{
    const auto year = intField(map, "year");
    const auto month = intField(map, "month");
    const auto day = intField(map, "day");
    if (!year || !month || !day)
        return std::nullopt;
    const int hour = intField(map, "hour").value_or(0);
    const int minute = intField(map, "minute").value_or(0);
    const int second = intField(map, "second").value_or(0);
    return QStringLiteral("%1-%2-%3T%4:%5:%6")
               .arg(*year, 4, 10, QLatin1Char('0'))
               .arg(*month, 2, 10, QLatin1Char('0'))
               .arg(*day, 2, 10, QLatin1Char('0'))
               .arg(hour, 2, 10, QLatin1Char('0'))
               .arg(minute, 2, 10, QLatin1Char('0'))
               .arg(second, 2, 10, QLatin1Char('0'))
        + fractionOf(map) + zoneOf(map);
}

} // namespace

std::optional<QString> readDate(const YAML::Node &node, Context &context)
{
    if (node.IsScalar())
        return fromStd(node.Scalar());
    if (node.IsMap()) {
        if (auto text = dateFromMap(node))
            return text;
    }
    context.error(node.Mark(),
                  tr("expected a date: xs:dateTime text or a mapping with year, "
                     "month, day, hour, minute, second"));
    return std::nullopt;
}

Value dateValue(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral(
        R"(^(\d{4})-(\d{2})-(\d{2})T(\d{2}):(\d{2}):(\d{2})(\.\d+)?([+-]\d{2}:\d{2})?$)"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch())
        return Value::string(text);
    Value map;
    const char *fields[] = {"year", "month", "day", "hour", "minute", "second"};
    YAML::Node check(YAML::NodeType::Map);
    for (int i = 0; i < 6; ++i) {
        const QString number = QString::number(match.captured(i + 1).toInt());
        map.set(QLatin1String(fields[i]), Value::plain(number));
        check[fields[i]] = toStd(number);
    }
    if (match.hasCaptured(7)) {
        const QString fraction = QLatin1Char('0') + match.captured(7);
        const QString ms = QString::number(qRound(fraction.toDouble() * 1000));
        map.set(QStringLiteral("fractionalSecond"), Value::plain(fraction));
        map.set(QStringLiteral("millisecond"), Value::plain(ms));
        check["fractionalSecond"] = toStd(fraction);
    }
    if (match.hasCaptured(8)) {
        const QString zone = match.captured(8);
        const int minutes = zone.mid(1, 2).toInt() * 60 + zone.mid(4, 2).toInt();
        const QString value
            = QString::number(zone.startsWith(QLatin1Char('-')) ? -minutes : minutes);
        map.set(QStringLiteral("timezone"), Value::plain(value));
        check["timezone"] = toStd(value);
    }
    // Only a mapping that reads back as the very same text is written as one.
    return dateFromMap(check) == text ? map : Value::string(text);
}

} // namespace Profile::RtcYaml
