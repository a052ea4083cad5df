// SPDX-License-Identifier: MIT
#include "rtcryocommand.h"

#include "cryo.h"
#include "profileio.h"

namespace Cli {

QString RtCryoCommand::summary() const
{
    return QStringLiteral("save the live system as an RTS profile");
}

QString RtCryoCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl cryo [--timeout MS] [-n NAME] [-v VERSION] [-e VENDOR] [-a ABSTRACT]\n"
        "                  [-o FILE] [PATH...]\n\n"
        "Saves the components under each PATH (name servers, contexts or components; default\n"
        "the servers of RTCTREE_NAMESERVERS, else localhost) with all configuration sets, owned\n"
        "execution contexts, ports and the connectors between them (IOR keys removed) as an RTS\n"
        "profile: XML, or YAML when FILE ends in .yaml; stdout without -o.\n"
        "Exit codes: 0 saved, 1 some component or path could not be read, 2 usage error.\n");
}

QStringList RtCryoCommand::optionNames() const
{
    return {QStringLiteral("-n"), QStringLiteral("-v"), QStringLiteral("-e"), QStringLiteral("-a"),
            QStringLiteral("-o")};
}

int RtCryoCommand::execute(const RtOptions &options, Streams streams)
{
    Deploy::CryoOptions cryo;
    cryo.name = options.value(QStringLiteral("-n"), cryo.name);
    cryo.version = options.value(QStringLiteral("-v"), cryo.version);
    cryo.vendor = options.value(QStringLiteral("-e"), cryo.vendor);
    cryo.abstract = options.value(QStringLiteral("-a"));
    for (const QString &text : options.positionals)
        cryo.paths.append(path(text).toString());
    if (cryo.paths.isEmpty()) {
        QStringList servers = Corba::NamingBrowser::serversFromEnvironment();
        if (servers.isEmpty())
            servers.append(QStringLiteral("localhost"));
        for (const QString &server : servers)
            cryo.paths.append(QLatin1Char('/') + server);
    }
    Deploy::DeployReport cryoReport;
    const Profile::RtsProfile profile = Deploy::cryoSystem(cryo, &cryoReport);
    for (const Deploy::DeployStep &step : cryoReport.stepsWith(Deploy::StepStatus::Failed))
        report(step.toString(), streams);
    const QString file = options.value(QStringLiteral("-o"));
    if (file.isEmpty()) {
        streams.out << QString::fromUtf8(
            Profile::serializeRtsProfile(profile, Profile::FileFormat::Xml));
        streams.out.flush();
    } else {
        Profile::Diagnostics diagnostics;
        if (!Profile::saveRtsProfileFile(profile, file, &diagnostics)) {
            for (const auto &diagnostic : diagnostics)
                streams.err << diagnostic.toString() << '\n';
            streams.err.flush();
            return ExitProblems;
        }
    }
    return cryoReport.stepsWith(Deploy::StepStatus::Failed).isEmpty() ? ExitOk : ExitProblems;
}

} // namespace Cli
