// SPDX-License-Identifier: MIT
#include "rtfindcommand.h"

#include "rtjson.h"

#include <QRegularExpression>

namespace Cli {

using namespace Corba;

namespace {

QChar typeLetter(NodeType type)
{
    switch (type) {
    case NodeType::Component:
        return QLatin1Char('c');
    case NodeType::Context:
        return QLatin1Char('d');
    case NodeType::Manager:
        return QLatin1Char('m');
    case NodeType::Server:
        return QLatin1Char('n');
    case NodeType::Zombie:
        return QLatin1Char('z');
    default:
        break;
    }
    return QLatin1Char('o');
}

struct Filter
{
    QRegularExpression name;
    QString types;

    bool matches(const NamingNode &node) const
    {
        if (!types.isEmpty() && !types.contains(typeLetter(node.type)))
            return false;
        return !name.isValid() || name.pattern().isEmpty() || name.match(node.name).hasMatch();
    }
};

void collect(const NamingNode &node, const Filter &filter, std::vector<const NamingNode *> &found)
{
    for (const NamingNode &child : node.children) {
        if (filter.matches(child))
            found.push_back(&child);
        collect(child, filter, found);
    }
}

} // namespace

QString RtFindCommand::summary() const
{
    return QStringLiteral("search the RTC tree by name and type");
}

QString RtFindCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl find [--json] [--timeout MS] PATH [-n PATTERN] [-i PATTERN] [-m DEPTH] "
        "[-t TYPES]\n\n"
        "Prints the full path of every node below PATH that matches (rtshell's rtfind).\n"
        "  -n PATTERN  glob on the node name (case-sensitive), e.g. 'Console*.rtc'\n"
        "  -i PATTERN  the same, case-insensitive\n"
        "  -m DEPTH    descend at most DEPTH levels\n"
        "  -t TYPES    any of c (component), d (directory/context), m (manager), n (name server),\n"
        "              z (zombie)\n"
        "  --json      a JSON array of {name, path, type}\n");
}

QStringList RtFindCommand::optionNames() const
{
    return {QStringLiteral("-n"), QStringLiteral("-i"), QStringLiteral("-m"), QStringLiteral("-t")};
}

int RtFindCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.size() != 1)
        return usageError(QStringLiteral("find needs exactly one PATH"), streams);
    bool ok = true;
    const int depth = options.value(QStringLiteral("-m"), QStringLiteral("-1")).toInt(&ok);
    if (!ok)
        return usageError(QStringLiteral("-m needs a number"), streams);
    Filter filter;
    filter.types = options.value(QStringLiteral("-t"));
    if (filter.types.contains(QRegularExpression(QStringLiteral("[^cdmnz]"))))
        return usageError(QStringLiteral("-t takes the letters c, d, m, n, z"), streams);
    const bool insensitive = options.values.contains(QStringLiteral("-i"));
    const QString glob
        = insensitive ? options.value(QStringLiteral("-i")) : options.value(QStringLiteral("-n"));
    if (!glob.isEmpty()) {
        filter.name.setPattern(QRegularExpression::wildcardToRegularExpression(
            glob, QRegularExpression::UnanchoredWildcardConversion));
        filter.name.setPattern(QLatin1Char('^') + filter.name.pattern() + QLatin1Char('$'));
        if (insensitive)
            filter.name.setPatternOptions(QRegularExpression::CaseInsensitiveOption);
    }
    const NamingNode tree = NamingBrowser::tree(path(options.positionals.first()), depth,
                                                NamingBrowser::serversFromEnvironment());
    std::vector<const NamingNode *> found;
    collect(tree, filter, found);
    QJsonArray json;
    for (const NamingNode *node : found) {
        if (options.has(QStringLiteral("--json")))
            json.append(QJsonObject {
                {"name", node->name}, {"path", node->path}, {"type", nodeTypeName(node->type)}});
        else
            streams.out << node->path << '\n';
    }
    if (options.has(QStringLiteral("--json")))
        streams.out << jsonText(json);
    return ExitOk;
}

} // namespace Cli
