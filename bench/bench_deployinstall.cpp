// SPDX-License-Identifier: MIT
// Install, then launch: four component types generated from the tour's Doubler profile, built
// against this build tree's SDK, packaged (rtctl package) and published in a signed repository
// (rtctl repo); then a system of 20 of their components, half pinned to each of two managers with
// empty package stores, deployed (plan, installs on both nodes side by side, restore, start) and
// undeployed with uninstall; then deployed again and the second manager killed: the ten components
// it ran are healed onto the first (planned, installed, created, connected, started). Prints the
// time of each step next to the deployment paper's row for automatic launch over SSH of modules
// that were already there (178 ms per component).
#include "deployer.h"
#include "healer.h"
#include "livesystem.h"
#include "orb.h"
#include "profileio.h"
#include "rtctlrunner.h"
#include "rtsprofile.h"
#include "sdkproject.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTextStream>

namespace {

constexpr int typeCount = 4;
constexpr int perType = 5;
const QString doublerProfile = QStringLiteral(RTSTUDIO_SOURCE_DIR "/resources/examples/tour/Doubler.xml");

QTextStream &out()
{
    static QTextStream stream(stdout);
    return stream;
}

void row(const QString &step, qint64 ms, const QString &note = QString())
{
    out() << QStringLiteral("%1 %2  %3\n").arg(step, -44).arg(ms, 8).arg(note);
    out().flush();
}

QString typeName(int t)
{
    return QStringLiteral("Doubler%1").arg(QChar('A' + t));
}

/// The tour's Doubler as type @p t, allowing several instances.
bool writeVariant(int t, const QString &file)
{
    QFile in(doublerProfile);
    if (!in.open(QIODevice::ReadOnly))
        return false;
    QString text = QString::fromUtf8(in.readAll());
    text.replace(QStringLiteral("rtc:name=\"Doubler\""), QStringLiteral("rtc:name=\"%1\"").arg(typeName(t)));
    text.replace(QStringLiteral(":Doubler:"), QStringLiteral(":%1:").arg(typeName(t)));
    text.replace(QStringLiteral("rtc:maxInstances=\"1\""), QStringLiteral("rtc:maxInstances=\"%1\"").arg(perType));
    QFile outFile(file);
    return outFile.open(QIODevice::WriteOnly) && outFile.write(text.toUtf8()) == text.toUtf8().size();
}

/// 20 components: type A feeds B on the first node, C feeds D on the second, each pinned.
Profile::RtsProfile benchSystem(const QStringList &nodes)
{
    Profile::RtsProfile profile = Profile::RtsProfile::createNew("Bench", "DeployInstall", "1.0");
    for (int t = 0; t < typeCount; ++t) {
        for (int i = 0; i < perType; ++i) {
            Profile::RtsComponent c;
            c.id = QStringLiteral("RTC:RTStudio:tour:%1:1.0.0").arg(typeName(t));
            c.instanceName = QStringLiteral("%1_%2").arg(typeName(t)).arg(i);
            for (const QString port : {"in", "out"}) {
                Profile::RtsPort p;
                p.name = c.instanceName + QLatin1Char('.') + port;
                c.dataPorts.append(p);
            }
            Profile::RtsProperty pin;
            pin.name = QStringLiteral("deploy.pin");
            pin.value = nodes.at(t / 2);
            c.properties.append(pin);
            profile.components.append(c);
        }
    }
    for (int t = 0; t < typeCount; t += 2) {
        for (int i = 0; i < perType; ++i) {
            Profile::RtsDataPortConnector c;
            const QString source = QStringLiteral("%1_%2").arg(typeName(t)).arg(i);
            const QString target = QStringLiteral("%1_%2").arg(typeName(t + 1)).arg(i);
            c.connectorId = QStringLiteral("bench-%1").arg(source);
            c.name = source + QLatin1Char('_') + target;
            c.dataType = QStringLiteral("IDL:RTC/TimedLong:1.0");
            c.interfaceType = QStringLiteral("corba_cdr");
            c.dataflowType = QStringLiteral("push");
            c.subscriptionType = QStringLiteral("flush");
            c.source.componentId = profile.components.at(t * perType + i).id;
            c.source.instanceName = source;
            c.source.portName = source + QStringLiteral(".out");
            c.target.componentId = profile.components.at((t + 1) * perType + i).id;
            c.target.instanceName = target;
            c.target.portName = target + QStringLiteral(".in");
            profile.dataPortConnectors.append(c);
        }
    }
    return profile;
}

/// The time of the steps with @p action in @p report: from the first start to the last finish.
qint64 phase(const Deploy::DeployReport &report, const QString &action)
{
    qint64 first = -1;
    qint64 last = -1;
    for (const Deploy::DeployStep &step : report.steps) {
        if (step.action != action)
            continue;
        first = first < 0 ? step.elapsedMs : qMin(first, step.elapsedMs);
        last = qMax(last, step.elapsedMs);
    }
    return first < 0 ? 0 : last - first;
}

int fail(const QString &message)
{
    out() << "bench_deployinstall: " << message << '\n';
    return 1;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    Corba::Orb::setCallTimeout(20000);
    QTemporaryDir work;
    QElapsedTimer timer;
    out() << QStringLiteral("%1 %2  %3\n").arg("step", -44).arg("ms", 8).arg("note");

    QStringList debs;
    qint64 building = 0;
    qint64 packaging = 0;
    for (int t = 0; t < typeCount; ++t) {
        const QString project = work.filePath(typeName(t));
        const QString profile = work.filePath(typeName(t) + QStringLiteral(".xml"));
        if (!writeVariant(t, profile))
            return fail(QStringLiteral("cannot write %1").arg(profile));
        const RtctlResult generated = runRtctl({"gen", profile, "--lang", "cpp", "-o", project});
        QString log;
        timer.start();
        if (generated.code != 0 || !SdkTest::buildProject(project, RTSTUDIO_BUILD_DIR, &log))
            return fail(generated.err + log);
        building += timer.elapsed();
        timer.start();
        const RtctlResult packaged = runRtctl({"package", project, "-o", work.filePath("debs")});
        if (packaged.code != 0)
            return fail(packaged.err);
        packaging += timer.elapsed();
        debs << packaged.lines().value(0);
    }
    row(QStringLiteral("build 4 component types (ccache)"), building);
    row(QStringLiteral("rtctl package, 4 packages"), packaging, QStringLiteral("%1 ms each").arg(packaging / typeCount));
    const QString repo = work.filePath("repo");
    timer.start();
    const RtctlResult made = runRtctl({"repo", "init", repo, "--new-key", "--gnupg-home", work.filePath("gnupg")});
    const RtctlResult published = runRtctl(QStringList {"repo", "publish", repo} + debs);
    if (made.code != 0 || published.code != 0)
        return fail(made.err + published.err);
    row(QStringLiteral("rtctl repo init (new key) + publish"), timer.elapsed());

    LiveTest::LiveSystem live;
    QString error;
    if (!live.startNameServer(&error))
        return fail(error);
    QStringList nodes;
    QList<QProcess *> managers;
    for (int n = 0; n < 2; ++n) {
        const quint16 port = LiveTest::freePort();
        const QStringList options {"corba.nameservers=" + live.namingServer(),
                                   QStringLiteral("naming.formats=node%1.host_cxt/%n.rtc").arg(n),
                                   QStringLiteral("manager.naming_formats=node%1.host_cxt/%n.mgr").arg(n),
                                   "manager.modules.load_path=" + work.filePath("none"),
                                   "manager.modules.package_path=" + work.filePath("none"),
                                   "manager.packages.store=" + work.filePath(QStringLiteral("store%1").arg(n)),
                                   "manager.packages.keyring=" + repo + "/archive-key.gpg"};
        QProcess *manager = live.startManager(QStringLiteral(RTMANAGER_PATH), port, options, &error);
        if (!manager)
            return fail(error);
        managers << manager;
        nodes << QStringLiteral("corbaloc::127.0.0.1:%1").arg(port);
    }
    const Profile::RtsProfile system = benchSystem(nodes);
    Deploy::DeployOptions options;
    options.target.nameServers = {live.namingServer()};
    options.repository = repo;

    timer.start();
    const Deploy::DeployPlan plan = Deploy::planDeploy(system, options);
    const qint64 planned = timer.elapsed();
    if (!plan.problems.isEmpty())
        return fail(plan.problems.join(QLatin1Char('\n')));
    row(QStringLiteral("plan: map, node facts, repository index"), planned,
        QStringLiteral("%1 installs on %2 nodes").arg(plan.installs.size()).arg(nodes.size()));
    timer.start();
    const Deploy::DeployReport report = Deploy::deploySystem(system, plan, options);
    const qint64 deployed = timer.elapsed();
    if (!report.ok)
        return fail(report.error);
    row(QStringLiteral("  install (both nodes side by side)"), phase(report, QStringLiteral("install")));
    row(QStringLiteral("  create"), phase(report, QStringLiteral("create")));
    row(QStringLiteral("  connect"), phase(report, QStringLiteral("connect")));
    row(QStringLiteral("  activate"), phase(report, QStringLiteral("activate")));
    const qint64 total = planned + deployed;
    const int components = int(system.components.size());
    row(QStringLiteral("deploy, %1 components of 4 types, total").arg(components), total,
        QStringLiteral("%1 ms per component (goal <= 50; paper, SSH launch: 178)").arg(double(total) / components, 0, 'f', 1));

    Deploy::TargetOptions target = options.target;
    timer.start();
    const Deploy::DeployReport undeployed
        = Deploy::undeploySystem(system, Deploy::planRestore(system, target), target, true);
    row(QStringLiteral("undeploy --uninstall"), timer.elapsed(), undeployed.ok ? QString() : undeployed.error);

    const Deploy::DeployReport again = Deploy::deploySystem(system, Deploy::planDeploy(system, options), options);
    if (!again.ok)
        return fail(again.error);
    Deploy::WatchOptions watch;
    watch.deploy = options;
    Deploy::SystemHealer healer(system, watch);
    healer.start();
    timer.start();
    managers.at(1)->kill();
    Deploy::DeployReport healed;
    // The healer's rounds as `rtctl deploy --watch` runs them, until one has healed.
    while (healed.steps.isEmpty() && timer.elapsed() < 60000)
        healed = healer.check();
    const qint64 healMs = timer.elapsed();
    if (!healed.ok)
        return fail(healed.error);
    row(QStringLiteral("heal: node killed -> 10 components running"), healMs,
        QStringLiteral("goal <= 2000 for 20 components; install %1, create %2, connect %3, activate %4")
            .arg(phase(healed, QStringLiteral("install")))
            .arg(phase(healed, QStringLiteral("create")))
            .arg(phase(healed, QStringLiteral("connect")))
            .arg(phase(healed, QStringLiteral("activate"))));
    return 0;
}
