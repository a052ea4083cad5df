// SPDX-License-Identifier: MIT
#include "commandline.h"
#include "manpage.h"
#include "buildcommand.h"
#include "gencommand.h"
#include "idlcommand.h"
#include "localcommand.h"
#include "tlscommand.h"
#include "packagecommand.h"
#include "plancommand.h"
#include "profilecommand.h"
#include "repocommand.h"
#include "rtcatcommand.h"
#include "rtconfcommand.h"
#include "rtconnectcommand.h"
#include "rtcryocommand.h"
#include "rtcwdcommand.h"
#include "rtdatacommand.h"
#include "rtfindcommand.h"
#include "rtlscommand.h"
#include "rtmgrcommand.h"
#include "nodecommand.h"
#include "rtstatecommand.h"
#include "rtsystemcommand.h"

namespace Cli {

CommandLine::CommandLine() = default;
CommandLine::~CommandLine() = default;

void CommandLine::addCommand(std::unique_ptr<Command> command)
{
    m_commands.push_back(std::move(command));
}

Command *CommandLine::find(const QString &name) const
{
    for (const auto &command : m_commands) {
        if (command->name() == name)
            return command.get();
    }
    return nullptr;
}

QString CommandLine::help() const
{
    QString text = QStringLiteral(
        "Usage: rtctl [--help] [--version] COMMAND [ARGUMENTS...]\n\n"
        "RT Studio on the command line: profiles, code generation and live systems.\n\n"
        "Commands:\n");
    for (const auto &command : m_commands)
        text += QStringLiteral("  %1  %2\n").arg(command->name(), -10).arg(command->summary());
    text += QStringLiteral("\n'rtctl COMMAND --help' describes a command.\n"
                           "Exit codes: 0 success, 1 problems found or the action failed, 2 usage "
                           "error.\n");
    return text;
}

int CommandLine::run(const QStringList &arguments, Streams streams)
{
    if (arguments.isEmpty()) {
        streams.err << help();
        return ExitUsage;
    }
    const QString first = arguments.first();
    if (first == QLatin1String("--help") || first == QLatin1String("-h")
        || first == QLatin1String("help")) {
        streams.out << help();
        return ExitOk;
    }
    // Not in --help: the build writes rtctl(1) with it.
    if (first == QLatin1String("--man")) {
        streams.out << ManPage::roff(*this, QStringLiteral(RTSTUDIO_VERSION));
        return ExitOk;
    }
    if (first == QLatin1String("--version")) {
        streams.out << "rtctl " << RTSTUDIO_VERSION << '\n';
        return ExitOk;
    }
    Command *command = find(first);
    if (!command) {
        streams.err << "rtctl: unknown command '" << first << "'\n\n" << help();
        return ExitUsage;
    }
    const QStringList rest = arguments.mid(1);
    if (rest.contains(QLatin1String("--help")) || rest.contains(QLatin1String("-h"))) {
        streams.out << command->usage();
        return ExitOk;
    }
    return command->run(rest, streams);
}

std::unique_ptr<CommandLine> createCommandLine()
{
    auto commandLine = std::make_unique<CommandLine>();
    commandLine->addCommand(std::make_unique<ProfileCommand>());
    commandLine->addCommand(std::make_unique<GenCommand>());
    commandLine->addCommand(std::make_unique<IdlCommand>());
    commandLine->addCommand(std::make_unique<BuildCommand>());
    commandLine->addCommand(std::make_unique<PackageCommand>());
    commandLine->addCommand(std::make_unique<RepoCommand>());
    commandLine->addCommand(std::make_unique<RtLsCommand>());
    commandLine->addCommand(std::make_unique<RtCatCommand>());
    commandLine->addCommand(std::make_unique<RtFindCommand>());
    commandLine->addCommand(std::make_unique<RtCwdCommand>(false));
    commandLine->addCommand(std::make_unique<RtCwdCommand>(true));
    using State = RtStateCommand::Action;
    for (State action : {State::Activate, State::Deactivate, State::Reset, State::Exit})
        commandLine->addCommand(std::make_unique<RtStateCommand>(action));
    commandLine->addCommand(std::make_unique<RtConnectCommand>(true));
    commandLine->addCommand(std::make_unique<RtConnectCommand>(false));
    commandLine->addCommand(std::make_unique<RtDataCommand>(RtDataCommand::Mode::Print));
    commandLine->addCommand(std::make_unique<RtDataCommand>(RtDataCommand::Mode::Inject));
    commandLine->addCommand(std::make_unique<RtDataCommand>(RtDataCommand::Mode::Log));
    commandLine->addCommand(std::make_unique<RtConfCommand>());
    commandLine->addCommand(std::make_unique<RtMgrCommand>());
    commandLine->addCommand(std::make_unique<NodeCommand>());
    using System = RtSystemCommand::Action;
    for (System action :
         {System::Resurrect, System::Teardown, System::Start, System::Stop, System::Diff,
          System::Deploy, System::Undeploy})
        commandLine->addCommand(std::make_unique<RtSystemCommand>(action));
    commandLine->addCommand(std::make_unique<RtCryoCommand>());
    commandLine->addCommand(std::make_unique<LocalCommand>());
    commandLine->addCommand(std::make_unique<TlsCommand>());
    commandLine->addCommand(std::make_unique<PlanCommand>());
    return commandLine;
}

} // namespace Cli
