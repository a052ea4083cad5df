// SPDX-License-Identifier: MIT
#include "rtstatecommand.h"

#include "corbaerror.h"

namespace Cli {

QString RtStateCommand::name() const
{
    switch (m_action) {
    case Action::Activate:
        return QStringLiteral("act");
    case Action::Deactivate:
        return QStringLiteral("deact");
    case Action::Reset:
        return QStringLiteral("reset");
    case Action::Exit:
        break;
    }
    return QStringLiteral("exit");
}

QString RtStateCommand::summary() const
{
    switch (m_action) {
    case Action::Activate:
        return QStringLiteral("activate components in an execution context");
    case Action::Deactivate:
        return QStringLiteral("deactivate components in an execution context");
    case Action::Reset:
        return QStringLiteral("reset components in the error state");
    case Action::Exit:
        break;
    }
    return QStringLiteral("make components exit");
}

QString RtStateCommand::usage() const
{
    const QString ec = m_action == Action::Exit ? QString() : QStringLiteral("[-e EC_INDEX] ");
    return QStringLiteral("Usage: rtctl %1 [--timeout MS] %2PATH...\n\n"
                          "%3 (rtshell's rt%1). PATH is a component in the RTC tree, e.g.\n"
                          "/localhost/myhost.host_cxt/ConsoleIn0.rtc, or relative to RTCSH_CWD.\n")
               .arg(name(), ec, summary().left(1).toUpper() + summary().mid(1))
        + (m_action == Action::Exit
               ? QString()
               : QStringLiteral("-e EC_INDEX  execution context: owned ones first, then "
                                "participating (default 0)\n"))
        + QStringLiteral("Exit codes: 0 done, 1 a component failed or refused, 2 usage error.\n");
}

QStringList RtStateCommand::optionNames() const
{
    return m_action == Action::Exit ? QStringList() : QStringList {QStringLiteral("-e")};
}

int RtStateCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.isEmpty())
        return usageError(QStringLiteral("missing PATH"), streams);
    bool ok = false;
    const int ec = options.value(QStringLiteral("-e"), QStringLiteral("0")).toInt(&ok);
    if (!ok || ec < 0)
        return usageError(QStringLiteral("-e needs an execution context index"), streams);
    return forEachPath(
        options.positionals, streams,
        [&](const QString &text) {
            const Corba::ComponentProxy rtc = component(path(text));
            switch (m_action) {
            case Action::Activate:
                rtc.activate(ec);
                break;
            case Action::Deactivate:
                rtc.deactivate(ec);
                break;
            case Action::Reset:
                rtc.reset(ec);
                break;
            case Action::Exit:
                rtc.exit();
                break;
            }
        },
        name());
}

} // namespace Cli
