// SPDX-License-Identifier: MIT
#include "localcommand.h"

#include "installation.h"
#include "localruntime.h"

#include <QJsonDocument>
#include <QJsonObject>

namespace Cli {

namespace {

QJsonObject processJson(const Deploy::LocalProcess &process)
{
    return {{QStringLiteral("pid"), process.pid},
            {QStringLiteral("port"), process.port},
            {QStringLiteral("running"), process.running}};
}

void print(const Deploy::LocalRuntimeState &state, bool json, QTextStream &out)
{
    if (json) {
        out << QJsonDocument(QJsonObject {{QStringLiteral("running"), state.running()},
                                          {QStringLiteral("nameServer"), processJson(state.nameServer)},
                                          {QStringLiteral("manager"), processJson(state.manager)},
                                          {QStringLiteral("tls"), state.tls},
                                          {QStringLiteral("folder"), state.folder}})
                   .toJson(QJsonDocument::Compact)
            << '\n';
        return;
    }
    if (!state.nameServer.running && !state.manager.running) {
        out << "local runtime: not running\n";
        return;
    }
    const auto line = [&out](const char *what, const Deploy::LocalProcess &process, const QString &address) {
        out << what << ' ' << (process.running ? address : QStringLiteral("not running"));
        if (process.running)
            out << " (pid " << process.pid << ')';
        out << '\n';
    };
    line("name server", state.nameServer, state.nameServerAddress());
    line("manager    ", state.manager, state.managerAddress());
    if (state.tls)
        out << "TLS         on: certificates in " << Deploy::LocalRuntime(state.folder).tls().certificateAuthorityFile
            << " and beside it; rtctl and RT Studio use them\n";
}

} // namespace

QString LocalCommand::summary() const
{
    return QStringLiteral("start, stop or show the local name server and manager");
}

QString LocalCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl local start [--tls]|stop|status [--json]\n\n"
        "The local runtime: omniNames on port 2809 (or the next free one) and an rtmanager master\n"
        "on 2810 (or the next free one) registered in it, both running on after rtctl exits, their\n"
        "data and logs in $XDG_RUNTIME_DIR/rtstudio. start reuses a running one; RT Studio's\n"
        "Online menu finds the same. status exits 0 when both run, 1 otherwise.\n\n"
        "--tls  both speak TLS only and require a certificate of the runtime's own certificate\n"
        "       authority, made with openssl on first use (tls/ in the runtime's folder) with one for\n"
        "       the servers and one for you, which rtctl and RT Studio then present by themselves.\n");
}

int LocalCommand::run(const QStringList &arguments, Streams streams)
{
    QStringList words = arguments;
    const bool json = words.removeAll(QStringLiteral("--json")) > 0;
    const bool tls = words.removeAll(QStringLiteral("--tls")) > 0;
    if (words.size() != 1)
        return usageError(QStringLiteral("local needs one of start, stop, status"), streams);
    Deploy::LocalRuntime runtime;
    const QString action = words.first();
    if (action == QLatin1String("status")) {
        const Deploy::LocalRuntimeState state = runtime.status();
        print(state, json, streams.out);
        return state.running() ? ExitOk : ExitProblems;
    }
    if (action == QLatin1String("start")) {
        QString error;
        const Deploy::LocalRuntimeState state = runtime.start(Codegen::Installation::managerProgram(), tls, &error);
        if (!error.isEmpty()) {
            streams.err << "rtctl local: " << error << '\n';
            return ExitProblems;
        }
        print(state, json, streams.out);
        return ExitOk;
    }
    if (action == QLatin1String("stop")) {
        QString error;
        if (!runtime.stop(&error)) {
            streams.err << "rtctl local: " << error << '\n';
            return ExitProblems;
        }
        return ExitOk;
    }
    return usageError(QStringLiteral("unknown action '%1'").arg(action), streams);
}

} // namespace Cli
