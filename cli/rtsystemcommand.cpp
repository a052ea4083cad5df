// SPDX-License-Identifier: MIT
#include "rtsystemcommand.h"

#include "deployer.h"
#include "drift.h"
#include "healer.h"
#include "interruptscope.h"
#include "profileio.h"
#include "restorer.h"
#include "sequencerunner.h"

#include <QDeadlineTimer>
#include <QThread>

#include <unistd.h>

namespace Cli {

using Deploy::DeployReport;
using Deploy::DeployStep;
using Deploy::StepStatus;

namespace {

// Streams each finished step as it happens, so a long start shows its progress. On a terminal the
// step under way stands on a line of its own, overwritten by the next.
Deploy::DeployControl printingControl(Streams streams)
{
    Deploy::DeployControl control;
    const bool terminal = ::isatty(STDOUT_FILENO);
    control.progress = [streams, terminal](const DeployStep &step) {
        if (terminal)
            streams.out << "\r\033[K";
        if (step.status == StepStatus::Running) {
            if (terminal)
                streams.out << "… " << step.action << ' ' << step.subject;
        } else {
            streams.out << step.toString() << '\n';
        }
        streams.out.flush();
    };
    return control;
}

// Every finished step, rolled-back ones included, was printed as it happened (printingControl).
int finish(const DeployReport &report, const QString &command, Streams streams)
{
    if (report.ok)
        return ExitOk;
    streams.err << "rtctl " << command << ": " << report.error << '\n';
    streams.err.flush();
    return ExitProblems;
}

std::optional<Profile::RtsProfile> loadSystem(const QString &file, const QString &command,
                                              Streams streams)
{
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(file, &diagnostics);
    for (const auto &diagnostic : diagnostics) {
        if (diagnostic.severity == Profile::Diagnostic::Severity::Error)
            streams.err << diagnostic.toString() << '\n';
    }
    if (loaded && loaded->rts)
        return loaded->rts;
    if (loaded)
        streams.err << "rtctl " << command << ": " << file << ": not an RTS profile\n";
    streams.err.flush();
    return std::nullopt;
}

} // namespace

QString RtSystemCommand::name() const
{
    switch (m_action) {
    case Action::Resurrect:
        return QStringLiteral("resurrect");
    case Action::Teardown:
        return QStringLiteral("teardown");
    case Action::Start:
        return QStringLiteral("start");
    case Action::Stop:
        return QStringLiteral("stop");
    case Action::Deploy:
        return QStringLiteral("deploy");
    case Action::Undeploy:
        return QStringLiteral("undeploy");
    case Action::Diff:
        break;
    }
    return QStringLiteral("diff");
}

QString RtSystemCommand::summary() const
{
    switch (m_action) {
    case Action::Resurrect:
        return QStringLiteral("restore a saved system onto the live components");
    case Action::Teardown:
        return QStringLiteral("disconnect the connectors of a saved system");
    case Action::Start:
        return QStringLiteral("activate a system in its declared order");
    case Action::Stop:
        return QStringLiteral("deactivate a system in its declared order");
    case Action::Deploy:
        return QStringLiteral("install what a system needs on its nodes, restore and start it");
    case Action::Undeploy:
        return QStringLiteral("stop a deployed system, remove its components and packages");
    case Action::Diff:
        break;
    }
    return QStringLiteral("list how the live system differs from a saved one");
}

QString RtSystemCommand::usage() const
{
    QString extra;
    if (m_action == Action::Resurrect)
        extra = QStringLiteral("[--create] [--dry-run] ");
    else if (m_action == Action::Deploy)
        extra = QStringLiteral("[--repo URL] [--ca FILE] [--plan --nodes M1,M2,…] [--dry-run] [--watch [--interval MS]] ");
    else if (m_action == Action::Undeploy)
        extra = QStringLiteral("[--uninstall] ");
    QString text = QStringLiteral("Usage: rtctl %1 [--timeout MS] [-s SERVER]... [-m MANAGER] "
                                  "[--host-manager HOST=ADDRESS]... %2FILE\n\n%3.\n")
                       .arg(name(), extra, summary().left(1).toUpper() + summary().mid(1));
    text += QStringLiteral(
        "Components are found at their saved pathUri when it is a live path, else by instance\n"
        "name under the name servers (-s, else RTCTREE_NAMESERVERS, else localhost).\n"
        "-s SERVER      name server host[:port] to search (repeatable)\n"
        "-m MANAGER     manager path or corbaloc::host[:port] that creates missing components\n"
        "               (default: the manager.mgr beside each component's saved path)\n"
        "--host-manager HOST=ADDRESS  components saved under HOST.host_cxt are created with\n"
        "               manager_address=ADDRESS\n");
    if (m_action == Action::Resurrect)
        text += QStringLiteral(
            "--create       create missing components through the manager\n"
            "--dry-run      print the plan and change nothing\n"
            "A failed required step undoes what this run created and connected.\n");
    if (m_action == Action::Deploy)
        text += QStringLiteral(
            "--repo URL     component repository (http, https, file URL or folder, #SUITE\n"
            "               picks a suite) that types a node cannot load are installed from\n"
            "--ca FILE      certificate authorities trusted for an https repository\n"
            "--dry-run      print what would be installed where and the restore plan\n"
            "--watch        then keep the system as planned until Ctrl+C: when a node's manager\n"
            "               stops answering, its components are planned anew on the nodes left\n"
            "               (installing as needed), created, configured, connected and started\n"
            "--plan         first place the components not pinned (deploy.pin) on the --nodes\n"
            "               with the planner, as rtctl plan does, and pin them there\n"
            "--nodes LIST   the nodes to plan on and move to (manager paths or corbalocs)\n"
            "--interval MS  how often the nodes are checked (default 200)\n"
            "Components pinned with the property deploy.pin are created by that manager.\n"
            "The nodes install side by side, then the system is restored and started; a\n"
            "failed required step undoes everything this run did, installs included.\n");
    if (m_action == Action::Undeploy)
        text += QStringLiteral(
            "--uninstall    also remove the packages providing the system's component types\n"
            "               from the nodes that ran them (kept while other components use them)\n");
    if (m_action == Action::Start || m_action == Action::Stop)
        text += QStringLiteral(
            "Follows the file's Activation/Deactivation (and StartUp/ShutDown) blocks as rtshell\n"
            "does: plain targets by sequence and unnamed components first; every WaitTime and\n"
            "Preceding waits side by side from the start of the plan (SYNC: until the preceding\n"
            "components reach the state, a timeout cancels the plan; ASYNC/NO_SYNC: until their\n"
            "action was sent).\n");
    return text
        + QStringLiteral("Exit codes: 0 done%1, 1 a required step failed%2, 2 usage error.\n")
              .arg(m_action == Action::Diff ? QStringLiteral(" (no differences)") : QString(),
                   m_action == Action::Diff ? QStringLiteral(" or differences found") : QString());
}

QStringList RtSystemCommand::flagNames() const
{
    if (m_action == Action::Resurrect)
        return {QStringLiteral("--create"), QStringLiteral("--dry-run")};
    if (m_action == Action::Deploy)
        return {QStringLiteral("--dry-run"), QStringLiteral("--watch"), QStringLiteral("--plan")};
    if (m_action == Action::Undeploy)
        return {QStringLiteral("--uninstall")};
    return {};
}

QStringList RtSystemCommand::optionNames() const
{
    QStringList names {QStringLiteral("-s"), QStringLiteral("-m"), QStringLiteral("--host-manager")};
    if (m_action == Action::Deploy)
        names << QStringLiteral("--repo") << QStringLiteral("--ca") << QStringLiteral("--nodes")
              << QStringLiteral("--interval");
    return names;
}

bool RtSystemCommand::targetOptions(const RtOptions &options, Deploy::TargetOptions *target,
                                    Streams streams) const
{
    target->nameServers = options.values.value(QStringLiteral("-s"));
    target->manager = options.value(QStringLiteral("-m"));
    target->create = options.has(QStringLiteral("--create"));
    for (const QString &pair : options.values.value(QStringLiteral("--host-manager"))) {
        const int eq = pair.indexOf(QLatin1Char('='));
        if (eq <= 0) {
            usageError(QStringLiteral("--host-manager needs HOST=ADDRESS"), streams);
            return false;
        }
        target->hostManagers.insert(pair.left(eq), pair.mid(eq + 1));
    }
    return true;
}

int RtSystemCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.size() != 1)
        return usageError(QStringLiteral("expected one FILE"), streams);
    Deploy::TargetOptions target;
    if (!targetOptions(options, &target, streams))
        return ExitUsage;
    const auto profile = loadSystem(options.positionals.first(), name(), streams);
    if (!profile)
        return ExitProblems;
    const Deploy::DeployControl control = printingControl(streams);
    if (m_action == Action::Deploy)
        return deploy(*profile, target, options, streams);
    const Deploy::RestorePlan plan = Deploy::planRestore(*profile, target);
    switch (m_action) {
    case Action::Resurrect:
        if (options.has(QStringLiteral("--dry-run"))) {
            streams.out << plan.toText();
            return plan.missingRequired().isEmpty() ? ExitOk : ExitProblems;
        }
        return finish(Deploy::restoreSystem(*profile, plan, target, control), name(), streams);
    case Action::Teardown:
        return finish(Deploy::teardownSystem(plan, control), name(), streams);
    case Action::Start:
        return finish(Deploy::startSystem(*profile, plan, control), name(), streams);
    case Action::Stop:
        return finish(Deploy::stopSystem(*profile, plan, control), name(), streams);
    case Action::Undeploy:
        return finish(Deploy::undeploySystem(*profile, plan, target,
                                             options.has(QStringLiteral("--uninstall")), control),
                      name(), streams);
    case Action::Deploy:
    case Action::Diff:
        break;
    }
    const QList<Deploy::DriftItem> drift = Deploy::diffSystem(*profile, plan);
    for (const Deploy::DriftItem &item : drift)
        streams.out << item.toString() << '\n';
    streams.out.flush();
    return drift.isEmpty() ? ExitOk : ExitProblems;
}

int RtSystemCommand::deploy(Profile::RtsProfile profile, const Deploy::TargetOptions &target,
                            const RtOptions &options, Streams streams) const
{
    Deploy::DeployOptions deploy;
    deploy.target = target;
    deploy.repository = options.value(QStringLiteral("--repo"));
    deploy.caCertificates = options.value(QStringLiteral("--ca"));
    if (options.has(QStringLiteral("--plan"))) {
        QStringList nodes;
        for (const QString &list : options.values.value(QStringLiteral("--nodes")))
            nodes << list.split(QLatin1Char(','), Qt::SkipEmptyParts);
        if (nodes.isEmpty())
            return usageError(QStringLiteral("--plan needs the nodes: --nodes M1,M2,…"), streams);
        QString why;
        const QHash<QString, QString> placement = Deploy::planPlacement(profile, nodes, deploy, {}, {}, &why);
        if (placement.isEmpty()) {
            report(why, streams);
            return ExitProblems;
        }
        Deploy::pinPlacement(&profile, placement);
        for (const Profile::RtsComponent &component : std::as_const(profile.components))
            streams.out << "plan " << component.instanceName << " -> " << placement.value(component.instanceName)
                        << '\n';
        streams.out.flush();
    }
    const Deploy::DeployPlan plan = Deploy::planDeploy(profile, deploy);
    if (options.has(QStringLiteral("--dry-run"))) {
        streams.out << plan.toText();
        streams.out.flush();
        return plan.problems.isEmpty() ? ExitOk : ExitProblems;
    }
    const int deployed = finish(Deploy::deploySystem(profile, plan, deploy, printingControl(streams)),
                                name(), streams);
    if (deployed != ExitOk || !options.has(QStringLiteral("--watch")))
        return deployed;
    return watch(profile, deploy, options, streams);
}

int RtSystemCommand::watch(const Profile::RtsProfile &profile, const Deploy::DeployOptions &deploy,
                           const RtOptions &options, Streams streams) const
{
    bool ok = true;
    const int interval = options.values.contains(QStringLiteral("--interval"))
        ? options.value(QStringLiteral("--interval")).toInt(&ok)
        : 200;
    if (!ok || interval <= 0)
        return usageError(QStringLiteral("--interval needs a positive number of milliseconds"), streams);
    Deploy::WatchOptions watch;
    watch.deploy = deploy;
    for (const QString &list : options.values.value(QStringLiteral("--nodes")))
        watch.nodes << list.split(QLatin1Char(','), Qt::SkipEmptyParts);
    const InterruptScope interrupts;
    Deploy::SystemHealer healer(profile, watch);
    healer.start();
    streams.out << "watching " << healer.nodes().join(QLatin1Char(' ')) << '\n';
    streams.out.flush();
    Deploy::DeployControl control = printingControl(streams);
    control.cancel = &InterruptScope::interrupted();
    while (!InterruptScope::interrupted()) {
        const Deploy::DeployReport report = healer.check(control);
        if (!report.ok)
            streams.err << "rtctl " << name() << ": heal failed: " << report.error << '\n';
        streams.err.flush();
        const QDeadlineTimer next(interval);
        while (!next.hasExpired() && !InterruptScope::interrupted())
            QThread::msleep(10);
    }
    streams.out << "stopped watching\n";
    streams.out.flush();
    return ExitOk;
}

} // namespace Cli
