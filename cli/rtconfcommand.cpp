// SPDX-License-Identifier: MIT
#include "rtconfcommand.h"

#include "corbaerror.h"
#include "rtjson.h"

namespace Cli {

using namespace Corba;

namespace {

bool isHidden(const QString &id)
{
    return id.startsWith(QLatin1String("__")) && id.endsWith(QLatin1String("__"));
}

} // namespace

QString RtConfCommand::summary() const
{
    return QStringLiteral("list, read, write and activate configuration sets");
}

QString RtConfCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl conf PATH [-a] [-s SET] [--json] [--timeout MS] [COMMAND]\n\n"
        "Configuration of a component (rtshell's rtconf). COMMAND is one of\n"
        "  list              sets and parameters, the active set marked '*' (default)\n"
        "  get PARAM         the value of PARAM in SET (default: the active set)\n"
        "  set PARAM VALUE   write PARAM in SET; writing the active set re-activates it\n"
        "  act               activate SET (needs -s)\n"
        "  -a      also hidden sets (__name__)\n"
        "  -s SET  the configuration set to work on\n"
        "  --json  list as {\"active\": ID, \"sets\": [{id, description, active, parameters}]}\n");
}

QStringList RtConfCommand::flagNames() const
{
    return {QStringLiteral("-a"), QStringLiteral("--json")};
}

QStringList RtConfCommand::optionNames() const
{
    return {QStringLiteral("-s")};
}

int RtConfCommand::list(const ComponentProxy &rtc, const RtOptions &options, Streams streams) const
{
    const QString active = rtc.activeConfigurationSet();
    const QString only = options.value(QStringLiteral("-s"));
    if (!only.isEmpty())
        rtc.configurationSet(only); // NotFound names the set
    QJsonArray sets;
    for (const ConfigurationSet &set : rtc.configurationSets()) {
        if ((!only.isEmpty() && set.id != only)
            || (only.isEmpty() && isHidden(set.id) && !options.has(QStringLiteral("-a"))))
            continue;
        sets.append(QJsonObject {{"id", set.id},
                                 {"description", set.description},
                                 {"active", set.id == active},
                                 {"parameters", propertiesToJson(set.data)}});
        if (options.has(QStringLiteral("--json")))
            continue;
        streams.out << (set.id == active ? "* " : "  ") << set.id << '\n';
        for (const auto &parameter : set.data)
            streams.out << "    " << parameter.first << "  " << parameter.second << '\n';
    }
    if (options.has(QStringLiteral("--json")))
        streams.out << jsonText(QJsonObject {{"active", active}, {"sets", sets}});
    return ExitOk;
}

int RtConfCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.isEmpty())
        return usageError(QStringLiteral("missing PATH"), streams);
    const QStringList words = options.positionals.mid(1);
    const QString command = words.value(0, QStringLiteral("list"));
    const int expected = command == QLatin1String("set") ? 3
        : command == QLatin1String("get")                ? 2
                                                         : 1;
    if (!QStringList {"list", "set", "get", "act"}.contains(command))
        return usageError(QStringLiteral("unknown conf command '%1'").arg(command), streams);
    if (words.size() > expected || (words.size() < expected && command != QLatin1String("list")))
        return usageError(QStringLiteral("wrong number of arguments for '%1'").arg(command),
                          streams);
    const QString set = options.value(QStringLiteral("-s"));
    if (command == QLatin1String("act") && set.isEmpty())
        return usageError(QStringLiteral("act needs -s SET"), streams);

    const ComponentProxy rtc = component(path(options.positionals.first()));
    if (command == QLatin1String("list"))
        return list(rtc, options, streams);
    const QString target = set.isEmpty() ? rtc.activeConfigurationSet() : set;
    if (target.isEmpty())
        throw Error(Error::Kind::NotFound,
                           QStringLiteral("%1: no configuration set is active (the sets were changed "
                                          "and none activated since); name one with -s SET")
                               .arg(rtc.path()));
    if (command == QLatin1String("get"))
        streams.out << rtc.parameter(target, words.at(1)) << '\n';
    else if (command == QLatin1String("set"))
        rtc.setParameter(target, words.at(1), words.at(2));
    else
        rtc.activateConfigurationSet(target);
    return ExitOk;
}

} // namespace Cli
