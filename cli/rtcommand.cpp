// SPDX-License-Identifier: MIT
#include "rtcommand.h"

#include "corbaerror.h"
#include "orb.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QRegularExpression>

namespace Cli {

using namespace Corba;

namespace {

// Splits "-lR" into "-l" "-R" when every letter is a known flag, as getopt does.
QStringList expandShortFlags(const QString &argument, const QStringList &flags)
{
    if (argument.size() <= 2 || argument.startsWith(QLatin1String("--")))
        return {argument};
    QStringList expanded;
    for (int i = 1; i < argument.size(); ++i) {
        const QString flag = QStringLiteral("-") + argument.at(i);
        if (!flags.contains(flag))
            return {argument};
        expanded.append(flag);
    }
    return expanded;
}

RtOptions parseOptions(const QStringList &arguments, const QStringList &flags,
                       const QStringList &options)
{
    RtOptions parsed;
    bool onlyPositionals = false;
    for (int i = 0; i < arguments.size(); ++i) {
        const QString argument = arguments.at(i);
        // Negative numbers are values (`rtctl inject … -3`), not options.
        static const QRegularExpression negativeNumber(QStringLiteral("^-\\.?\\d"));
        if (onlyPositionals || !argument.startsWith(QLatin1Char('-'))
            || argument == QLatin1String("-") || negativeNumber.match(argument).hasMatch()) {
            parsed.positionals.append(argument);
            continue;
        }
        if (argument == QLatin1String("--")) {
            onlyPositionals = true;
            continue;
        }
        if (options.contains(argument)) {
            if (i + 1 >= arguments.size()) {
                parsed.error = QStringLiteral("option %1 needs a value").arg(argument);
                return parsed;
            }
            parsed.values[argument].append(arguments.at(++i));
            parsed.sequence.append({argument, arguments.at(i)});
            continue;
        }
        for (const QString &flag : expandShortFlags(argument, flags)) {
            if (!flags.contains(flag)) {
                parsed.error = QStringLiteral("unknown option %1").arg(flag);
                return parsed;
            }
            ++parsed.flags[flag];
        }
    }
    return parsed;
}

} // namespace

Corba::ManagerProxy RtCommand::managerAt(const QString &text) const
{
    const RtPath target = path(text);
    // `corbaloc::host:port` names a manager's object ("manager" key): its first call tells whether
    // it answers, a round trip less than asking first what it is.
    const NamingNode node = target.isDirect() && target.corbaloc.endsWith(QLatin1String("/manager"))
                                ? NamingNode {QStringLiteral("manager.mgr"), NodeType::Manager, target.toString(),
                                              target.corbaloc, {}, {}}
                                : NamingBrowser::node(target);
    if (node.type != NodeType::Manager)
        throw Error(
            Error::Kind::WrongType,
            node.reason.isEmpty()
                ? QStringLiteral("%1: not a manager (%2)").arg(node.path, nodeTypeName(node.type))
                : node.reason);
    return ManagerProxy(node.ior, node.path);
}

int RtCommand::run(const QStringList &arguments, Streams streams)
{
    RtOptions options = parseOptions(arguments, flagNames(),
                                     optionNames() + QStringList {QStringLiteral("--timeout")});
    if (!options.error.isEmpty())
        return usageError(options.error, streams);
    if (options.values.contains(QStringLiteral("--timeout"))) {
        bool ok = false;
        const int timeout = options.value(QStringLiteral("--timeout")).toInt(&ok);
        if (!ok || timeout <= 0)
            return usageError(QStringLiteral("--timeout needs a positive number of milliseconds"),
                              streams);
        Orb::setCallTimeout(timeout);
    }
    try {
        return execute(options, streams);
    } catch (const Error &e) {
        report(e.message(), streams);
        return ExitProblems;
    }
}

QString RtCommand::currentDirectory()
{
    const QString cwd = qEnvironmentVariable("RTCSH_CWD");
    return cwd.isEmpty() ? QStringLiteral("/") : cwd;
}

RtPath RtCommand::path(const QString &text) const
{
    QString error;
    const auto parsed = RtPath::parse(text, currentDirectory(), &error);
    if (!parsed)
        throw Error(Error::Kind::BadPath, QStringLiteral("%1: %2").arg(text, error));
    return *parsed;
}

ComponentProxy RtCommand::component(const RtPath &path) const
{
    const NamingNode node = NamingBrowser::node(path);
    if (node.type == NodeType::Zombie)
        throw Error(Error::Kind::WrongType,
                    node.reason.isEmpty() ? node.path + QStringLiteral(": zombie") : node.reason);
    if (node.type != NodeType::Component)
        throw Error(
            Error::Kind::WrongType,
            QStringLiteral("%1: not a component (%2)").arg(node.path, nodeTypeName(node.type)));
    return ComponentProxy(node.ior, node.path);
}

void RtCommand::report(const QString &message, Streams streams) const
{
    streams.err << "rtctl " << name() << ": " << message << '\n';
    streams.err.flush();
}

QString RtCommand::jsonText(const QJsonValue &value)
{
    const QJsonDocument document
        = value.isArray() ? QJsonDocument(value.toArray()) : QJsonDocument(value.toObject());
    return QString::fromUtf8(document.toJson(QJsonDocument::Indented));
}

int forEachPath(const QStringList &paths, Streams streams,
                const std::function<void(const QString &)> &action, const QString &command)
{
    int code = ExitOk;
    for (const QString &path : paths) {
        try {
            action(path);
        } catch (const Error &e) {
            streams.err << "rtctl " << command << ": " << e.message() << '\n';
            code = ExitProblems;
        }
    }
    streams.err.flush();
    return code;
}

} // namespace Cli
