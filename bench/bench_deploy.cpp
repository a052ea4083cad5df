// SPDX-License-Identifier: MIT
// bench_deploy: restore + start of 100 components / 150 connectors on two managers (a master and
// a slave it starts through manager_address), against real omniNames and rtmanager processes.
// Prints one table row per phase; timing never fails the build.
#include "benchlivesystem.h"
#include "cryo.h"
#include "livesystem.h"
#include "managerproxy.h"
#include "orb.h"
#include "restorer.h"
#include "rtsprofile.h"
#include "sequencerunner.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTextStream>

#include <functional>

using namespace Deploy;

namespace {

constexpr int pairs = 50; // 50 sources + 50 sinks = 100 components
constexpr int fanOut = 3; // 3 connectors per source = 150 connectors

// Sources on the master's host, sinks on the slave's.
Profile::RtsProfile benchSystem(const QString &server)
{
    return Bench::liveSystem(QStringLiteral("Deploy"), pairs, fanOut,
                             [&server](int k) {
                                 return Bench::Placement {server, k % 2 ? QStringLiteral("hostB") : QStringLiteral("hostA")};
                             },
                             QStringLiteral("100"), QStringLiteral("flush"));
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    Corba::Orb::setCallTimeout(20000);
    LiveTest::LiveSystem live;
    QString error;
    const quint16 masterPort = LiveTest::freePort();
    const quint16 slavePort = LiveTest::freePort();
    if (!live.startNameServer(&error)
        || !live.startProcess(
            QStringLiteral(RTMANAGER_PATH),
            {"-d", "-o", QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(masterPort), "-o",
             "corba.nameservers=" + live.namingServer(), "-o", "naming.formats=%h.host_cxt/%n.rtc",
             "-o", "manager.naming_formats=%h.host_cxt/%n.mgr"},
            "rtmanager ready", &error)) {
        out << "bench_deploy: " << error << '\n';
        return 1;
    }
    const Profile::RtsProfile profile = benchSystem(live.namingServer());
    TargetOptions options;
    options.nameServers = {live.namingServer()};
    options.manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(masterPort);
    options.hostManagers.insert("hostB", QStringLiteral("127.0.0.1:%1").arg(slavePort));
    options.create = true;

    out << QStringLiteral("%1 %2 %3\n").arg("phase", -40).arg("ms", 8).arg("result");
    auto row = [&](const QString &phase, const std::function<DeployReport()> &run) {
        QElapsedTimer timer;
        timer.start();
        const DeployReport report = run();
        out << QStringLiteral("%1 %2 %3\n")
                   .arg(phase, -40)
                   .arg(timer.elapsed(), 8)
                   .arg(report.ok ? QStringLiteral("ok") : report.error);
        out.flush();
        return report.ok;
    };
    RestorePlan plan;
    bool ok = row("plan + create 100 + connect 150 (2 mgrs)", [&] {
        plan = planRestore(profile, options);
        return restoreSystem(profile, plan, options);
    });
    const Corba::ManagerProxy master(ComponentMapper::resolveManager(options.manager),
                                     options.manager);
    out << QStringLiteral("%1 %2 %3\n")
               .arg("components via master / slave managers", -40)
               .arg(master.components().size(), 8)
               .arg(master.slaveManagers().size());
    ok = ok && row("teardown 150", [&] {
             plan = planRestore(profile, options);
             return teardownSystem(plan);
         });
    ok = ok && row("restore (existing) + start", [&] {
             plan = planRestore(profile, options);
             DeployReport report = restoreSystem(profile, plan, options);
             if (report.ok)
                 report = startSystem(profile, plan);
             return report;
         });
    ok = ok && row("stop", [&] { return stopSystem(profile, plan); });
    ok = ok && row("cryo", [&] {
             CryoOptions cryo;
             cryo.paths = {QLatin1Char('/') + live.namingServer()};
             DeployReport report;
             const Profile::RtsProfile saved = cryoSystem(cryo, &report);
             if (saved.components.size() != profile.components.size()
                 || saved.dataPortConnectors.size() != profile.dataPortConnectors.size()) {
                 report.ok = false;
                 report.error = QStringLiteral("cryo saw %1 components, %2 connectors")
                                    .arg(saved.components.size())
                                    .arg(saved.dataPortConnectors.size());
             }
             return report;
         });
    return ok ? 0 : 1;
}
