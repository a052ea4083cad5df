// SPDX-License-Identifier: MIT
#include "nodefacts.h"

#include <QRegularExpression>

namespace Planner {

namespace {

std::optional<QString> text(const QMap<QString, QString> &values, const QString &key)
{
    const auto it = values.constFind(key);
    if (it == values.constEnd() || it->trimmed().isEmpty())
        return std::nullopt;
    return it->trimmed();
}

template<typename Number, typename Convert>
std::optional<Number> number(const QMap<QString, QString> &values, const QString &key,
                             Convert convert)
{
    const std::optional<QString> value = text(values, key);
    if (!value)
        return std::nullopt;
    bool ok = false;
    const Number n = convert(*value, &ok);
    return ok ? std::optional<Number>(n) : std::nullopt;
}

std::optional<QStringList> list(const QMap<QString, QString> &values, const QString &key)
{
    const auto it = values.constFind(key);
    if (it == values.constEnd())
        return std::nullopt;
    return splitFactList(*it);
}

QMap<QString, QString> toMap(const FactProperties &properties)
{
    QMap<QString, QString> map;
    for (const auto &[key, value] : properties)
        map.insert(key, value);
    return map;
}

} // namespace

QStringList splitFactList(const QString &text)
{
    static const QRegularExpression separators(QStringLiteral("[,\\s]+"));
    return text.split(separators, Qt::SkipEmptyParts);
}

QString canonicalArchitecture(const QString &name)
{
    const QString lower = name.trimmed().toLower();
    static const QMap<QString, QString> aliases {
        {QStringLiteral("amd64"), QStringLiteral("x86_64")},

        {QStringLiteral("x64"), QStringLiteral("x86_64")},
        {QStringLiteral("arm64"), QStringLiteral("aarch64")},
        {QStringLiteral("armhf"), QStringLiteral("armv7l")},
        {QStringLiteral("armv7"), QStringLiteral("armv7l")},
        {QStringLiteral("i686"), QStringLiteral("i386")},
        {QStringLiteral("x86"), QStringLiteral("i386")},
        {QStringLiteral("ia32"), QStringLiteral("i386")}};
    return aliases.value(lower, lower);
}

QStringList NodeFacts::devices() const
{
    return splitFactList(userFacts.value(QStringLiteral("devices")));
}

std::optional<double> NodeFacts::freeCpus() const
{
    if (!cpuCount)
        return std::nullopt;
    return qMax(0.0, *cpuCount - loadAverage.value_or(0.0));
}

NodeFacts NodeFacts::fromProperties(const QString &name, const FactProperties &properties)
{
    const QMap<QString, QString> v = toMap(properties);
    NodeFacts facts;
    facts.name = name;
    facts.os = text(v, QStringLiteral("os.name"));
    facts.osRelease = text(v, QStringLiteral("os.release"));
    facts.distribution = text(v, QStringLiteral("os.distribution"));
    facts.architecture = text(v, QStringLiteral("os.arch"));
    facts.hostname = text(v, QStringLiteral("os.hostname"));
    facts.cpuCount = number<int>(v, QStringLiteral("rtstudio.cpu_count"),
                                 [](const QString &s, bool *ok) { return s.toInt(ok); });
    facts.memoryKiB = number<qint64>(v, QStringLiteral("rtstudio.memory_kib"),
                                     [](const QString &s, bool *ok) { return s.toLongLong(ok); });
    facts.loadAverage = number<double>(v, QStringLiteral("rtstudio.load_average"),
                                       [](const QString &s, bool *ok) { return s.toDouble(ok); });
    facts.sdkAbi = text(v, QStringLiteral("rtstudio.sdk_abi"));
    facts.languages = list(v, QStringLiteral("supported_languages"));
    if (!facts.languages)
        facts.languages = list(v, QStringLiteral("manager.supported_languages"));
    facts.loadableTypes = list(v, QStringLiteral("rtstudio.loadable_types"));
    facts.packages = list(v, QStringLiteral("rtstudio.packages"));
    for (auto it = v.constBegin(); it != v.constEnd(); ++it) {
        if (it.key().startsWith(QLatin1String("node.")))
            facts.userFacts.insert(it.key().mid(5), it.value().trimmed());
    }
    return facts;
}

NodeFacts NodeFacts::fromManager(const QString &name, const FactProperties &profile,
                                 const FactProperties &configuration,
                                 const std::optional<QList<FactProperties>> &loadableModules)
{
    // The configuration first, so that what the profile says wins where both say something.
    NodeFacts facts = fromProperties(name, configuration + profile);
    if (loadableModules) {
        QStringList types;
        for (const FactProperties &module : *loadableModules) {
            for (const auto &[key, value] : module) {
                if (key == QLatin1String("implementation_id") && !types.contains(value))
                    types << value;
            }
        }
        facts.loadableTypes = types;
    }
    return facts;
}

} // namespace Planner
