// SPDX-License-Identifier: MIT
#include "rtcwdcommand.h"

#include "corbaerror.h"

namespace Cli {

using namespace Corba;

QString RtCwdCommand::summary() const
{
    return m_change ? QStringLiteral("change the current tree directory (eval its output)")
                    : QStringLiteral("print the current tree directory");
}

QString RtCwdCommand::usage() const
{
    if (!m_change)
        return QStringLiteral("Usage: rtctl pwd\n\nPrints the current RTC tree directory, kept in "
                              "the environment variable RTCSH_CWD (/ when unset).\n");
    return QStringLiteral(
        "Usage: eval \"$(rtctl cd [--timeout MS] [PATH])\"\n\n"
        "Checks that PATH (absolute, or relative to RTCSH_CWD; / when omitted) is a name server,\n"
        "naming context or manager and prints 'export RTCSH_CWD=...' for the shell to evaluate.\n"
        "Relative paths of every rtctl tree command then start there.\n");
}

int RtCwdCommand::execute(const RtOptions &options, Streams streams)
{
    if (!m_change) {
        if (!options.positionals.isEmpty())
            return usageError(QStringLiteral("pwd takes no arguments"), streams);
        streams.out << currentDirectory() << '\n';
        return ExitOk;
    }
    if (options.positionals.size() > 1)
        return usageError(QStringLiteral("cd takes one PATH"), streams);
    const RtPath target = path(options.positionals.value(0, QStringLiteral("/")));
    if (target.isDirect() || !target.port.isEmpty())
        throw Error(Error::Kind::WrongType,
                    target.toString() + QStringLiteral(": not a directory"));
    if (!target.isRoot()) {
        const NamingNode node = NamingBrowser::node(target);
        if (node.type != NodeType::Server && node.type != NodeType::Context
            && node.type != NodeType::Manager)
            throw Error(
                Error::Kind::WrongType,
                QStringLiteral("%1: not a directory (%2)").arg(node.path, nodeTypeName(node.type)));
    }
    QString quoted = target.toString();
    quoted.replace(QLatin1Char('\''), QStringLiteral("'\\''"));
    streams.out << "export RTCSH_CWD='" << quoted << "'\n";
    return ExitOk;
}

} // namespace Cli
