// SPDX-License-Identifier: MIT
#include "nodefactsfile.h"

#include <QFile>
#include <QSet>

#include <yaml-cpp/yaml.h>

namespace Planner {

namespace {

/// Thrown inside this file only: a bad entry, with the line it is on.
struct FactsError
{
    int line;
    QString reason;
};

QString qs(const std::string &text)
{
    return QString::fromStdString(text);
}

int lineOf(const YAML::Node &node)
{
    return node.Mark().line + 1;
}

QString scalarOrList(const YAML::Node &value, const QString &key)
{
    if (value.IsScalar())
        return qs(value.Scalar());
    if (value.IsNull())
        return QString();
    if (!value.IsSequence())
        throw FactsError {lineOf(value), QStringLiteral("'%1' must be a value or a list").arg(key)};
    QStringList items;
    for (const YAML::Node &item : value) {
        if (!item.IsScalar())
            throw FactsError {lineOf(item), QStringLiteral("'%1' must list plain values").arg(key)};
        items << qs(item.Scalar());
    }
    return items.join(QLatin1Char(','));
}

void flatten(const YAML::Node &map, const QString &prefix, FactProperties *out)
{
    for (const auto &entry : map) {
        if (!entry.first.IsScalar())
            throw FactsError {lineOf(entry.first), QStringLiteral("a key must be plain text")};
        const QString key = prefix + qs(entry.first.Scalar());
        if (entry.second.IsMap())
            flatten(entry.second, key + QLatin1Char('.'), out);
        else
            out->append({key, scalarOrList(entry.second, key)});
    }
}

NodeFacts readNode(const YAML::Node &entry)
{
    if (!entry.IsMap())
        throw FactsError {lineOf(entry), QStringLiteral("a node must be a map of facts")};
    FactProperties properties;
    flatten(entry, QString(), &properties);
    QString name;
    for (const auto &[key, value] : std::as_const(properties)) {
        if (key == QLatin1String("name"))
            name = value.trimmed();
    }
    if (name.isEmpty())
        throw FactsError {lineOf(entry), QStringLiteral("a node has no 'name'")};
    return NodeFacts::fromProperties(name, properties);
}

QList<NodeFacts> readNodes(const YAML::Node &root)
{
    const YAML::Node list = root.IsMap() ? root["nodes"] : root;
    if (!list || !list.IsSequence())
        throw FactsError {lineOf(root),
                          QStringLiteral("expected a list of nodes (or 'nodes:' with one)")};
    QList<NodeFacts> nodes;
    QSet<QString> names;
    for (const YAML::Node &entry : list) {
        NodeFacts facts = readNode(entry);
        if (names.contains(facts.name))
            throw FactsError {lineOf(entry),
                              QStringLiteral("node '%1' is listed twice").arg(facts.name)};
        names.insert(facts.name);
        nodes << std::move(facts);
    }
    if (nodes.isEmpty())
        throw FactsError {lineOf(list), QStringLiteral("no nodes listed")};
    return nodes;
}

} // namespace

std::optional<QList<NodeFacts>> readNodeFactsData(const QByteArray &data, const QString &fileName,
                                                  QString *error)
{
    try {
        return readNodes(YAML::Load(data.toStdString()));
    } catch (const FactsError &bad) {
        *error = QStringLiteral("%1:%2: %3").arg(fileName).arg(bad.line).arg(bad.reason);
    } catch (const YAML::Exception &bad) {
        *error = QStringLiteral("%1:%2: %3").arg(fileName).arg(bad.mark.line + 1).arg(qs(bad.msg));
    }
    return std::nullopt;
}

std::optional<QList<NodeFacts>> readNodeFactsFile(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return readNodeFactsData(file.readAll(), path, error);
}

} // namespace Planner
