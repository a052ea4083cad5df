// SPDX-License-Identifier: MIT
// What the deployment planner reads: requirements from RTS and RTC profiles, node facts from
// managers' properties and from facts files, and `rtctl plan` with a facts file.
#include "nodefactsfile.h"
#include "profileio.h"
#include "requirements.h"
#include "nativerepository.h"
#include "rtcprofile.h"
#include "rtctlrunner.h"
#include "rtsprofile.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace Planner;

namespace {

QString dataFile(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/planner/")) + name;
}

Profile::RtsProfile robot()
{
    Profile::Diagnostics diagnostics;
    const auto loaded
        = Profile::loadProfileFile(dataFile(QStringLiteral("robot.xml")), &diagnostics);
    return loaded && loaded->rts ? *loaded->rts : Profile::RtsProfile();
}

QHash<QString, Profile::RtcProfile> viewerProfile()
{
    Profile::Diagnostics diagnostics;
    const auto loaded
        = Profile::loadProfileFile(dataFile(QStringLiteral("profiles/Viewer.xml")), &diagnostics);
    QHash<QString, Profile::RtcProfile> profiles;
    if (loaded && loaded->rtc)
        profiles.insert(loaded->rtc->id, *loaded->rtc);
    return profiles;
}

const ComponentRequirements *find(const SystemRequirements &r, const QString &instance)
{
    for (const ComponentRequirements &c : r.components) {
        if (c.instanceName == instance)
            return &c;
    }
    return nullptr;
}

/// Writes @p text as a facts file in @p dir and returns its path.
QString factsFile(const QTemporaryDir &dir, const QByteArray &text)
{
    const QString path = dir.filePath(QStringLiteral("facts.yaml"));
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(text);
    return path;
}

const QByteArray RobotNodes = R"(nodes:
  - name: corbaloc::onboard:2810
    os.name: Linux
    os.arch: aarch64
    rtstudio.cpu_count: 4
    supported_languages: [C++]
    rtstudio.loadable_types: [ConsoleIn, ConsoleOut, Controller, Motor, PeriodicECSharedComposite]
    node: {devices: lidar0, role: onboard}
  - name: corbaloc::base:2810
    os.name: Linux
    os.arch: x86_64
    rtstudio.cpu_count: 8
    supported_languages: C++, Python
    rtstudio.loadable_types: [ConsoleIn, ConsoleOut, Viewer]
    node.role: base
)";

} // namespace

class TestPlannerInputs : public QObject
{
    Q_OBJECT

private slots:
    void requirementsFromRtcProfile();
    void requirementsFromComponentProperties();
    void compositeMembersShareProcess();
    void connectorRates();
    void factsFromManager();
    void factsFiles_data();
    void factsFiles();
    void badFactsFiles_data();
    void badFactsFiles();
    void rtctlPlanPlacesByFacts();
    void rtctlPlanJson();
    void rtctlPlanExplainsNoPlan();
    void rtctlPlanUsage();
    void rtctlPlanInstallsFromRepository();
};

void TestPlannerInputs::requirementsFromRtcProfile()
{
    const SystemRequirements r = readRequirements(robot(), viewerProfile());
    const ComponentRequirements *viewer = find(r, QStringLiteral("Viewer0"));
    QVERIFY(viewer);
    QCOMPARE(viewer->typeName, QStringLiteral("Viewer"));
    QCOMPARE(viewer->language, QStringLiteral("Python"));
    QCOMPARE(viewer->oses, QStringList {QStringLiteral("Linux")});
    QCOMPARE(viewer->architectures, QStringList {QStringLiteral("x86_64")});
    QCOMPARE(viewer->nodeFacts.value(QStringLiteral("role")), QStringLiteral("base"));
    QCOMPARE(viewer->cpuShare, 0.5);
    // Types without an RTC profile are named once, in one warning.
    QCOMPARE(r.warnings.size(), qsizetype(1));
    QVERIFY(r.warnings.first().contains(QLatin1String("ConsoleIn, ConsoleOut")));
}

void TestPlannerInputs::requirementsFromComponentProperties()
{
    Profile::RtsProfile system = robot();
    // The component's own property overrides its type's.
    Profile::setRtsProperty(system.component(QStringLiteral("Viewer0"))->properties,
                            QStringLiteral("deploy.cpu_share"), QStringLiteral("1.5"));
    Profile::setRtsProperty(system.component(QStringLiteral("Filter0"))->properties,
                            QStringLiteral("deploy.cpu_share"), QStringLiteral("lots"));
    const SystemRequirements r = readRequirements(system, viewerProfile());
    QCOMPARE(find(r, QStringLiteral("Viewer0"))->cpuShare, 1.5);
    QCOMPARE(find(r, QStringLiteral("Lidar0"))->devices, QStringList {QStringLiteral("lidar0")});
    QCOMPARE(find(r, QStringLiteral("Logger0"))->pinnedNode, QStringLiteral("corbaloc::base:2810"));
    QCOMPARE(find(r, QStringLiteral("Logger0"))->cpuShare, 0.25);
    QCOMPARE(find(r, QStringLiteral("Motor0"))->nodeFacts.value(QStringLiteral("role")),
             QStringLiteral("onboard"));
    QCOMPARE(find(r, QStringLiteral("Filter0"))->cpuShare, 0.0);
    QVERIFY(r.warnings.join(QLatin1Char('\n'))
                .contains(QLatin1String("Filter0: deploy.cpu_share 'lots'")));
    QVERIFY(find(r, QStringLiteral("Filter0"))->pinnedNode.isEmpty());
}

void TestPlannerInputs::compositeMembersShareProcess()
{
    const SystemRequirements r = readRequirements(robot(), {});
    QCOMPARE(find(r, QStringLiteral("Loop0"))->process, QStringLiteral("Loop0"));
    QCOMPARE(find(r, QStringLiteral("Ctrl0"))->process, QStringLiteral("Loop0"));
    QCOMPARE(find(r, QStringLiteral("Motor0"))->process, QStringLiteral("Loop0"));
    QVERIFY(find(r, QStringLiteral("Lidar0"))->process.isEmpty());
}

void TestPlannerInputs::connectorRates()
{
    const SystemRequirements r = readRequirements(robot(), {});
    QCOMPARE(r.links.size(), qsizetype(2));
    // The source's execution context rate, unless the connector states its own.
    QCOMPARE(r.links.at(0).source, QStringLiteral("Lidar0"));
    QCOMPARE(r.links.at(0).target, QStringLiteral("Filter0"));
    QCOMPARE(r.links.at(0).rate, 1000.0);
    QCOMPARE(r.links.at(1).rate, 2.0);
}

void TestPlannerInputs::factsFromManager()
{
    // OpenRTM-aist keeps os.* in the configuration; the profile wins where both say something.
    const FactProperties configuration {
        {QStringLiteral("os.name"), QStringLiteral("Linux")},
        {QStringLiteral("os.arch"), QStringLiteral("x86_64")},
        {QStringLiteral("manager.supported_languages"), QStringLiteral("C++, Python3")},
        {QStringLiteral("node.devices"), QStringLiteral("lidar0, camera0")},
        {QStringLiteral("node.role"), QStringLiteral("onboard")}};
    const FactProperties profile {
        {QStringLiteral("os.arch"), QStringLiteral("aarch64")},
        {QStringLiteral("rtstudio.cpu_count"), QStringLiteral("6")},
        {QStringLiteral("rtstudio.load_average"), QStringLiteral("1.5")},
        {QStringLiteral("rtstudio.memory_kib"), QStringLiteral("2048000")},
        {QStringLiteral("rtstudio.sdk_abi"), QStringLiteral("librtsdk.so.0")}};
    const QList<FactProperties> modules {
        {{QStringLiteral("implementation_id"), QStringLiteral("ConsoleIn")}},
        {{QStringLiteral("language"), QStringLiteral("C++")}}};
    const NodeFacts facts
        = NodeFacts::fromManager(QStringLiteral("m"), profile, configuration, modules);
    QCOMPARE(facts.name, QStringLiteral("m"));
    QCOMPARE(facts.os, QStringLiteral("Linux"));
    QCOMPARE(facts.architecture, QStringLiteral("aarch64"));
    QCOMPARE(facts.cpuCount, 6);
    QCOMPARE(facts.loadAverage, 1.5);
    QCOMPARE(facts.freeCpus(), 4.5);
    QCOMPARE(facts.memoryKiB, qint64(2048000));
    QCOMPARE(facts.sdkAbi, QStringLiteral("librtsdk.so.0"));
    QCOMPARE(facts.languages, (QStringList {QStringLiteral("C++"), QStringLiteral("Python3")}));
    QCOMPARE(facts.loadableTypes, QStringList {QStringLiteral("ConsoleIn")});
    QCOMPARE(facts.devices(), (QStringList {QStringLiteral("lidar0"), QStringLiteral("camera0")}));
    QCOMPARE(facts.userFacts.value(QStringLiteral("role")), QStringLiteral("onboard"));
    QVERIFY(!facts.distribution);

    // A manager that could not list its modules: what it loads is unknown, not nothing.
    QVERIFY(!NodeFacts::fromManager(QStringLiteral("m"), profile, configuration, std::nullopt)
                 .loadableTypes);
}

void TestPlannerInputs::factsFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("yaml") << "nodes.yaml";
    QTest::newRow("json") << "nodes.json";
}

void TestPlannerInputs::factsFiles()
{
    QFETCH(QString, file);
    QString error;
    const auto nodes = readNodeFactsFile(dataFile(file), &error);
    QVERIFY2(nodes, qPrintable(error));
    QCOMPARE(nodes->size(), qsizetype(2));
    const NodeFacts &first = nodes->first();
    QVERIFY(first.name.startsWith(QLatin1String("corbaloc::")));
    QCOMPARE(first.os, QStringLiteral("Linux"));
    QVERIFY(first.devices().contains(QStringLiteral("lidar0")));
    QVERIFY(first.cpuCount.has_value());
    // What the file does not say stays unknown.
    QVERIFY(!nodes->at(1).architecture || file == QLatin1String("nodes.yaml"));
    QVERIFY(!nodes->at(1).cpuCount || file == QLatin1String("nodes.yaml"));
    if (file == QLatin1String("nodes.yaml")) {
        QCOMPARE(first.architecture, QStringLiteral("aarch64"));
        QCOMPARE(first.distribution, QStringLiteral("debian 13"));
        QCOMPARE(first.userFacts.value(QStringLiteral("role")), QStringLiteral("onboard"));
        QCOMPARE(first.loadableTypes,
                 (QStringList {QStringLiteral("ConsoleIn"), QStringLiteral("ConsoleOut")}));
        QCOMPARE(nodes->at(1).languages,
                 (QStringList {QStringLiteral("C++"), QStringLiteral("Python")}));
    }
}

void TestPlannerInputs::badFactsFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("message");
    QTest::newRow("no name") << "nodes-noname.yaml"
                             << "nodes-noname.yaml:4: a node has no 'name'";
    QTest::newRow("twice") << "nodes-twice.yaml"
                           << "nodes-twice.yaml:3: node 'a' is listed twice";
    QTest::newRow("broken") << "nodes-broken.yaml"
                            << "nodes-broken.yaml:4: ";
    QTest::newRow("missing") << "no-such-file.yaml"
                             << "no-such-file.yaml: ";
}

void TestPlannerInputs::badFactsFiles()
{
    QFETCH(QString, file);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!readNodeFactsFile(dataFile(file), &error));
    QVERIFY2(error.contains(message), qPrintable(error));
    QVERIFY(!readNodeFactsData("just text", QStringLiteral("t.yaml"), &error));
    QVERIFY2(error.startsWith(QLatin1String("t.yaml:1: expected a list of nodes")),
             qPrintable(error));
}

void TestPlannerInputs::rtctlPlanPlacesByFacts()
{
    QTemporaryDir dir;
    const RtctlResult result
        = runRtctl({QStringLiteral("plan"), dataFile(QStringLiteral("robot.xml")),
                    QStringLiteral("--facts"), factsFile(dir, RobotNodes),
                    QStringLiteral("--profiles"), dataFile(QStringLiteral("profiles"))});
    QVERIFY2(result.code == 0, qPrintable(result.err));
    const QString onboard = QStringLiteral("corbaloc::onboard:2810");
    const QString base = QStringLiteral("corbaloc::base:2810");
    QHash<QString, QString> nodeOf;
    QHash<QString, QString> processOf;
    for (const QString &line : result.lines()) {
        const QStringList fields = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (fields.size() >= 3 && fields.at(1).startsWith(QLatin1String("corbaloc"))) {
            nodeOf.insert(fields.at(0), fields.at(1));
            processOf.insert(fields.at(0), fields.at(2));
        }
    }
    QCOMPARE(nodeOf.value(QStringLiteral("Lidar0")), onboard);
    QCOMPARE(nodeOf.value(QStringLiteral("Filter0")), onboard); // 1 kHz from Lidar0
    QCOMPARE(nodeOf.value(QStringLiteral("Viewer0")), base);
    QCOMPARE(nodeOf.value(QStringLiteral("Motor0")), onboard);
    QCOMPARE(nodeOf.value(QStringLiteral("Ctrl0")), onboard);
    QCOMPARE(processOf.value(QStringLiteral("Ctrl0")), QStringLiteral("Loop0"));
    QCOMPARE(nodeOf.value(QStringLiteral("Logger0")), base);
    QCOMPARE(processOf.value(QStringLiteral("Logger0")), QStringLiteral("own"));
    QVERIFY2(result.out.contains(QLatin1String("connectors between hosts: 2 Hz")),
             qPrintable(result.out));
}

void TestPlannerInputs::rtctlPlanJson()
{
    QTemporaryDir dir;
    const RtctlResult result = runRtctl(
        {QStringLiteral("plan"), dataFile(QStringLiteral("robot.xml")), QStringLiteral("--facts"),
         factsFile(dir, RobotNodes), QStringLiteral("--profiles"),
         dataFile(QStringLiteral("profiles")), QStringLiteral("--json")});
    QVERIFY2(result.code == 0, qPrintable(result.err));
    const QJsonObject plan = result.json().object();
    QCOMPARE(plan.value(QStringLiteral("feasible")).toBool(), true);
    QCOMPARE(plan.value(QStringLiteral("placements")).toArray().size(), 7);
    const QJsonObject first = plan.value(QStringLiteral("placements")).toArray().first().toObject();
    QCOMPARE(first.value(QStringLiteral("component")).toString(), QStringLiteral("Lidar0"));
    QCOMPARE(first.value(QStringLiteral("node")).toString(),
             QStringLiteral("corbaloc::onboard:2810"));
    QCOMPARE(plan.value(QStringLiteral("cross_host_rate")).toDouble(), 2.0);
}

void TestPlannerInputs::rtctlPlanExplainsNoPlan()
{
    QTemporaryDir dir;
    QByteArray nodes = RobotNodes;
    nodes.replace("devices: lidar0", "devices: camera0");
    const RtctlResult result
        = runRtctl({QStringLiteral("plan"), dataFile(QStringLiteral("robot.xml")),
                    QStringLiteral("--facts"), factsFile(dir, nodes)});
    QCOMPARE(result.code, 1);
    QVERIFY2(result.err.contains(QLatin1String("Lidar0: device lidar0 - no node meets it; closest "
                                               "corbaloc::onboard:2810 has camera0")),
             qPrintable(result.err));
}

void TestPlannerInputs::rtctlPlanUsage()
{
    QCOMPARE(runRtctl({QStringLiteral("plan"), dataFile(QStringLiteral("robot.xml"))}).code, 2);
    QCOMPARE(runRtctl({QStringLiteral("plan"), dataFile(QStringLiteral("robot.xml")),
                       QStringLiteral("--facts"), dataFile(QStringLiteral("nodes.yaml")),
                       QStringLiteral("--solver-timeout"), QStringLiteral("x")})
                 .code,
             2);
    const RtctlResult broken
        = runRtctl({QStringLiteral("plan"), dataFile(QStringLiteral("robot.xml")),
                    QStringLiteral("--facts"), dataFile(QStringLiteral("nodes-noname.yaml"))});
    QCOMPARE(broken.code, 1);
    QVERIFY2(broken.err.contains(QLatin1String("nodes-noname.yaml:4: a node has no 'name'")),
             qPrintable(broken.err));
    const RtctlResult notSystem
        = runRtctl({QStringLiteral("plan"), dataFile(QStringLiteral("profiles/Viewer.xml")),
                    QStringLiteral("--facts"), dataFile(QStringLiteral("nodes.yaml"))});
    QCOMPARE(notSystem.code, 1);
    QVERIFY2(notSystem.err.contains(QLatin1String("not an RTS profile")),
             qPrintable(notSystem.err));
}

// A type no node loads, in a repository for this machine's architecture only: installed once, on
// the node of that architecture, for both components (its RTC profile comes from the package).
void TestPlannerInputs::rtctlPlanInstallsFromRepository()
{
    QTemporaryDir dir;
    QString arch;
    QString error;
    const QString repo = TestSupport::makeNativeRepository(dir.path(), &arch, &error);
    QVERIFY2(!repo.isEmpty(), qPrintable(error));

    const QByteArray nodes
        = QStringLiteral(
              "- {name: other, os.name: Linux, os.arch: riscv64, supported_languages: C++}\n"
              "- {name: native, os.name: Linux, os.arch: %1, supported_languages: C++}\n")
              .arg(arch)
              .toUtf8();
    const RtctlResult result = runRtctl(
        {QStringLiteral("plan"), dataFile(QStringLiteral("probe.xml")), QStringLiteral("--facts"),
         factsFile(dir, nodes), QStringLiteral("--repo"), repo, QStringLiteral("--json")});
    QVERIFY2(result.code == 0, qPrintable(result.err + result.out));
    const QJsonObject plan = result.json().object();
    const QJsonArray installs = plan.value(QStringLiteral("installs")).toArray();
    QCOMPARE(installs.size(), 1);
    QCOMPARE(installs.first().toObject().value(QStringLiteral("node")).toString(),
             QStringLiteral("native"));
    QCOMPARE(installs.first().toObject().value(QStringLiteral("package")).toString(),
             QStringLiteral("rtc-rtstudiotests-packaging-native"));
    for (const QJsonValue &p : plan.value(QStringLiteral("placements")).toArray())
        QCOMPARE(p.toObject().value(QStringLiteral("node")).toString(), QStringLiteral("native"));

    // Its RTC profile (C++) came from the package: a node without C++ cannot take it.
    QByteArray noCxx = nodes;
    noCxx.replace("os.arch: " + arch.toUtf8() + ", supported_languages: C++",
                  "os.arch: " + arch.toUtf8() + ", supported_languages: Python");
    noCxx.replace("riscv64, supported_languages: C++", "riscv64");
    const RtctlResult refused = runRtctl(
        {QStringLiteral("plan"), dataFile(QStringLiteral("probe.xml")), QStringLiteral("--facts"),
         factsFile(dir, noCxx), QStringLiteral("--repo"), repo});
    QCOMPARE(refused.code, 1);
    QVERIFY2(refused.err.contains(QLatin1String(
                 "Probe0: language C++ - no node meets it; closest native has Python")),
             qPrintable(refused.err));
}

QTEST_GUILESS_MAIN(TestPlannerInputs)
#include "tst_plannerinputs.moc"
