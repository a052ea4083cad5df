// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

#include <memory>
#include <vector>

namespace Cli {

/// The rtctl front end: global options and dispatch to the registered commands.
class CommandLine
{
public:
    CommandLine();
    ~CommandLine();

    /// Adds a command; later features plug in here.
    void addCommand(std::unique_ptr<Command> command);
    /// Runs `rtctl <arguments...>` (without the program name) and returns the exit code.
    int run(const QStringList &arguments, Streams streams);

    QString help() const;
    /// The commands in the order `rtctl --help` lists them.
    const std::vector<std::unique_ptr<Command>> &commands() const { return m_commands; }

private:
    Command *find(const QString &name) const;

    std::vector<std::unique_ptr<Command>> m_commands;
};

/// A front end with every command rtctl has.
std::unique_ptr<CommandLine> createCommandLine();

} // namespace Cli
