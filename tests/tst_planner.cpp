// SPDX-License-Identifier: MIT
// The deployment planner (planner/): each kind of requirement and fact, shared processes, pins,
// installs from a repository, the objective on connector rates, and infeasible systems with
// their explanation.
#include "planner.h"

#include <QTest>

using namespace Planner;

namespace {

/// A Linux x86_64 node with 4 CPUs that hosts C++ and can load type T.
NodeFacts node(const QString &name)
{
    NodeFacts facts;
    facts.name = name;
    facts.os = QStringLiteral("Linux");
    facts.architecture = QStringLiteral("x86_64");
    facts.cpuCount = 4;
    facts.sdkAbi = QStringLiteral("librtsdk.so.0");
    facts.languages = QStringList {QStringLiteral("C++")};
    facts.loadableTypes = QStringList {QStringLiteral("T")};
    return facts;
}

ComponentRequirements component(const QString &name, const QString &type = QStringLiteral("T"))
{
    ComponentRequirements c;
    c.instanceName = name;
    c.typeName = type;
    return c;
}

Plan plan(const PlanProblem &problem)
{
    return DeploymentPlanner({20000}).plan(problem);
}

QString nodeOf(const Plan &plan, const QString &instance)
{
    const Placement *p = plan.placement(instance);
    return p ? p->node : QString();
}

QString describe(const Plan &plan)
{
    QStringList lines;
    for (const Unmet &u : plan.unmet)
        lines << QStringLiteral("%1: %2 (closest %3: %4)")
                     .arg(u.instanceName, u.requirement, u.closestNode, u.found);
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestPlanner : public QObject
{
    Q_OBJECT

private slots:
    void singleRequirement_data();
    void singleRequirement();
    void unknownFactsNeverMatch_data();
    void unknownFactsNeverMatch();
    void cpuShareSpreadsComponents();
    void cpuShareBeyondCapacityIsExplained();
    void sharedProcessStaysTogether();
    void sharedProcessWithoutCommonNode();
    void pinPlacesComponent();
    void pinToUnknownNode();
    void infeasibleNamesClosestNode();
    void installsWhereNotLoadable();
    void fewestInstalls();
    void installsOncePerNode_data();
    void installsOncePerNode();
    void packageForOtherArchitectureIsNoSource();
    void highRateConnectorStaysInsideHost();
    void balancesCpuLoad();
    void noNodes();
    void extremeFiguresStayValid();
    void timeLimitStillGivesValidPlan();
    void samePlanEveryTime();
};

// Each requirement, with two nodes of which only "good" meets it.
void TestPlanner::singleRequirement_data()
{
    QTest::addColumn<QString>("requirement");
    QTest::newRow("architecture") << "architecture";
    QTest::newRow("architecture alias") << "architecture alias";
    QTest::newRow("os") << "os";
    QTest::newRow("os version") << "os version";
    QTest::newRow("language") << "language";
    QTest::newRow("device") << "device";
    QTest::newRow("user fact") << "user fact";
}

void TestPlanner::singleRequirement()
{
    QFETCH(QString, requirement);
    NodeFacts bad = node(QStringLiteral("bad"));
    NodeFacts good = node(QStringLiteral("good"));
    ComponentRequirements c = component(QStringLiteral("C"));
    bool fromRepository = false;
    if (requirement == QLatin1String("architecture")) {
        good.architecture = QStringLiteral("aarch64");
        c.architectures << QStringLiteral("aarch64");
    } else if (requirement == QLatin1String("architecture alias")) {
        bad.architecture = QStringLiteral("aarch64");
        c.architectures << QStringLiteral("amd64");
    } else if (requirement == QLatin1String("os")) {
        bad.os = QStringLiteral("Windows");
        c.oses << QStringLiteral("linux");
    } else if (requirement == QLatin1String("os version")) {
        good.distribution = QStringLiteral("ubuntu 24.04");
        bad.distribution = QStringLiteral("debian 13");
        c.osVersions << QStringLiteral("Ubuntu 24");
    } else if (requirement == QLatin1String("language")) {
        good.languages = QStringList {QStringLiteral("C++"), QStringLiteral("Python3")};
        c.language = QStringLiteral("Python");
        c.typeName = QStringLiteral("PyComp");
        // Loadable on both: the language alone decides (a loadable type implies its language).
        good.loadableTypes = QStringList();
        fromRepository = true;
    } else if (requirement == QLatin1String("device")) {
        good.userFacts.insert(QStringLiteral("devices"), QStringLiteral("camera0, lidar0"));
        bad.userFacts.insert(QStringLiteral("devices"), QStringLiteral("camera0"));
        c.devices << QStringLiteral("lidar0");
    } else if (requirement == QLatin1String("user fact")) {
        good.userFacts.insert(QStringLiteral("role"), QStringLiteral("onboard"));
        bad.userFacts.insert(QStringLiteral("role"), QStringLiteral("base"));
        c.nodeFacts.insert(QStringLiteral("role"), QStringLiteral("onboard"));
    }
    PlanProblem problem;
    if (fromRepository)
        problem.packages.append({QStringLiteral("rtc-py"),
                                 QStringLiteral("1.0"),
                                 QStringLiteral("all"),
                                 QString(),
                                 {QStringLiteral("PyComp")}});
    problem.nodes << bad << good;
    problem.components << c;
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QCOMPARE(nodeOf(result, QStringLiteral("C")), QStringLiteral("good"));

    // Without the good node there is no plan, and the reason names the requirement.
    problem.nodes.removeLast();
    const Plan none = plan(problem);
    QVERIFY(!none.feasible);
    QCOMPARE(none.unmet.size(), qsizetype(1));
    QCOMPARE(none.unmet.first().instanceName, QStringLiteral("C"));
    QCOMPARE(none.unmet.first().closestNode, QStringLiteral("bad"));
}

void TestPlanner::unknownFactsNeverMatch_data()
{
    QTest::addColumn<QString>("fact");
    QTest::newRow("architecture") << "architecture";
    QTest::newRow("os") << "os";
    QTest::newRow("languages") << "languages";
    QTest::newRow("cpu count") << "cpu count";
    QTest::newRow("devices") << "devices";
}

// An OpenRTM-aist manager gives only some facts: what it does not give is no match.
void TestPlanner::unknownFactsNeverMatch()
{
    QFETCH(QString, fact);
    NodeFacts silent = node(QStringLiteral("silent"));
    silent.loadableTypes = QStringList();
    ComponentRequirements c = component(QStringLiteral("C"), QStringLiteral("U"));
    PlanProblem problem;
    problem.packages.append({QStringLiteral("rtc-u"),
                             QStringLiteral("1.0"),
                             QStringLiteral("amd64"),
                             QString(),
                             {QStringLiteral("U")}});
    if (fact == QLatin1String("architecture")) {
        silent.architecture.reset();
        c.architectures << QStringLiteral("x86_64");
    } else if (fact == QLatin1String("os")) {
        silent.os.reset();
        c.oses << QStringLiteral("Linux");
    } else if (fact == QLatin1String("languages")) {
        silent.languages.reset();
        c.language = QStringLiteral("C++");
    } else if (fact == QLatin1String("cpu count")) {
        silent.cpuCount.reset();
        c.cpuShare = 0.1;
    } else {
        c.devices << QStringLiteral("lidar0");
    }
    problem.nodes << silent;
    problem.components << c;
    const Plan result = plan(problem);
    QVERIFY2(!result.feasible, qPrintable(nodeOf(result, QStringLiteral("C"))));
    QVERIFY(!result.unmet.isEmpty());
    QVERIFY2(result.unmet.first().found == QLatin1String("unknown")
                 || result.unmet.first().found == QLatin1String("no devices listed"),
             qPrintable(describe(result)));
}

void TestPlanner::cpuShareSpreadsComponents()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    a.cpuCount = b.cpuCount = 1;
    PlanProblem problem;
    problem.nodes << a << b;
    for (const QString &name : {QStringLiteral("C1"), QStringLiteral("C2")}) {
        ComponentRequirements c = component(name);
        c.cpuShare = 0.75;
        problem.components << c;
    }
    // The connector would pull them together; the CPU share does not let it.
    problem.links.append({QStringLiteral("C1"), QStringLiteral("C2"), 1000});
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QVERIFY(nodeOf(result, QStringLiteral("C1")) != nodeOf(result, QStringLiteral("C2")));
}

void TestPlanner::cpuShareBeyondCapacityIsExplained()
{
    NodeFacts a = node(QStringLiteral("a"));
    a.cpuCount = 2;
    a.loadAverage = 1.0;
    PlanProblem problem;
    problem.nodes << a;
    for (const QString &name : {QStringLiteral("C1"), QStringLiteral("C2")}) {
        ComponentRequirements c = component(name);
        c.cpuShare = 0.6;
        problem.components << c;
    }
    const Plan result = plan(problem);
    QVERIFY(!result.feasible);
    QCOMPARE(result.unmet.size(), qsizetype(1));
    QCOMPARE(result.unmet.first().instanceName, QStringLiteral("C1, C2"));
    QVERIFY2(result.unmet.first().requirement.contains(QLatin1String("CPU")),
             qPrintable(describe(result)));
    QCOMPARE(result.unmet.first().closestNode, QStringLiteral("a"));
    QCOMPARE(result.unmet.first().found, QStringLiteral("1 CPUs free"));
}

void TestPlanner::sharedProcessStaysTogether()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    b.userFacts.insert(QStringLiteral("devices"), QStringLiteral("lidar0"));
    PlanProblem problem;
    problem.nodes << a << b;
    ComponentRequirements driver = component(QStringLiteral("Driver"));
    driver.devices << QStringLiteral("lidar0");
    driver.process = QStringLiteral("loop");
    ComponentRequirements filter = component(QStringLiteral("Filter"));
    filter.process = QStringLiteral("loop");
    ComponentRequirements logger = component(QStringLiteral("Logger"));
    problem.components << driver << filter << logger;
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QCOMPARE(nodeOf(result, QStringLiteral("Filter")), QStringLiteral("b"));
    QCOMPARE(result.placement(QStringLiteral("Filter"))->process, QStringLiteral("loop"));
    QVERIFY(result.placement(QStringLiteral("Filter"))->sharedProcess);
    QCOMPARE(result.placement(QStringLiteral("Logger"))->process, QStringLiteral("Logger"));
    QVERIFY(!result.placement(QStringLiteral("Logger"))->sharedProcess);
}

void TestPlanner::sharedProcessWithoutCommonNode()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    b.architecture = QStringLiteral("aarch64");
    PlanProblem problem;
    problem.nodes << a << b;
    ComponentRequirements x = component(QStringLiteral("X"));
    x.architectures << QStringLiteral("x86_64");
    x.process = QStringLiteral("p");
    ComponentRequirements y = component(QStringLiteral("Y"));
    y.architectures << QStringLiteral("aarch64");
    y.process = QStringLiteral("p");
    problem.components << x << y;
    const Plan result = plan(problem);
    QVERIFY(!result.feasible);
    QCOMPARE(result.unmet.size(), qsizetype(1));
    QCOMPARE(result.unmet.first().instanceName, QStringLiteral("Y"));
    QCOMPARE(result.unmet.first().requirement, QStringLiteral("same process (p) as X"));
    QCOMPARE(result.unmet.first().closestNode, QStringLiteral("a"));
    QCOMPARE(result.unmet.first().found, QStringLiteral("architecture aarch64 not met"));
}

void TestPlanner::pinPlacesComponent()
{
    PlanProblem problem;
    problem.nodes << node(QStringLiteral("a")) << node(QStringLiteral("b"));
    ComponentRequirements pinned = component(QStringLiteral("Pinned"));
    pinned.pinnedNode = QStringLiteral("b");
    ComponentRequirements free = component(QStringLiteral("Free"));
    problem.components << pinned << free;
    // A strong connector pulls Free next to Pinned, wherever Pinned is.
    problem.links.append({QStringLiteral("Free"), QStringLiteral("Pinned"), 100});
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QCOMPARE(nodeOf(result, QStringLiteral("Pinned")), QStringLiteral("b"));
    QCOMPARE(nodeOf(result, QStringLiteral("Free")), QStringLiteral("b"));
    QCOMPARE(result.crossHostRate, 0.0);
}

void TestPlanner::pinToUnknownNode()
{
    PlanProblem problem;
    problem.nodes << node(QStringLiteral("a"));
    ComponentRequirements pinned = component(QStringLiteral("Pinned"));
    pinned.pinnedNode = QStringLiteral("gone");
    problem.components << pinned;
    const Plan result = plan(problem);
    QVERIFY(!result.feasible);
    QCOMPARE(result.unmet.first().requirement, QStringLiteral("pinned to gone"));
}

void TestPlanner::infeasibleNamesClosestNode()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    b.userFacts.insert(QStringLiteral("devices"), QStringLiteral("lidar0"));
    PlanProblem problem;
    problem.nodes << a << b;
    ComponentRequirements c = component(QStringLiteral("Mapper"));
    c.devices << QStringLiteral("lidar0");
    c.architectures << QStringLiteral("aarch64");
    problem.components << c << component(QStringLiteral("Other"));
    const Plan result = plan(problem);
    QVERIFY(!result.feasible);
    // b has the device but not the architecture: one requirement short, the closest.
    QCOMPARE(result.unmet.size(), qsizetype(1));
    QCOMPARE(result.unmet.first().instanceName, QStringLiteral("Mapper"));
    QCOMPARE(result.unmet.first().requirement, QStringLiteral("architecture aarch64"));
    QCOMPARE(result.unmet.first().closestNode, QStringLiteral("b"));
    QCOMPARE(result.unmet.first().found, QStringLiteral("x86_64"));
}

void TestPlanner::installsWhereNotLoadable()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    b.architecture = QStringLiteral("aarch64");
    PlanProblem problem;
    problem.nodes << a << b;
    problem.packages.append({QStringLiteral("rtc-camera"),
                             QStringLiteral("1.0"),
                             QStringLiteral("arm64"),
                             QStringLiteral("librtsdk.so.0"),
                             {QStringLiteral("Camera")}});
    problem.packages.append({QStringLiteral("rtc-camera"),
                             QStringLiteral("1.2"),
                             QStringLiteral("arm64"),
                             QStringLiteral("librtsdk.so.0"),
                             {QStringLiteral("Camera")}});
    problem.components << component(QStringLiteral("Cam"), QStringLiteral("Camera"));
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QCOMPARE(nodeOf(result, QStringLiteral("Cam")), QStringLiteral("b"));
    QCOMPARE(result.placement(QStringLiteral("Cam"))->installPackage, QStringLiteral("rtc-camera"));
    QCOMPARE(result.installs.size(), qsizetype(1));
    QCOMPARE(result.installs.first().node, QStringLiteral("b"));
    QCOMPARE(result.installs.first().version, QStringLiteral("1.2"));
}

void TestPlanner::fewestInstalls()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    b.loadableTypes = QStringList {QStringLiteral("T"), QStringLiteral("Camera")};
    PlanProblem problem;
    problem.nodes << a << b;
    problem.packages.append({QStringLiteral("rtc-camera"),
                             QStringLiteral("1.0"),
                             QStringLiteral("amd64"),
                             QStringLiteral("librtsdk.so.0"),
                             {QStringLiteral("Camera")}});
    for (int i = 0; i < 4; ++i)
        problem.components << component(QStringLiteral("Cam%1").arg(i), QStringLiteral("Camera"));
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QVERIFY(result.installs.isEmpty());
    for (int i = 0; i < 4; ++i)
        QCOMPARE(nodeOf(result, QStringLiteral("Cam%1").arg(i)), QStringLiteral("b"));
}

void TestPlanner::installsOncePerNode_data()
{
    QTest::addColumn<double>("share");
    QTest::addColumn<int>("installs");
    QTest::newRow("no CPU limit") << 0.0 << 1;
    QTest::newRow("two fit on a node") << 0.4 << 2;
}

// Three components of a type no node loads: one install on one node, unless CPU shares spread them.
void TestPlanner::installsOncePerNode()
{
    QFETCH(double, share);
    QFETCH(int, installs);
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    a.cpuCount = b.cpuCount = 1;
    PlanProblem problem;
    problem.nodes << a << b;
    problem.packages.append({QStringLiteral("rtc-camera"),
                             QStringLiteral("1.0"),
                             QStringLiteral("amd64"),
                             QStringLiteral("librtsdk.so.0"),
                             {QStringLiteral("Camera")}});
    for (int i = 0; i < 3; ++i) {
        ComponentRequirements c
            = component(QStringLiteral("Cam%1").arg(i), QStringLiteral("Camera"));
        c.cpuShare = share;
        problem.components << c;
    }
    problem.components << component(QStringLiteral("Other"));
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QVERIFY(result.optimal);
    QCOMPARE(result.installs.size(), qsizetype(installs));
}

void TestPlanner::packageForOtherArchitectureIsNoSource()
{
    NodeFacts a = node(QStringLiteral("a"));
    PlanProblem problem;
    problem.nodes << a;
    problem.packages.append({QStringLiteral("rtc-camera"),
                             QStringLiteral("1.0"),
                             QStringLiteral("arm64"),
                             QString(),
                             {QStringLiteral("Camera")}});
    problem.packages.append({QStringLiteral("rtc-camera"),
                             QStringLiteral("1.0"),
                             QStringLiteral("amd64"),
                             QStringLiteral("librtsdk.so.9"),
                             {QStringLiteral("Camera")}});
    problem.components << component(QStringLiteral("Cam"), QStringLiteral("Camera"));
    const Plan result = plan(problem);
    QVERIFY(!result.feasible);
    QCOMPARE(result.unmet.first().requirement,
             QStringLiteral("type Camera loadable or installable"));
}

void TestPlanner::highRateConnectorStaysInsideHost()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    a.cpuCount = b.cpuCount = 1;
    PlanProblem problem;
    problem.nodes << a << b;
    // Two fit on a node. Counting connectors, A,C | B,D is best (one crosses); weighing them by
    // rate, A,B | C,D (the 1 kHz one inside, two 1 Hz ones across).
    for (const QString &name :
         {QStringLiteral("A"), QStringLiteral("C"), QStringLiteral("B"), QStringLiteral("D")}) {
        ComponentRequirements c = component(name);
        c.cpuShare = 0.45;
        problem.components << c;
    }
    problem.links.append({QStringLiteral("A"), QStringLiteral("B"), 1000});
    problem.links.append({QStringLiteral("A"), QStringLiteral("C"), 1});
    problem.links.append({QStringLiteral("B"), QStringLiteral("D"), 1});
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QVERIFY(result.optimal);
    QCOMPARE(nodeOf(result, QStringLiteral("A")), nodeOf(result, QStringLiteral("B")));
    QCOMPARE(nodeOf(result, QStringLiteral("C")), nodeOf(result, QStringLiteral("D")));
    QCOMPARE(result.crossHostRate, 2.0);
}

void TestPlanner::balancesCpuLoad()
{
    NodeFacts a = node(QStringLiteral("a"));
    NodeFacts b = node(QStringLiteral("b"));
    a.loadAverage = 2.0;
    PlanProblem problem;
    problem.nodes << a << b;
    for (int i = 0; i < 6; ++i) {
        ComponentRequirements c = component(QStringLiteral("C%1").arg(i));
        c.cpuShare = 0.5;
        problem.components << c;
    }
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    // a starts with 2 of its 4 CPUs busy: the even plan leaves it fewer components than b.
    int onA = 0;
    for (const Placement &p : result.placements)
        onA += p.node == QLatin1String("a") ? 1 : 0;
    QVERIFY2(onA >= 1 && onA <= 2, qPrintable(QString::number(onA)));
}

void TestPlanner::noNodes()
{
    PlanProblem problem;
    problem.components << component(QStringLiteral("C"));
    const Plan result = plan(problem);
    QVERIFY(!result.feasible);
    QCOMPARE(result.unmet.first().found, QStringLiteral("no nodes given"));
}

// Figures far beyond real ones (facts files are typed by people) give a plan, not an overflow.
void TestPlanner::extremeFiguresStayValid()
{
    NodeFacts big = node(QStringLiteral("big"));
    big.cpuCount = 2000000000;
    NodeFacts other = node(QStringLiteral("other"));
    other.loadAverage = 1e12;
    PlanProblem problem;
    problem.nodes << big << other;
    ComponentRequirements hungry = component(QStringLiteral("Hungry"));
    hungry.cpuShare = 1e9;
    problem.components << hungry << component(QStringLiteral("B"));
    problem.links.append({QStringLiteral("Hungry"), QStringLiteral("B"), 1e12});
    problem.links.append({QStringLiteral("B"), QStringLiteral("Hungry"), 1e12});
    const Plan result = plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QCOMPARE(nodeOf(result, QStringLiteral("Hungry")), QStringLiteral("big"));
    QCOMPARE(nodeOf(result, QStringLiteral("B")), QStringLiteral("big"));
}

// A budget far too short to prove anything: still a plan that keeps every requirement, marked
// as not proven best.
void TestPlanner::timeLimitStillGivesValidPlan()
{
    PlanProblem problem;
    for (int n = 0; n < 10; ++n) {
        NodeFacts facts = node(QStringLiteral("n%1").arg(n));
        if (n == 7)
            facts.userFacts.insert(QStringLiteral("devices"), QStringLiteral("lidar0"));
        problem.nodes << facts;
    }
    for (int c = 0; c < 400; ++c) {
        ComponentRequirements comp = component(QStringLiteral("C%1").arg(c));
        if (c % 10 == 0)
            comp.devices << QStringLiteral("lidar0");
        problem.components << comp;
        if (c > 0)
            problem.links.append(
                {QStringLiteral("C%1").arg(c - 1), comp.instanceName, double(c % 7)});
    }
    const Plan result = DeploymentPlanner({1}).plan(problem);
    QVERIFY2(result.feasible, qPrintable(describe(result)));
    QVERIFY(!result.optimal);
    QVERIFY(!result.warnings.isEmpty());
    QCOMPARE(result.placements.size(), qsizetype(400));
    for (int c = 0; c < 400; c += 10)
        QCOMPARE(nodeOf(result, QStringLiteral("C%1").arg(c)), QStringLiteral("n7"));
}

// Nodes alike are solved as one and spread afterwards; the outcome must not depend on the run.
void TestPlanner::samePlanEveryTime()
{
    PlanProblem problem;
    for (int n = 0; n < 8; ++n) {
        NodeFacts facts = node(QStringLiteral("n%1").arg(n));
        facts.loadableTypes = QStringList {n % 2 ? QStringLiteral("T") : QStringLiteral("U")};
        problem.nodes << facts;
    }
    for (int c = 0; c < 300; ++c) {
        problem.components << component(QStringLiteral("C%1").arg(c),
                                        c % 3 ? QStringLiteral("T") : QStringLiteral("U"));
        if (c > 0)
            problem.links.append({QStringLiteral("C%1").arg(c - 1),
                                  problem.components.last().instanceName, double(1 + c % 5)});
    }
    const Plan first = plan(problem);
    QVERIFY2(first.optimal, qPrintable(describe(first)));
    QSet<QString> used;
    for (const Placement &p : first.placements)
        used.insert(p.node);
    // Spread over the alike nodes, not piled on one of each kind.
    QVERIFY2(used.size() > 2, qPrintable(QString::number(used.size())));
    for (int run = 0; run < 3; ++run) {
        const Plan again = plan(problem);
        QCOMPARE(again.crossHostRate, first.crossHostRate);
        for (int c = 0; c < first.placements.size(); ++c)
            QCOMPARE(again.placements.at(c).node, first.placements.at(c).node);
    }
}

QTEST_GUILESS_MAIN(TestPlanner)
#include "tst_planner.moc"
