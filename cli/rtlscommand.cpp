// SPDX-License-Identifier: MIT
#include "rtlscommand.h"

#include "componentproxy.h"
#include "corbaerror.h"
#include "rtjson.h"

namespace Cli {

using namespace Corba;

namespace {

bool isDirectory(const NamingNode &node)
{
    return node.type == NodeType::Root || node.type == NodeType::Server
        || node.type == NodeType::Context || node.type == NodeType::Manager;
}

QString pair(int total, int connected)
{
    return QStringLiteral("%1/%2").arg(total).arg(connected);
}

} // namespace

QString RtLsCommand::summary() const
{
    return QStringLiteral("list name servers, contexts, components and managers");
}

QString RtLsCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl ls [-l] [-R] [--json] [--timeout MS] [PATH...]\n\n"
        "Lists the RTC tree (rtshell's rtls). PATH defaults to RTCSH_CWD (or /); the root lists\n"
        "the name servers in RTCTREE_NAMESERVERS (';'-separated). Zombies (names whose object\n"
        "is gone or of the wrong type) are marked with '*'; objects that hang keep their place and\n"
        "show as Silent in the long form.\n"
        "  -l      long form: state, ports total/connected, in, out, service, name\n"
        "  -R      recurse into contexts and managers\n"
        "  --json  one JSON array of {name, path, type, ...} (with -l also state and ports)\n");
}

QStringList RtLsCommand::flagNames() const
{
    return {QStringLiteral("-l"), QStringLiteral("-R"), QStringLiteral("--json")};
}

QString RtLsCommand::row(const NamingNode &node, bool longForm) const
{
    const QString name
        = (node.type == NodeType::Zombie ? QStringLiteral("*") : QString()) + node.name;
    if (!longForm)
        return name;
    QStringList columns {QStringLiteral("-"), QStringLiteral("-"), QStringLiteral("-"),
                         QStringLiteral("-"), QStringLiteral("-")};
    // One that did not answer while listing is not asked again (another call timeout each).
    if (!node.answering)
        columns[0] = QStringLiteral("Silent");
    else if (node.type == NodeType::Component && !node.ior.isEmpty()) {
        try {
            const ComponentProxy rtc(node.ior, node.path);
            const PortCounts c = countPorts(rtc.ports());
            columns
                = {stateName(rtc.state()), pair(c.total, c.connected), pair(c.in, c.inConnected),
                   pair(c.out, c.outConnected), pair(c.service, c.serviceConnected)};
        } catch (const Error &) {
            columns[0] = stateName(LifeCycleState::Unknown);
        }
    }
    return QStringLiteral("%1 %2 %3 %4 %5 %6")
        .arg(columns[0], -9)
        .arg(columns[1], -5)
        .arg(columns[2], -5)
        .arg(columns[3], -5)
        .arg(columns[4], -5)
        .arg(name);
}

void RtLsCommand::printListing(const NamingNode &directory, bool longForm, bool recursive,
                               Streams streams) const
{
    if (!isDirectory(directory)) {
        streams.out << row(directory, longForm) << '\n';
        return;
    }
    if (recursive)
        streams.out << directory.path << ":\n";
    for (const NamingNode &child : directory.children)
        streams.out << row(child, longForm) << '\n';
    if (!recursive)
        return;
    for (const NamingNode &child : directory.children) {
        if (isDirectory(child)) {
            streams.out << '\n';
            printListing(child, longForm, recursive, streams);
        }
    }
}

QJsonObject RtLsCommand::detailedJson(const NamingNode &node, bool longForm) const
{
    QJsonObject object = nodeToJson(node);
    object.remove(QStringLiteral("children"));
    if (longForm && node.type == NodeType::Component && !node.ior.isEmpty() && node.answering) {
        try {
            const ComponentProxy rtc(node.ior, node.path);
            const PortCounts c = countPorts(rtc.ports());
            object.insert("state", stateName(rtc.state()));
            object.insert("ports",
                          QJsonObject {{"total", c.total},
                                       {"connected", c.connected},
                                       {"in", c.in},
                                       {"out", c.out},
                                       {"service", c.service}});
        } catch (const Error &e) {
            object.insert("state", stateName(LifeCycleState::Unknown));
            object.insert("reason", e.message());
        }
    }
    if (!node.children.empty()) {
        QJsonArray children;
        for (const NamingNode &child : node.children)
            children.append(detailedJson(child, longForm));
        object.insert("children", children);
    }
    return object;
}

int RtLsCommand::execute(const RtOptions &options, Streams streams)
{
    const bool longForm = options.has(QStringLiteral("-l"));
    const bool recursive = options.has(QStringLiteral("-R"));
    const QStringList texts
        = options.positionals.isEmpty() ? QStringList {currentDirectory()} : options.positionals;
    const QStringList servers = NamingBrowser::serversFromEnvironment();
    QJsonArray json;
    int code = ExitOk;
    for (const QString &text : texts) {
        try {
            const NamingNode tree = NamingBrowser::tree(path(text), recursive ? -1 : 1, servers);
            if (!options.has(QStringLiteral("--json"))) {
                printListing(tree, longForm, recursive, streams);
                continue;
            }
            if (!isDirectory(tree))
                json.append(detailedJson(tree, longForm));
            for (const NamingNode &child : tree.children)
                json.append(detailedJson(child, longForm));
        } catch (const Error &e) {
            report(e.message(), streams);
            code = ExitProblems;
        }
    }
    if (options.has(QStringLiteral("--json")))
        streams.out << jsonText(json);
    return code;
}

} // namespace Cli
