// SPDX-License-Identifier: MIT
// The deployment planner on generated systems: 100 and 1,000 components on 5 and 20 nodes, with
// device and architecture requirements, shared processes, installs from a repository and a chain
// of connectors at mixed rates. Prints the solver's time per size; goal: 1,000 on 20 within 1 s.
#include "planner.h"

#include <QCoreApplication>
#include <QTextStream>

#include <tuple>

using namespace Planner;

namespace {

constexpr int Types = 20;

NodeFacts node(int index)
{
    NodeFacts facts;
    facts.name = QStringLiteral("corbaloc::node%1:2810").arg(index);
    facts.os = QStringLiteral("Linux");
    facts.architecture = index % 4 == 3 ? QStringLiteral("aarch64") : QStringLiteral("x86_64");
    facts.cpuCount = 64;
    facts.loadAverage = 0.5 * (index % 3);
    facts.sdkAbi = QStringLiteral("librtsdk.so.0");
    facts.languages = QStringList {QStringLiteral("C++")};
    QStringList loadable;
    for (int t = index % 2; t < Types; t += 2)
        loadable << QStringLiteral("Type%1").arg(t);
    facts.loadableTypes = loadable;
    facts.userFacts.insert(QStringLiteral("devices"),
                           index % 5 == 0 ? QStringLiteral("lidar0,camera0") : QString());
    return facts;
}

ComponentRequirements component(int index)
{
    ComponentRequirements c;
    c.instanceName = QStringLiteral("Comp%1").arg(index);
    c.typeName = QStringLiteral("Type%1").arg(index % Types);
    c.language = QStringLiteral("C++");
    c.cpuShare = 0.05;
    if (index % 50 == 0)
        c.devices << QStringLiteral("lidar0");
    if (index % 7 == 0)
        c.architectures << QStringLiteral("x86_64");
    if (index % 10 < 3)
        c.process = QStringLiteral("loop%1").arg(index / 10);
    return c;
}

PlanProblem problem(int components, int nodes)
{
    PlanProblem p;
    for (int n = 0; n < nodes; ++n)
        p.nodes << node(n);
    for (int c = 0; c < components; ++c)
        p.components << component(c);
    for (int c = 1; c < components; ++c)
        p.links.append({p.components.at(c - 1).instanceName, p.components.at(c).instanceName,
                        c % 4 == 0 ? 1000.0 : 10.0});
    for (int t = 0; t < Types; ++t) {
        p.packages.append({QStringLiteral("rtc-type%1").arg(t),
                           QStringLiteral("1.0.0"),
                           QStringLiteral("amd64"),
                           QStringLiteral("librtsdk.so.0"),
                           {QStringLiteral("Type%1").arg(t)}});
        p.packages.append({QStringLiteral("rtc-type%1").arg(t),
                           QStringLiteral("1.0.0"),
                           QStringLiteral("arm64"),
                           QStringLiteral("librtsdk.so.0"),
                           {QStringLiteral("Type%1").arg(t)}});
    }
    return p;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    out << "| components | nodes | budget ms | solver ms | optimal | balanced | installs | "
           "cross-host Hz | goal ms |\n"
        << "|-----------:|------:|----------:|----------:|:-------:|:--------:|---------:|---------"
           "-----:|--------:|\n";
    // The default budget (10 s), then the largest size within the goal's second: the best plan the
    // solver found by then.
    const QList<std::tuple<int, int, int>> runs {
        {100, 5, 10000}, {100, 20, 10000}, {1000, 5, 10000}, {1000, 20, 10000}, {1000, 20, 1000}};
    for (const auto &[components, nodes, budget] : runs) {
        const Plan plan = DeploymentPlanner({budget}).plan(problem(components, nodes));
        out << QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 | %7 | %8 | %9 |\n")
                   .arg(components, 10)
                   .arg(nodes, 5)
                   .arg(budget, 9)
                   .arg(plan.solveMs, 9, 'f', 1)
                   .arg(plan.feasible ? (plan.optimal ? "yes" : "no") : "NO PLAN", 7)
                   .arg(plan.balanced ? "yes" : "no", 8)
                   .arg(plan.installs.size(), 8)
                   .arg(plan.crossHostRate, 13, 'f', 0)
                   .arg(components == 1000 && nodes == 20 ? QStringLiteral("1000")
                                                          : QStringLiteral("-"),
                        7);
        out.flush();
    }
    return 0;
}
