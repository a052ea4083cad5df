// SPDX-License-Identifier: MIT
#include "plancommand.h"

#include "nodefactsfile.h"
#include "nodefactsreader.h"
#include "planner.h"
#include "planrepository.h"
#include "profileio.h"
#include "rtcprofile.h"
#include "rtsprofile.h"

#include <QDirIterator>
#include <QJsonDocument>

namespace Cli {

namespace {

using TypeProfiles = QHash<QString, Profile::RtcProfile>;

void readProfileFolder(const QString &folder, TypeProfiles *profiles, QStringList *warnings)
{
    QDirIterator it(folder,
                    {QStringLiteral("*.xml"), QStringLiteral("*.yaml"), QStringLiteral("*.yml")},
                    QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        Profile::Diagnostics diagnostics;
        const auto loaded = Profile::loadProfileFile(file, &diagnostics);
        if (loaded && loaded->rtc)
            Planner::addTypeProfile(*loaded->rtc, profiles);
        else if (!loaded)
            *warnings
                << QStringLiteral("%1: not read (%2)").arg(file, diagnostics.value(0).toString());
    }
}

/// The packages of the repository folder @p root and the RTC profiles they ship.
bool readRepository(const QString &root, Planner::PlanProblem *problem, TypeProfiles *profiles,
                    QStringList *warnings, QString *error)
{
    const auto repository = Deploy::readPlanRepository(root, warnings, error);
    if (!repository)
        return false;
    problem->packages << repository->packages;
    profiles->insert(repository->typeProfiles);
    return true;
}

std::optional<Profile::RtsProfile> loadSystem(const QString &file, QString *error)
{
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(file, &diagnostics);
    if (loaded && loaded->rts)
        return loaded->rts;
    *error = loaded ? QStringLiteral("%1: not an RTS profile").arg(file)
                    : (diagnostics.isEmpty() ? QStringLiteral("%1: not read").arg(file)
                                             : diagnostics.first().toString());
    return std::nullopt;
}

QString placementProcess(const Planner::Placement &p)
{
    return p.sharedProcess ? p.process + QStringLiteral(" (shared)") : QStringLiteral("own");
}

void printPlacements(const Planner::Plan &plan, QTextStream &out)
{
    int nameWidth = 9;
    int nodeWidth = 4;
    for (const Planner::Placement &p : plan.placements) {
        nameWidth = qMax(nameWidth, int(p.instanceName.size()));
        nodeWidth = qMax(nodeWidth, int(p.node.size()));
    }
    out << QStringLiteral("%1  %2  %3  %4\n")
               .arg(QStringLiteral("COMPONENT"), -nameWidth)
               .arg(QStringLiteral("NODE"), -nodeWidth)
               .arg(QStringLiteral("PROCESS"), -16)
               .arg(QStringLiteral("INSTALL"));
    for (const Planner::Placement &p : plan.placements) {
        out << QStringLiteral("%1  %2  %3  %4")
                   .arg(p.instanceName, -nameWidth)
                   .arg(p.node, -nodeWidth)
                   .arg(placementProcess(p), -16)
                   .arg(p.installPackage.isEmpty() ? QStringLiteral("-") : p.installPackage)
            << '\n';
    }
}

void printSummary(const Planner::Plan &plan, QTextStream &out)
{
    for (const Planner::Install &i : plan.installs)
        out << "install " << i.package << ' ' << i.version << " on " << i.node << '\n';
    out << "connectors between hosts: " << plan.crossHostRate << " Hz\n";
    out << "CPU load per CPU:";
    for (auto it = plan.cpuLoad.constBegin(); it != plan.cpuLoad.constEnd(); ++it)
        out << ' ' << it.key() << '=' << QString::number(it.value(), 'f', 2);
    out << '\n'
        << "solved in " << QString::number(plan.solveMs, 'f', 1) << " ms"
        << (plan.optimal ? "" : " (time limit reached: not proven best)") << '\n';
}

/// "COMPONENT: REQUIREMENT - no node meets it; closest NODE has FOUND", or the reason a whole
/// system has no plan (the solver's time, no nodes).
QString unmetText(const Planner::Unmet &u)
{
    if (u.closestNode.isEmpty())
        return QStringLiteral("%1 (%2)").arg(u.requirement, u.found);
    return QStringLiteral("%1: %2 - no node meets it; closest %3 has %4")
        .arg(u.instanceName.isEmpty() ? QStringLiteral("system") : u.instanceName, u.requirement,
             u.closestNode, u.found);
}

} // namespace

QString PlanCommand::summary() const
{
    return QStringLiteral("plan where each component of a system runs, from the nodes' facts");
}

QString PlanCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl plan SYSTEM (--nodes M1,M2,… | --facts FILE) [--repo DIR] [--profiles DIR]\n"
        "                  [--solver-timeout MS] [--json] [--timeout MS]\n\n"
        "Decides on which node (manager) and in which process each component of the RTS profile\n"
        "SYSTEM runs: every requirement of its RTC profile (language, OS, architecture) and of\n"
        "the deploy.* properties (devices, node facts, CPU share, shared process, pin) must hold,\n"
        "and its type must be loadable there or installable from the repository. Among such\n"
        "plans: fewest installs, then the least connector rate between hosts, then even CPU "
        "load.\n\n"
        "  --nodes M1,M2,…     managers, as rtctl mgr takes them (corbaloc::host:port, paths);\n"
        "                      their facts are read from their profiles\n"
        "  --facts FILE        node facts from a JSON or YAML file (one entry per node)\n"
        "  --repo DIR          a component repository folder (rtctl repo): its packages can be\n"
        "                      installed, and their RTC profiles give requirements\n"
        "  --profiles DIR      folder of RTC profiles (RTC.xml/.yaml) of the system's types\n"
        "  --solver-timeout MS the solver's time budget (default 10000); the best plan found\n"
        "                      by then is printed\n"
        "  --json              the plan as one JSON object\n"
        "Prints each component's node, process (own slave or a shared one) and the package to\n"
        "install; without a plan, each unmet requirement with the closest node.\n"
        "Exit codes: 0 a plan, 1 no plan or a node or file not read, 2 usage error.\n");
}

QStringList PlanCommand::optionNames() const
{
    return {QStringLiteral("--nodes"), QStringLiteral("--facts"), QStringLiteral("--repo"),
            QStringLiteral("--profiles"), QStringLiteral("--solver-timeout")};
}

bool PlanCommand::readNodes(const RtOptions &options, Planner::PlanProblem *problem,
                            QStringList *warnings, Streams streams) const
{
    for (const QString &file : options.values.value(QStringLiteral("--facts"))) {
        QString error;
        const auto nodes = Planner::readNodeFactsFile(file, &error);
        if (!nodes) {
            report(error, streams);
            return false;
        }
        problem->nodes << *nodes;
    }
    QStringList addresses;
    for (const QString &list : options.values.value(QStringLiteral("--nodes")))
        addresses << list.split(QLatin1Char(','), Qt::SkipEmptyParts);
    bool unreachable = false;
    for (const Deploy::NodeFactsReading &reading : Deploy::readNodeFacts(addresses)) {
        if (reading.error.isEmpty()) {
            problem->nodes << reading.facts;
        } else {
            report(reading.error, streams);
            unreachable = true;
        }
    }
    if (unreachable)
        *warnings << QStringLiteral("nodes that did not answer are left out of the plan");
    if (problem->nodes.isEmpty())
        report(QStringLiteral("no node to plan on"), streams);
    return !problem->nodes.isEmpty();
}

void PlanCommand::print(const Planner::Plan &plan, Streams streams) const
{
    for (const QString &warning : plan.warnings)
        streams.err << "rtctl plan: warning: " << warning << '\n';
    if (!plan.feasible) {
        streams.err << "rtctl plan: no plan:\n";
        for (const Planner::Unmet &u : plan.unmet)
            streams.err << "  " << unmetText(u) << '\n';
        streams.err.flush();
        return;
    }
    printPlacements(plan, streams.out);
    printSummary(plan, streams.out);
    streams.out.flush();
}

int PlanCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.size() != 1)
        return usageError(QStringLiteral("give one SYSTEM file"), streams);
    if (!options.values.contains(QStringLiteral("--nodes"))
        && !options.values.contains(QStringLiteral("--facts")))
        return usageError(QStringLiteral("give the nodes: --nodes M1,M2,… or --facts FILE"),
                          streams);
    Planner::PlanOptions planOptions;
    if (options.values.contains(QStringLiteral("--solver-timeout"))) {
        bool ok = false;
        planOptions.timeoutMs = options.value(QStringLiteral("--solver-timeout")).toInt(&ok);
        if (!ok || planOptions.timeoutMs <= 0)
            return usageError(
                QStringLiteral("--solver-timeout needs a positive number of milliseconds"),
                streams);
    }
    QString error;
    const auto system = loadSystem(options.positionals.first(), &error);
    if (!system) {
        report(error, streams);
        return ExitProblems;
    }
    Planner::PlanProblem problem;
    QStringList warnings;
    TypeProfiles profiles;
    for (const QString &folder : options.values.value(QStringLiteral("--profiles")))
        readProfileFolder(folder, &profiles, &warnings);
    const QString repo = options.value(QStringLiteral("--repo"));
    if (!repo.isEmpty() && !readRepository(repo, &problem, &profiles, &warnings, &error)) {
        report(error, streams);
        return ExitProblems;
    }
    if (!readNodes(options, &problem, &warnings, streams))
        return ExitProblems;
    const Planner::SystemRequirements requirements = Planner::readRequirements(*system, profiles);
    problem.components = requirements.components;
    problem.links = requirements.links;
    Planner::Plan plan = Planner::DeploymentPlanner(planOptions).plan(problem);
    plan.warnings = warnings + requirements.warnings + plan.warnings;
    if (options.has(QStringLiteral("--json"))) {
        streams.out << QJsonDocument(Planner::planToJson(plan)).toJson(QJsonDocument::Indented);
        streams.out.flush();
    } else {
        print(plan, streams);
    }
    return plan.feasible ? ExitOk : ExitProblems;
}

} // namespace Cli
